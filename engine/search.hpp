#pragma once
// Best-first search over a state space the caller defines: anytime weighted
// A* (priority = cost so far + weight * estimate of the cost to go), with
// duplicate states merged by a key, limits on expansions, open states and
// seconds, and a deterministic order (ties go to the state generated first).
// A goal is recorded when generated, not queued; the search goes on for a
// cheaper one while its budget lasts, dropping every state that cannot beat
// the best goal by its lower bound.
//
// A Space provides:
//   using State = ...;                       movable
//   using Key = ...; using KeyHash = ...;    states with equal keys are one state
//   Key key(const State&);
//   double cost(const State&);               paid so far
//   double estimate(const State&);           still to pay (0 at a goal)
//   double lower_bound(const State&);        still to pay at least
//   bool goal(const State&);
//   void expand(const State&, F&& emit);     emit(State&&) for each successor,
//                                            in a deterministic order
// With weight 1 and an estimate that never overshoots, a search that runs
// to the end finds a cheapest goal; larger weights trade that for speed.
#include <chrono>
#include <limits>
#include <cstddef>
#include <optional>
#include <queue>
#include <unordered_map>
#include <vector>

namespace loom::engine {

struct SearchLimits {
  std::size_t max_expansions = 100'000;
  std::size_t max_open = 1'000'000;  ///< open states kept; beyond it the worst are not added
  double max_seconds = 10;
  double weight = 1;                 ///< priority = cost + weight * estimate
};

struct SearchStats {
  std::size_t expanded = 0, generated = 0, merged = 0;  ///< merged: duplicates dropped
  std::size_t goals = 0, pruned = 0;  ///< goals generated; states dropped as unable to beat the best goal
  std::size_t peak_open = 0, keys = 0;                  ///< most states open at once; distinct keys seen
  double seconds = 0;
  bool exhausted = false;   ///< the open list ran empty: the goal found is the cheapest (weight 1)
  bool out_of_budget = false;
  double expansions_per_second() const { return seconds > 0 ? expanded / seconds : 0; }
  double states_per_second() const { return seconds > 0 ? generated / seconds : 0; }
};

template <class State>
struct SearchOutcome {
  std::optional<State> goal;     ///< the cheapest goal found, if any
  std::optional<State> closest;  ///< the expanded state with the least estimate (ties: least cost)
  SearchStats stats;
};

/// What both searches do with a state just generated: count it, record it if
/// it is a goal cheaper than `best_goal`, and drop it if it cannot beat that
/// goal by its lower bound. True when the state went no further.
template <class Space, class State>
bool goal_or_pruned(Space& space, State& s, double& best_goal, SearchOutcome<State>& out) {
  ++out.stats.generated;
  const double g = space.cost(s);
  if (space.goal(s)) {
    ++out.stats.goals;
    if (g < best_goal) {
      best_goal = g;
      out.goal = std::move(s);
    }
    return true;
  }
  if (g + space.lower_bound(s) >= best_goal) {
    ++out.stats.pruned;
    return true;
  }
  return false;
}

template <class Space>
SearchOutcome<typename Space::State> best_first_search(Space& space, typename Space::State start,
                                                       const SearchLimits& limits) {
  using State = typename Space::State;
  using Clock = std::chrono::steady_clock;
  struct Open {
    double priority;
    std::size_t sequence;
    bool operator>(const Open& o) const { return priority != o.priority ? priority > o.priority : sequence > o.sequence; }
  };
  SearchOutcome<State> out;
  const auto begin = Clock::now();
  std::vector<std::optional<State>> states;
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  std::unordered_map<typename Space::Key, double, typename Space::KeyHash> best_cost;
  double closest_estimate = 0, closest_cost = 0;
  double best_goal = std::numeric_limits<double>::infinity();

  auto push = [&](State&& s) {
    if (goal_or_pruned(space, s, best_goal, out)) return;
    const double g = space.cost(s);
    auto [it, fresh] = best_cost.try_emplace(space.key(s), g);
    if (!fresh) {
      if (it->second <= g) {
        ++out.stats.merged;
        return;
      }
      it->second = g;
    }
    if (open.size() >= limits.max_open) return;
    const double priority = g + limits.weight * space.estimate(s);
    open.push({priority, states.size()});
    states.emplace_back(std::move(s));
    out.stats.peak_open = std::max(out.stats.peak_open, open.size());
  };

  push(std::move(start));
  while (!open.empty()) {
    if (out.stats.expanded >= limits.max_expansions ||
        std::chrono::duration<double>(Clock::now() - begin).count() > limits.max_seconds) {
      out.stats.out_of_budget = true;
      break;
    }
    const Open top = open.top();
    open.pop();
    State s = std::move(*states[top.sequence]);
    states[top.sequence].reset();
    const double h = space.estimate(s), g = space.cost(s);
    if (g + space.lower_bound(s) >= best_goal) {
      ++out.stats.pruned;
      continue;
    }
    if (!out.closest || h < closest_estimate || (h == closest_estimate && g < closest_cost)) {
      closest_estimate = h;
      closest_cost = g;
      out.closest = s;
    }
    ++out.stats.expanded;
    space.expand(s, [&](State&& next) { push(std::move(next)); });
  }
  out.stats.exhausted = open.empty();
  out.stats.keys = best_cost.size();
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return out;
}

}  // namespace loom::engine
