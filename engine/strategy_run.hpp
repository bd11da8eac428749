#pragma once
// Running a strategy (strategy.hpp) on an engine: the interpreter of its
// phases, applies, repeats, tries, backtracking and iterative-deepening searches.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "engine/strategy.hpp"

namespace loom::engine {

/// What the domain gives a strategy: the measures a backtrack's goal may name
/// (the goal is met when the measure is 0), what to do after every
/// application, and a bound on applications.
struct StrategyDomain {
  std::map<std::string, std::function<std::int64_t()>> measures;
  /// Called after each application the strategy keeps for now; a search's
  /// trial applications are not shown, only the path it settles on.
  std::function<void(const Application&)> after_step;
  /// Called for each application after_step showed that a backtrack or a
  /// failed try then undoes, newest first, with its step number. After it,
  /// the applications shown and not undone are exactly those on the graph.
  std::function<void(std::size_t step)> after_undo;
  std::size_t max_steps = SIZE_MAX;
};

struct PhaseFigures {
  std::string name;
  std::size_t steps = 0;       ///< applications kept or undone
  std::size_t backtracks = 0;  ///< choices undone to take another
  std::size_t searched = 0;    ///< applications a search tried (kept or not)
  double seconds = 0;
};

struct StrategyOutcome {
  std::vector<PhaseFigures> phases;
  std::size_t backtracks = 0;
  bool stalled = false;          ///< a backtrack stopped: its measure stopped reaching new minima
  std::size_t stalled_for = 0;   ///< applications since its last minimum
  bool step_limit_hit = false;
};

/// Throws RuleError (at the strategy's file:line:column) if it names a rule
/// that is not among `rules`, or a measure that is not among `measures`.
void check_strategy(const Strategy& strategy, const std::vector<Rule>& rules, const std::vector<std::string>& measures);

/// Runs every phase of `strategy` in turn on `engine` (whose rules it names;
/// check_strategy() first). Throws RuleError when an application fails.
StrategyOutcome run_strategy(Engine& engine, const Strategy& strategy, const StrategyDomain& domain);

}  // namespace loom::engine
