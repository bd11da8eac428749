#pragma once
// The weave: from the initial STC of a surface, apply the rules under a
// strategy until no rule applies. Closed when no whisker is left.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "engine/rule.hpp"
#include "engine/strategy.hpp"
#include "engine/strategy_run.hpp"
#include "src/stc/stc.hpp"

namespace loom::closure {
class Database;
}

namespace loom::weave {

struct WeaveResult;

/// The shipped rules' strategy file (rules/strategies/default.strategy).
engine::Strategy default_strategy();
/// "priority", "random" or "sequence:a,b": one phase that applies every rule
/// (or those named) by that pick, backtracking on dead ends as the shipped
/// default does (window 64, branching 3, at most 200, goal `front`); else the
/// path of a strategy file. Throws as engine::Strategy::parse.
engine::Strategy strategy_named(const std::string& spec);
/// The strategy of a rule directory: its strategies/default.strategy if it
/// has one, else strategy_named("priority").
engine::Strategy strategy_of(const std::filesystem::path& rules_dir);

struct WeaveOptions {
  /// Its goals and costs may name strategy_measures(): `front`, the open hex
  /// sides left (0 when the weave has closed), `inverted`, `irregular`.
  engine::Strategy strategy = default_strategy();
  /// Stop after this many applications (0: 200 per initial face plus 10,000).
  std::size_t max_steps = 0;
  /// The rules after whose every application the STC invariants are checked
  /// (a violation rolls it back and names the rule); all of them when
  /// stc::invariant_checks_on().
  std::vector<std::string> check_rules;
  /// Called after every application (trace, pictures, progress).
  std::function<void(const engine::Application&, const stc::Stc&)> after_step;
  /// Called for each application after_step saw that the strategy then
  /// undid (a backtrack), newest first (engine::StrategyDomain::after_undo).
  std::function<void(std::size_t step)> after_undo;
  /// The closure database of the template rule's actions (closes_from_database,
  /// close_from_database; rules/closure/database.rule), asked when a rule
  /// first needs it; null: none, and the test fails. Unset: the one in
  /// default_rules_dir(). The pipeline passes the one its rules directory has.
  std::function<const closure::Database*()> database;
};

struct WeaveResult {
  bool closed = false;
  bool step_limit_hit = false;
  std::size_t steps = 0;
  std::size_t whiskers_left = 0;
  std::size_t backtracks = 0;       ///< choices undone to try another
  std::vector<engine::PhaseFigures> phases;  ///< of the strategy
  bool stalled = false;             ///< the weave stopped because its front stopped shrinking
  std::map<std::string, std::size_t> applications;  ///< by rule name
  engine::EngineCounters counters;
  /// One line saying what is left when the weave did not close.
  std::string left;
};

/// The rules shipped with Loom (the source tree's rules/, or $LOOM_RULES).
std::filesystem::path default_rules_dir();

/// The measures the weave offers a strategy's goals and costs
/// (docs/strategies.md): `front` (whiskers left), `inverted`, `irregular`.
const std::vector<std::string>& strategy_measures();

/// The domain's named actions, tests and measures that rules may use
/// (place_hex_corner; measures.hpp: angle, corner_sj, ...).
/// `database` as WeaveOptions::database.
engine::Actions weave_actions(stc::Stc& stc, std::function<const closure::Database*()> database = {});

/// Weaves `stc` in place with `rules`.
WeaveResult weave(stc::Stc& stc, std::vector<engine::Rule> rules, const WeaveOptions& options);

}  // namespace loom::weave
