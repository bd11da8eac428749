#pragma once
// Beam search over a state space the caller defines: the same Space as
// best_first_search (search.hpp), searched level by level. Every state of a
// level is expanded; of the states they generate, only the `width` with the
// least priority (cost + weight * estimate; ties to the state generated
// first) make the next level. A key seen at any earlier level is not kept
// again. Goals are recorded when generated, as in best_first_search, and a
// state that cannot beat the best goal by its lower bound is dropped.
// `closest` is the first state of the last level kept.
//
// Where best-first search spends its budget round the cheapest states, a beam
// goes deep along a few: the shape of search that suits an expensive
// estimate, such as a whole inner search run on each state.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>
#include <unordered_set>
#include <vector>

#include "engine/search.hpp"

namespace loom::engine {

struct BeamLimits {
  std::size_t width = 10;      ///< states kept at each level
  std::size_t max_depth = 6;   ///< levels below the start
  std::size_t max_expansions = 10'000;
  double max_seconds = 600;    ///< a guard against a runaway, checked between expansions
  double weight = 1;           ///< priority = cost + weight * estimate
};

template <class Space>
SearchOutcome<typename Space::State> beam_search(Space& space, typename Space::State start, const BeamLimits& limits) {
  using State = typename Space::State;
  using Clock = std::chrono::steady_clock;
  struct Ranked {
    double priority;
    std::size_t sequence;
    State state;
  };
  SearchOutcome<State> out;
  const auto begin = Clock::now();
  std::unordered_set<typename Space::Key, typename Space::KeyHash> seen;
  double best_goal = std::numeric_limits<double>::infinity();
  std::vector<State> level;
  seen.insert(space.key(start));
  level.push_back(std::move(start));
  for (std::size_t depth = 0; depth < limits.max_depth && !level.empty(); ++depth) {
    std::vector<Ranked> next;
    auto emit = [&](State&& s) {
      if (goal_or_pruned(space, s, best_goal, out)) return;
      if (!seen.insert(space.key(s)).second) {
        ++out.stats.merged;
        return;
      }
      const double priority = space.cost(s) + limits.weight * space.estimate(s);
      next.push_back({priority, out.stats.generated, std::move(s)});
    };
    for (const State& s : level) {
      if (out.stats.expanded >= limits.max_expansions ||
          std::chrono::duration<double>(Clock::now() - begin).count() > limits.max_seconds) {
        out.stats.out_of_budget = true;
        break;
      }
      ++out.stats.expanded;
      space.expand(s, emit);
    }
    std::sort(next.begin(), next.end(), [](const Ranked& a, const Ranked& b) {
      return a.priority != b.priority ? a.priority < b.priority : a.sequence < b.sequence;
    });
    if (next.size() > limits.width) next.resize(limits.width);
    out.stats.peak_open = std::max(out.stats.peak_open, next.size());
    level.clear();
    for (Ranked& r : next) level.push_back(std::move(r.state));
    if (!level.empty()) out.closest = level.front();
    if (out.stats.out_of_budget) break;
  }
  out.stats.exhausted = level.empty();
  out.stats.keys = seen.size();
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  return out;
}

}  // namespace loom::engine
