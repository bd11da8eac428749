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
#include "src/stc/stc.hpp"

namespace loom::weave {

struct WeaveResult;

struct WeaveOptions {
  engine::Strategy strategy;
  /// Stop after this many applications (0: 200 per initial face plus 10,000).
  std::size_t max_steps = 0;
  /// When no rule applies and whiskers are left, go back to the latest of
  /// the last `backtrack_window` choices that had alternatives and take the
  /// next one (at most `branching` alternatives a choice, `max_backtracks` in all).
  std::size_t max_backtracks = 200;
  std::size_t branching = 3;
  std::size_t backtrack_window = 64;
  /// The rules after whose every application the STC invariants are checked
  /// (a violation rolls it back and names the rule); all of them when
  /// stc::invariant_checks_on().
  std::vector<std::string> check_rules;
  /// Called after every application (trace, pictures, progress).
  std::function<void(const engine::Application&, const stc::Stc&)> after_step;
};

struct WeaveResult {
  bool closed = false;
  bool step_limit_hit = false;
  std::size_t steps = 0;
  std::size_t whiskers_left = 0;
  std::size_t backtracks = 0;       ///< choices undone to try another
  bool stalled = false;             ///< the weave stopped because its front stopped shrinking
  std::map<std::string, std::size_t> applications;  ///< by rule name
  engine::EngineCounters counters;
  /// One line saying what is left when the weave did not close.
  std::string left;
};

/// The rules shipped with Loom (the source tree's rules/, or $LOOM_RULES).
std::filesystem::path default_rules_dir();

/// The domain's named actions that rules may call (place_hex_corner).
engine::Actions weave_actions(stc::Stc& stc);

/// Weaves `stc` in place with `rules`.
WeaveResult weave(stc::Stc& stc, std::vector<engine::Rule> rules, const WeaveOptions& options);

}  // namespace loom::weave
