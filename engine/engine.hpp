#pragma once
// Engine: applies rules to a graph, one match at a time, from the rules and
// by the pick a selection names (a strategy's `apply`, strategy.hpp).
//
// Matching is anchored and incremental. Each rule keeps a queue of candidate
// anchors. At the start every element of the anchor's kind is a candidate;
// after a rewrite, each change the graph logged (a slot, an incoming
// incidence, an attribute, a creation) is traced back along the rule's search
// plan to the anchors whose match it could have created, and only those are
// tried again. So the cost of a step follows what the step changed, not the
// size of the graph. A candidate is matched when queued and once more when
// chosen, so stale candidates are dropped.
//
// Every application is a transaction. It runs inside a checkpoint of the
// graph; if its rewrite throws, it leaves a slot of a required port empty
// (schema.hpp) or it breaks an invariant the caller asked to check, the graph
// is rolled back to where it was and a RuleError names the rule and its file.
//
// A rule is matched and kept up to date only once a selection that holds it
// has been used: rules of a later phase cost nothing before it.
#include <cstdint>
#include <cstddef>
#include <functional>
#include <map>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "engine/graph.hpp"
#include "engine/matcher.hpp"
#include "engine/rewriter.hpp"
#include "engine/rule.hpp"
#include "engine/strategy.hpp"

namespace loom::engine {

struct Application {
  std::size_t step = 0;        ///< 1 for the first application
  const Rule* rule = nullptr;
  Match matched;               ///< the elements matched, before the rewrite
  Match result;                ///< after: created elements bound, merged ones replaced
  Id first_new = no_element;   ///< elements with ids from here on were made by the step (actions included)
};

struct EngineCounters {
  std::size_t steps = 0;
  std::size_t match_attempts = 0;   ///< anchored searches run
  std::size_t candidates = 0;       ///< anchors queued
  std::size_t rescans = 0;          ///< full rescans (rules with unanchored parts)
  std::size_t undos = 0;            ///< rollbacks to a checkpoint
};

class Engine {
public:
  /// Throws RuleError if a rule calls an unknown action or test; `seed`
  /// seeds the random picks.
  Engine(Graph& graph, std::vector<Rule> rules, Actions actions, std::uint64_t seed = 0);

  /// Which rules an application may come from and how its match is picked.
  using Selection = std::size_t;
  /// The rules named (with `all`: every rule but those), picked as `pick`
  /// says (StrategyNode::Pick). Throws std::invalid_argument naming a rule
  /// that is not loaded.
  Selection select(StrategyNode::Pick pick, bool all, const std::vector<std::string>& names);

  /// Applies one match of the selection. Returns false when none applies.
  /// Throws RuleError when the application failed; the graph is then as it
  /// was before.
  bool step(Selection selection, Application* applied = nullptr);
  /// step() from every rule, by priority.
  bool step(Application* applied = nullptr) { return step(all_by_priority(), applied); }

  /// A check of the whole graph: empty when it holds, else what is broken.
  using Invariant = std::function<std::string(const Graph&)>;
  /// Runs `check` after each application of the rules named (of every rule
  /// when `rules` is empty); throws std::invalid_argument naming a rule that
  /// is not loaded.
  void check_after(Invariant check, const std::vector<std::string>& rules = {});

  // --- choices and undo, for search with backtracking -------------------------
  /// Up to `limit` applicable matches of the selection, best first, from the
  /// highest tier of rules that has any (what step() would apply is the first).
  std::vector<Match> choices(Selection selection, std::size_t limit);
  std::vector<Match> choices(std::size_t limit) { return choices(all_by_priority(), limit); }
  /// Applies a match (one of choices(), on the graph as it is now).
  void apply(Match m, Application* applied = nullptr);
  /// Opens a checkpoint of the graph; undo() goes back to it (and keeps it open).
  Graph::Checkpoint mark() { return g_.checkpoint(); }
  void undo(Graph::Checkpoint c);
  /// Keeps the changes made since `c` for good.
  void release(Graph::Checkpoint c) { g_.release(c); }
  /// Closes the oldest open checkpoint (a window of recent ones costs bounded memory).
  void release_oldest() { g_.release_oldest(); }
  /// Graph::position() and Graph::oldest_checkpoint() of the graph.
  Graph::Checkpoint position() const { return g_.position(); }
  Graph::Checkpoint oldest_checkpoint() const { return g_.oldest_checkpoint(); }

  const std::vector<Rule>& rules() const { return rules_; }
  const EngineCounters& counters() const { return counters_; }
  /// Applications so far, by rule name.
  const std::map<std::string, std::size_t>& applications() const { return applications_; }
  /// Makes every element a candidate again (after the graph changed outside the engine).
  void rescan();
  /// The reference mode the tests compare the incremental one with: after
  /// every step, every element is a candidate again.
  void set_full_rescan(bool on) { full_rescan_ = on; }

private:
  struct Entry {
    std::int64_t key;
    Id anchor;
    bool operator>(const Entry& o) const { return key != o.key ? key > o.key : anchor > o.anchor; }
  };
  struct RuleState {
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;  ///< picks by priority, sequence
    std::vector<Id> pool;                                                 ///< random picks
    std::vector<bool> queued, pooled;  ///< in `queue` (a rule without order), in `pool`
    bool use_queue = false, use_pool = false;  ///< a selection in use picks it so
    std::vector<std::vector<int>> relevant;  ///< relevance_key -> variables
    std::vector<std::vector<int>> relevant_to_negatives;  ///< relevance_key -> variables read by negatives only
  };
  struct SelectionState {
    std::vector<std::vector<std::size_t>> tiers;  ///< rule indices, first tier first
    bool random = false;
    bool active = false;  ///< its rules are matched and kept up to date
  };

  Selection all_by_priority();
  void activate(SelectionState& s);
  void offer(std::size_t rule, Id anchor);
  /// The first match at `anchor` that passes the rule's tests.
  bool match_at(std::size_t rule, Id anchor, Match& m);
  void index_relevance();
  std::size_t relevance_key(KindId kind, int change, std::size_t which) const {
    return (static_cast<std::size_t>(kind) * 3 + static_cast<std::size_t>(change)) * width_ + which;
  }
  /// Offers the anchors the logged changes concern; elements with ids from
  /// `first_new` on were created by the step (no_element: none were, as after
  /// a rollback).
  void process_changes(Id first_new);
  /// Adds to anchors_ the anchors whose match may involve `element` as `var`.
  void trace(const Rule& rule, int var, Id element);
  /// Pops candidates of `rule` until one still matches with an up-to-date key.
  bool pop_best(std::size_t rule, Entry& entry, Match& m);
  bool try_rule_queue(std::size_t rule, Application* applied);
  bool try_random_tier(const std::vector<std::size_t>& tier, Application* applied);
  void apply_rule(std::size_t rule, Match& m, Application* applied);
  /// Throws RuleError if the application just made broke what it must keep.
  void check_application(const Rule& rule) const;
  std::size_t rule_index(const Rule* r) const { return static_cast<std::size_t>(r - rules_.data()); }

  Graph& g_;
  std::vector<Rule> rules_;
  Actions actions_;
  Matcher matcher_;
  std::vector<RuleState> state_;
  std::vector<SelectionState> selections_;
  Selection all_by_priority_ = SIZE_MAX;
  std::vector<Graph::Change> log_;
  std::size_t width_ = 1;
  // Scratch space reused from step to step.
  Match scratch_;
  std::vector<Id> anchors_, current_, next_;
  std::vector<std::pair<int, Id>> seeds_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t stamp_now_ = 0;
  std::mt19937_64 rng_;
  bool full_rescan_ = false;
  EngineCounters counters_;
  std::map<std::string, std::size_t> applications_;
  Invariant invariant_;
  std::vector<bool> checked_;  ///< per rule: run invariant_ after its applications
};

}  // namespace loom::engine
