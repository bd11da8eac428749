#pragma once
// Engine: applies rules to a graph, one match at a time, under a strategy.
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
// graph; if its rewrite throws, its action declines, it leaves a slot of a
// required port empty (schema.hpp) or it breaks an invariant the caller asked
// to check, the graph is rolled back to where it was, and (but for a decline)
// a RuleError names the rule and its file.
#include <cstdint>
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
  /// Throws RuleError if a rule calls an unknown action, std::invalid_argument
  /// if a sequence strategy names an unknown rule.
  Engine(Graph& graph, std::vector<Rule> rules, Actions actions, Strategy strategy);

  /// Applies one match, chosen by the strategy (a match whose action declines
  /// is passed over). Returns false when no rule applies. Throws RuleError
  /// when the application failed; the graph is then as it was before.
  bool step(Application* applied = nullptr);

  /// A check of the whole graph: empty when it holds, else what is broken.
  using Invariant = std::function<std::string(const Graph&)>;
  /// Runs `check` after each application of the rules named (of every rule
  /// when `rules` is empty); throws std::invalid_argument naming a rule that
  /// is not loaded.
  void check_after(Invariant check, const std::vector<std::string>& rules = {});

  // --- choices and undo, for search with backtracking -------------------------
  /// Up to `limit` applicable matches, best first, from the highest-priority
  /// rules that have any (what step() would apply is the first).
  std::vector<Match> choices(std::size_t limit);
  /// Applies a match (one of choices(), on the graph as it is now); false
  /// when its action declined (nothing changed, nothing counted).
  bool apply(Match m, Application* applied = nullptr);
  /// Opens a checkpoint of the graph; undo() goes back to it (and keeps it open).
  Graph::Checkpoint mark() { return g_.checkpoint(); }
  void undo(Graph::Checkpoint c);
  /// Keeps the changes made since `c` for good.
  void release(Graph::Checkpoint c) { g_.release(c); }

  const std::vector<Rule>& rules() const { return rules_; }
  const EngineCounters& counters() const { return counters_; }
  /// Applications so far, by rule name.
  const std::map<std::string, std::size_t>& applications() const { return applications_; }
  /// Makes every element a candidate again (after the graph changed outside the engine).
  void rescan();
  /// Offers again every match whose action declined since the last call
  /// (they are otherwise looked at again only when something changes near
  /// them); returns how many.
  std::size_t retry_declined();
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
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;  ///< priority, sequence
    std::vector<Id> pool;                                                 ///< random
    std::vector<bool> pooled;    ///< in `pool` (random) or in `queue` (a rule without order)
    bool enabled = true;
    std::int64_t rank = 0;  ///< higher first
    std::vector<std::vector<int>> relevant;  ///< relevance_key -> variables
  };

  void offer(std::size_t rule, Id anchor);
  void index_relevance();
  std::size_t relevance_key(KindId kind, int change, std::size_t which) const {
    return (static_cast<std::size_t>(kind) * 3 + static_cast<std::size_t>(change)) * width_ + which;
  }
  void process_changes();
  /// Adds to anchors_ the anchors whose match may involve `element` as `var`.
  void trace(const Rule& rule, int var, Id element);
  /// Pops candidates of `rule` until one still matches with an up-to-date key.
  bool pop_best(std::size_t rule, Entry& entry, Match& m);
  bool try_rule_queue(std::size_t rule, Application* applied);
  bool try_random_tier(const std::vector<std::size_t>& tier, Application* applied);
  bool apply_rule(std::size_t rule, Match& m, Application* applied);
  /// Throws RuleError if the application just made broke what it must keep.
  void check_application(const Rule& rule) const;
  std::size_t rule_index(const Rule* r) const { return static_cast<std::size_t>(r - rules_.data()); }

  Graph& g_;
  std::vector<Rule> rules_;
  Actions actions_;
  Strategy strategy_;
  Matcher matcher_;
  std::vector<RuleState> state_;
  std::vector<std::vector<std::size_t>> tiers_;  ///< rule indices, highest rank first
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
  std::vector<std::pair<std::size_t, Id>> declined_;  ///< (rule, anchor)
  Invariant invariant_;
  std::vector<bool> checked_;  ///< per rule: run invariant_ after its applications
};

}  // namespace loom::engine
