#pragma once
// Applying a rule's rewrite to a match: its operations run in the order the
// rule file gives them (create, set ports and attributes, delete, merge,
// identify, call a named action the domain registered).
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "engine/graph.hpp"
#include "engine/matcher.hpp"

namespace loom::engine {

/// A named action: domain code a rule may call for what is not local. It
/// returns true when it acted; false when the state it was given does not call
/// for it (it has then changed nothing, and the match does not count as an
/// application).
using Action = std::function<bool(Graph& graph, std::span<const Id> args)>;

/// One argument of an action: its name in messages, and the kind of element
/// it must be.
struct ActionParameter {
  std::string name;
  KindId kind = 0;
};

/// Whether an action may return false. One that may is allowed only as the
/// first statement of a rewrite, so that declining leaves the graph as it was.
enum class Declines : bool { never, sometimes };

/// The actions a domain offers rules, each with its signature, which
/// check_actions() holds every call to when rules load.
class Actions {
public:
  struct Entry {
    std::vector<ActionParameter> parameters;
    Declines declines = Declines::never;
    Action run;
  };

  void add(const std::string& name, std::vector<ActionParameter> parameters, Action action,
           Declines declines = Declines::never) {
    actions_[name] = Entry{std::move(parameters), declines, std::move(action)};
  }
  const Entry* find(const std::string& name) const {
    auto it = actions_.find(name);
    return it == actions_.end() ? nullptr : &it->second;
  }

private:
  std::map<std::string, Entry> actions_;
};

/// Runs the rewrite of `m.rule` on `graph`. Afterwards `m.elements` holds the
/// created elements, and variables whose element was merged away hold the
/// element kept. `merge a into b` redirects every incidence to a onto b and
/// removes a; `identify a, b` does the same keeping the element with the
/// larger preferred attribute, else the one with more incoming incidences
/// (so repeated identifications cost O(n log n) in all). Returns false when
/// the rewrite's first statement is a call whose action declined.
bool apply_rewrite(Graph& graph, Match& m, const Actions& actions);

/// Throws RuleError (at the call's file:line:column) if a rule calls an
/// action that `actions` does not have, with the wrong number or kinds of
/// arguments, or one that may decline anywhere but first.
void check_actions(const Rule& rule, const Actions& actions, const Schema& schema);

}  // namespace loom::engine
