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
/// always acts; whether it should is the business of the rule's pattern and
/// of its tests.
using Action = std::function<void(Graph& graph, std::span<const Id> args)>;

/// A named test: a predicate a rule's pattern may require of its match
/// (`test NAME(args)`), for what a pattern cannot say (CGAL's is_sewable
/// before sew). It may change the graph to find out, but must leave it as it
/// found it (a checkpoint and a rollback).
using Test = std::function<bool(Graph& graph, std::span<const Id> args)>;

/// One argument of an action or test: its name in messages, and the kind of
/// element it must be.
struct ActionParameter {
  std::string name;
  KindId kind = 0;
};

/// The actions and tests a domain offers rules, each with its signature,
/// which check_actions() holds every call to when rules load.
class Actions {
public:
  struct Entry {
    std::vector<ActionParameter> parameters;
    Action run;   ///< an action's
    Test test;    ///< a test's
    MeasureFn measure;  ///< a measure's
  };

  void add(const std::string& name, std::vector<ActionParameter> parameters, Action action) {
    actions_[name] = Entry{std::move(parameters), std::move(action), {}, {}};
  }
  void add_test(const std::string& name, std::vector<ActionParameter> parameters, Test test) {
    tests_[name] = Entry{std::move(parameters), {}, std::move(test), {}};
  }
  /// A measure rules may use in any expression (`if`, `where`, `order`): an
  /// integer, in a unit the domain documents (degrees, thousandths).
  void add_measure(const std::string& name, std::vector<ActionParameter> parameters, MeasureFn measure) {
    measures_[name] = Entry{std::move(parameters), {}, {}, std::move(measure)};
  }
  const Entry* find(const std::string& name) const { return find_in(actions_, name); }
  const Entry* find_test(const std::string& name) const { return find_in(tests_, name); }
  const Entry* find_measure(const std::string& name) const { return find_in(measures_, name); }
  /// Every measure, by name.
  const std::map<std::string, Entry>& measures() const { return measures_; }

private:
  static const Entry* find_in(const std::map<std::string, Entry>& m, const std::string& name) {
    auto it = m.find(name);
    return it == m.end() ? nullptr : &it->second;
  }
  std::map<std::string, Entry> actions_, tests_, measures_;
};

/// Runs the rewrite of `m.rule` on `graph`. Afterwards `m.elements` holds the
/// created elements, and variables whose element was merged away hold the
/// element kept. `merge a into b` redirects every incidence to a onto b and
/// removes a; `identify a, b` does the same keeping the element with the
/// larger preferred attribute, else the one with more incoming incidences
/// (so repeated identifications cost O(n log n) in all).
void apply_rewrite(Graph& graph, Match& m, const Actions& actions);

/// Whether the match passes every `test` of its rule's pattern.
bool passes_tests(Graph& graph, const Match& m, const Actions& actions);

/// Throws RuleError (at the call's file:line:column) if a rule calls an
/// action or a test that `actions` does not have, or with the wrong number
/// or kinds of arguments.
void check_actions(const Rule& rule, const Actions& actions, const Schema& schema);

/// Points each of the rule's measure calls at the domain's function (after
/// check_actions, which holds them to their signatures).
void bind_measures(Rule& rule, const Actions& actions);

}  // namespace loom::engine
