#pragma once
// What `loom weave SURFACE` and `loom mesh PART` share: their options, and the
// run from a quad surface to the written hex mesh (weave, closure, placement,
// check, outputs). Exit 0: closed, valid, every scaled Jacobian > 0; 3: closed
// and combinatorially valid but some scaled Jacobian <= 0 (written anyway);
// 1: not closed or not valid (nothing written); 2: bad input or usage (thrown
// as InputError).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "src/cli/run_budget.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace loom::cli {

struct WeaveCommandOptions {
  std::string input, output, rules, strategy, dot_dir, trace, report, plot;
  std::vector<std::string> check_rules;
  std::uint64_t seed = 0;
  std::size_t attempts = 16;
  pipeline::Closure closure = pipeline::Closure::full;
  pipeline::Prefer prefer = pipeline::Prefer::quality;
  bool seed_given = false, dot_steps = false, partial = false, quiet = false, no_svg = false;
  bool progress = false;
  double max_seconds = 0;
  std::uint64_t max_memory = 0;
};

/// Adds every option but the input to `app`; `o` must outlive the parse.
void add_weave_options(CLI::App& app, WeaveCommandOptions& o);

/// Runs the pipeline on the surface `surface_of` gives (called once the
/// budget runs, so --max-seconds and --progress cover it) and writes what the
/// options ask for. Returns the exit status.
int run_weave(const WeaveCommandOptions& o, const std::function<QuadSurface(RunBudget&)>& surface_of);

}  // namespace loom::cli
