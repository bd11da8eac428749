#include "src/cli/weave_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/check/quality_histogram.hpp"
#include "src/check/surface_angle_bound.hpp"
#include "src/check/validity.hpp"
#include "src/check/verdict.hpp"
#include "src/cli/weave_report.hpp"
#include "src/geometry/inversion_causes.hpp"
#include "src/io/hex_io.hpp"
#include "src/io/mesh_format.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/stc/sheet_diagram.hpp"
#include "src/util/atomic_file.hpp"
#include "src/util/error.hpp"
#include "src/weave/step_dump.hpp"
#include "src/weave/weave.hpp"

namespace loom::cli {

namespace {

/// A broken rule is bad input: one line naming file:line:column.
loom::InputError rule_error(const loom::engine::RuleError& e) {
  return loom::InputError(e.pos.line > 0 ? std::string(e.what()) + "; fix the rule file (grammar: docs/rules.md)"
                                         : std::string(e.what()));
}

std::vector<loom::engine::Rule> load_rules(const std::string& dir) {
  try {
    auto rules = loom::engine::load_rule_dir(dir, *loom::stc::StcSchema::get().schema);
    loom::stc::Stc scratch;
    auto actions = loom::weave::weave_actions(scratch);
    for (const auto& r : rules) loom::engine::check_actions(r, actions, *loom::stc::StcSchema::get().schema);
    return rules;
  } catch (const loom::engine::RuleError& e) {
    throw rule_error(e);
  }
}

loom::engine::Strategy parse_strategy(const WeaveCommandOptions& o, const std::vector<loom::engine::Rule>& rules) {
  loom::engine::Strategy s;
  try {
    if (!o.strategy.empty()) s = loom::weave::strategy_named(o.strategy);
    else s = o.rules.empty() ? loom::weave::default_strategy() : loom::weave::strategy_of(o.rules);
    loom::engine::check_strategy(s, rules, loom::weave::strategy_measures());
  } catch (const std::invalid_argument& e) {
    throw loom::InputError(e.what());
  } catch (const loom::engine::RuleError& e) {
    throw loom::InputError(e.pos.line > 0 ? std::string(e.what()) + "; fix the strategy file (grammar: docs/strategies.md)"
                                          : std::string(e.what()));
  }
  if (o.seed_given) s.seed = o.seed;
  return s;
}

/// One line per application: step, rule, anchor, then variable=element.
std::string trace_line(const loom::engine::Application& a) {
  std::string line = fmt::format("{} {} anchor={}", a.step, a.rule->name, a.matched.anchor());
  for (int v = 0; v < a.rule->pattern_vars; ++v)
    line += fmt::format(" {}={}", a.rule->vars[v].name, a.matched.elements[v]);
  return line + "\n";
}

/// --partial: the hexes woven so far as OUTPUT-stem.partial.EXT, and the STC
/// with its sheet diagrams in the directory OUTPUT-stem.partial/.
void write_partial(const std::filesystem::path& output, const loom::stc::Stc& stc, loom::stc::PictureFailures& failures,
                   std::size_t svg_limit) {
  std::filesystem::path mesh = output, dir = output;
  mesh.replace_extension(".partial" + output.extension().string());
  dir.replace_extension(".partial");
  loom::write_hex_mesh(mesh, loom::stc::woven_hexes(stc));
  loom::stc::write_stc_dot(stc, dir, failures, svg_limit);
  std::cerr << fmt::format("partial state: {} (hexes woven so far) and {}/ (STC and sheet diagrams)\n", mesh.string(),
                           dir.string());
}

/// The names --check-rules gives ('all': every rule loaded), each one loaded.
std::vector<std::string> checked_rules(const WeaveCommandOptions& o, const std::vector<loom::engine::Rule>& rules) {
  std::vector<std::string> names;
  for (const std::string& name : o.check_rules) {
    if (name == "all") {
      for (const auto& r : rules) names.push_back(r.name);
      continue;
    }
    if (std::none_of(rules.begin(), rules.end(), [&](const auto& r) { return r.name == name; }))
      throw loom::InputError(fmt::format("--check-rules: no rule '{}' is loaded; see 'loom rules list'", name));
    names.push_back(name);
  }
  return names;
}

}  // namespace

int run_weave(const WeaveCommandOptions& o, const std::function<QuadSurface(RunBudget&)>& surface_of) {
  if (o.dot_steps && o.dot_dir.empty()) throw loom::InputError("--dot-steps needs --dot DIR to write into");
  loom::hex_format_of(o.output);  // an unwritable format is refused before any work
  // Rules and strategy before the surface: a broken file is refused before Gmsh's meshing.
  const std::filesystem::path rules_dir = o.rules.empty() ? loom::weave::default_rules_dir() : std::filesystem::path(o.rules);
  auto rules = load_rules(rules_dir.string());
  loom::pipeline::MeshingOptions options = loom::pipeline::default_meshing_options(rules_dir);
  options.weave.strategy = parse_strategy(o, rules);
  options.weave.check_rules = checked_rules(o, rules);
  RunBudget budget(o.max_seconds, o.max_memory, o.progress);
  loom::QuadSurface surface = surface_of(budget);
  const loom::SurfaceAngleBound bound = loom::surface_angle_bound(surface);
  if (bound.quads_below_0_2 > 0)
    std::cerr << fmt::format("loom: note: {} quad{} of the surface ha{} a corner angle whose sine is below 0.2 (the "
                             "least {:.3f}): no hex mesh bounded by it has every scaled Jacobian above {:.3f}\n",
                             bound.quads_below_0_2, bound.quads_below_0_2 == 1 ? "" : "s",
                             bound.quads_below_0_2 == 1 ? "s" : "ve", bound.least_sine, bound.least_sine);
  options.attempts = o.attempts;
  options.closure = o.closure;
  options.prefer = o.prefer;
  options.on_stage = [&](const char* stage) { budget.stage(stage); };

  // The trace is written as the weave goes, a line a step, so that a run that
  // stops halfway (a broken rule, a kill) keeps it. It holds every attempt,
  // each after a line naming it, and says which applications were undone.
  std::ofstream trace;
  auto start_attempt_in_trace = [&](std::size_t attempt, const loom::engine::Strategy& s) {
    if (o.trace.empty()) return;
    if (!trace.is_open()) {
      trace = std::ofstream(o.trace, std::ios::trunc);
      if (!trace) loom::fail_input(o.trace, "cannot write the trace file", "choose another --trace path");
    }
    trace << fmt::format("# attempt {}: strategy {}, seed {}\n", attempt, s.name(), s.seed) << std::flush;
  };
  start_attempt_in_trace(1, options.weave.strategy);
  std::optional<loom::weave::StepDumper> steps;
  if (o.dot_steps) steps.emplace(std::filesystem::path(o.dot_dir) / "steps", !o.no_svg);
  bool progress = !o.quiet && !o.progress && ::isatty(STDERR_FILENO);
  auto last = std::chrono::steady_clock::now();
  options.weave.after_step = [&](const loom::engine::Application& a, const loom::stc::Stc& stc) {
    if (trace.is_open()) trace << trace_line(a) << std::flush;
    if (steps) steps->dump(a, stc);
    // Counting whiskers takes a pass over the STC: four times a second at most.
    if (std::chrono::steady_clock::now() - last > std::chrono::milliseconds(250)) {
      last = std::chrono::steady_clock::now();
      const std::size_t whiskers = stc.whiskers();
      budget.weaving(a.step, stc.hexes(), whiskers);
      if (progress)
        std::cerr << fmt::format("\rweaving: {} steps, {} hexes, {} whiskers left   ", a.step, stc.hexes(), whiskers);
    }
  };

  options.weave.after_undo = [&](std::size_t step) {
    if (trace.is_open()) trace << fmt::format("undo {}\n", step) << std::flush;
  };
  options.before_attempt = [&](std::size_t attempt, const loom::engine::Strategy& s, const loom::weave::WeaveResult&) {
    start_attempt_in_trace(attempt, s);
    if (steps) steps->clear();
  };

  loom::pipeline::MeshingResult result;
  try {
    result = loom::pipeline::mesh_surface(surface, std::move(rules), options);
  } catch (const loom::engine::RuleError& e) {
    throw rule_error(e);
  }
  if (progress) std::cerr << "\r" << std::string(60, ' ') << "\r";
  if (steps) {
    budget.stage("drawing the step pictures");
    steps->render();
  }
  budget.commit();

  // Diagnostics describe the run whatever its outcome; the mesh is written only on success.
  if (!o.report.empty())
    loom::write_text_atomically(o.report,
                                report_json(o.input, {bound, loom::surface_half_thickness(surface)}, result).dump(2) + "\n");
  loom::stc::PictureFailures pictures = steps ? steps->picture_failures() : loom::stc::PictureFailures{};
  const std::size_t svg_limit = o.no_svg ? 0 : 4000;
  // --dot draws the mesh that is written. When the weave made all of it, that
  // is the weave's STC, numbered as the step pictures are; when closure or the
  // boundary layer added hexes, it is the dual built from the mesh. With no
  // mesh, it is the weave's last state, which shows where it stopped.
  if (!o.dot_dir.empty()) {
    const bool woven_whole = result.mesh && result.stc.hexes() == result.mesh->hexes.size() && result.made_by == "woven";
    loom::stc::write_stc_dot(result.combinatorially_valid() && !woven_whole ? loom::stc::build_from_hex_mesh(*result.mesh)
                                                                           : result.stc,
                             o.dot_dir, pictures, svg_limit);
  }
  // The weave's partial state, also when the fill then meshed the surface.
  if (o.partial && !result.weave.closed) write_partial(o.output, result.stc, pictures, svg_limit);
  if (pictures.count) std::cerr << pictures.warning() << "\n";

  if (!result.combinatorially_valid()) {
    const auto* fail = result.check ? result.check->first_failure() : nullptr;
    std::string why = fail ? fmt::format("criterion {} ({}) fails: {}", fail->number, fail->name, fail->detail) : result.failure;
    if (result.filled()) {
      std::cerr << "loom: internal error: the constructive fill's mesh is not valid: " << why
                << "; nothing written; please report it with the input\n";
      return 1;
    }
    std::string after;
    if (!result.closure_failure.empty()) after += "; the cavity closure gave no mesh: " + result.closure_failure;
    if (!result.fill_failure.empty()) after += "; nor can the constructive fill mesh it: " + result.fill_failure;
    if (o.closure == loom::pipeline::Closure::none) after += "; try another --strategy, add rules, or drop --closure none";
    if (!result.weave.closed) {
      std::cerr << "loom: weave did not close" << (result.attempts > 1 ? fmt::format(" in {} attempts", result.attempts) : "")
                << ": " << result.weave.left << after << "\n";
      return 1;
    }
    std::cerr << "loom: weave closed but the result is not a valid hex mesh: " << why << after << "; nothing written\n";
    return 1;
  }
  loom::write_hex_mesh(o.output, *result.mesh, cell_fields(*result.mesh, result.source, result.inversions));
  if (!o.plot.empty())
    loom::write_text_atomically(o.plot, loom::histogram_svg(loom::quality_histogram(*result.mesh),
                                                            o.input + ": " + o.output));
  const auto& q = result.check->quality;
  const std::size_t hexes = result.mesh->hexes.size();
  auto count = [&](loom::closure::HexSource s) { return std::count(result.source.begin(), result.source.end(), s); };
  std::string counts;
  for (const auto& [rule, n] : result.weave.applications) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", rule, n);
  const std::size_t attempt_shown = result.attempts - result.attempts_before_cut;  // the ball's, when cut
  std::string attempt = attempt_shown == 1 ? std::string()
                        : fmt::format(" (attempt {}: strategy {} seed {})", attempt_shown, result.strategy.name(),
                                      result.strategy.seed);
  std::string layer = result.boundary_layer.hexes_added == 0
                          ? std::string()
                          : fmt::format(", boundary layer pillowed (+{} hexes)", result.boundary_layer.hexes_added);
  if (result.cut_disks > 0)
    layer = fmt::format(", the solid cut into a ball along {} meridian disk{} and glued back{}", result.cut_disks,
                        result.cut_disks == 1 ? "" : "s", layer);
  std::string quality = fmt::format("min scaled Jacobian {:.3f}, mean {:.3f}; wrote {}", q.min_scaled_jacobian,
                                    q.mean_scaled_jacobian, o.output);
  using loom::closure::HexSource;
  if (result.made_by == "filled")
    std::cout << fmt::format("filled: {} hexes by the constructive fill, as neither the weave ({} attempt{}) nor the "
                             "cavity closure gave a valid mesh; {}\n",
                             hexes, result.attempts, result.attempts == 1 ? "" : "s", quality);
  else if (result.made_by == "closed")
    std::cout << fmt::format("closed: {} hexes = {} woven (of the weave that left the fewest whiskers; {} peeled) + {} "
                             "searched + {} from the database + {} filled + {} pillow, in {} cavit{} of {} quads{}{}; {}\n",
                             hexes, count(HexSource::woven), result.closure.peeled, count(HexSource::searched),
                             count(HexSource::database), count(HexSource::filled), count(HexSource::pillow),
                             result.closure.cavities, result.closure.cavities == 1 ? "y" : "ies",
                             result.closure.front_quads,
                             result.closure.pull_backs ? fmt::format(" after {} pull-back{} round stuck fronts",
                                                                     result.closure.pull_backs,
                                                                     result.closure.pull_backs == 1 ? "" : "s")
                                                       : "",
                             layer, quality);
  else if (result.made_by == "searched")
    std::cout << fmt::format("searched: {} hexes = {} searched + {} from the database + {} filled + {} pillow, from the "
                             "surface itself, better by --prefer {} than what the weave and its cavities gave{}{}; {}\n",
                             hexes, count(HexSource::searched), count(HexSource::database), count(HexSource::filled),
                             count(HexSource::pillow), o.prefer == loom::pipeline::Prefer::quality ? "quality" : "fewest-hexes",
                             result.weave.closed ? fmt::format(" (the weave: {} hexes)", result.stc.hexes()) : "",
                             layer, quality);
  else
    std::cout << fmt::format("woven: {} hex{} in {} steps ({}){}{}; {}\n", hexes, hexes == 1 ? "" : "es",
                             result.weave.steps, counts, attempt, layer, quality);
  if (!result.wide_search_stopped.empty())
    std::cerr << fmt::format("loom: note: the last searches for a mesh within 72 hexes stopped: {}; the mesh found "
                             "before them is written; raise --max-memory to let them finish\n",
                             result.wide_search_stopped);
  if (const std::string note = loom::centre_note(q); !note.empty())
    std::cerr << "loom: warning: criterion 7 holds" << note << "\n";
  if (q.below_zero > 0) {
    std::cerr << fmt::format("loom: warning: {} hexes have a scaled Jacobian <= 0 (minimum {:.3f}): {}; the cell "
                             "field inversion_cause names them; the mesh is written for its connectivity\n",
                             q.below_zero, q.min_scaled_jacobian,
                             geometry::describe(result.inversions));
    return 3;
  }
  return 0;
}

void add_weave_options(CLI::App& app, WeaveCommandOptions& o) {
  app.add_option("-o,--output", o.output, "hex mesh to write (.vtk .vtu .msh .exo .e)")->required();
  app.add_option("--rules", o.rules, "directory of *.rule files, and of the closure database and fill caps the run may use (closure/, fill/; default: the shipped rules/)");
  app.add_option("--strategy", o.strategy, "a strategy file (default: the rules' strategies/default.strategy, else priority), priority, random or sequence:RULE,RULE...");
  app.add_option("--check-rules", o.check_rules,
                 "check the STC invariants after every application of these rules (names, or 'all'); a violation "
                 "rolls the application back and stops with exit 2 naming the rule")
      ->delimiter(',');
  app.add_option("--seed", o.seed, "seed of the random strategy")->each([&o](const std::string&) { o.seed_given = true; });
  app.add_option("--attempts", o.attempts,
                 "weaves to try: when one gives no valid mesh, weave again with the random strategy, seeds 1, 2, ... "
                 "(default 16; 1: only the strategy given)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  app.add_option("--dot", o.dot_dir, "write the STC of the mesh written (else the weave's last state) and its sheet diagrams (DOT and SVG) into this directory");
  app.add_flag("--dot-steps", o.dot_steps, "also write one picture per rule application into DIR/steps");
  app.add_flag("--no-svg", o.no_svg, "with --dot or --partial: write DOT files only, no SVG");
  app.add_option("--trace", o.trace, "write one line per rule application to this file");
  app.add_option("--report", o.report, "write a JSON report to this file");
  app.add_option("--plot", o.plot, "with the mesh, write a bar chart (SVG) of its scaled Jacobians to this file");
  app.add_flag("--partial", o.partial, "when the weave does not close, write the hexes woven so far and the STC (DOT/SVG) for inspection");
  // Named choices: a string checked against the names (so a wrong one is
  // answered with the names), then looked up.
  auto add_choice = [&app](const char* flag, auto& target, auto names, const char* help) {
    std::vector<std::string> keys;
    for (const auto& [name, value] : names) keys.push_back(name);
    app.add_option_function<std::string>(
           flag, [&target, names](const std::string& v) {
             target = names.at(CLI::detail::to_lower(v));
           }, help)
        ->check(CLI::IsMember(keys, CLI::ignore_case).description(""))
        ->type_name(fmt::format("{{{}}}", fmt::join(keys, ",")));
  };
  add_choice("--closure", o.closure,
             std::map<std::string, loom::pipeline::Closure>{{"full", loom::pipeline::Closure::full},
                                                            {"none", loom::pipeline::Closure::none},
                                                            {"search", loom::pipeline::Closure::search}},
             "what runs when no weave gives a valid mesh: full (default: cavity search, database and fill, then "
             "the whole-surface fill), search (cavity search and database only) or none (the weave alone)");
  add_choice("--prefer", o.prefer,
             std::map<std::string, loom::pipeline::Prefer>{{"quality", loom::pipeline::Prefer::quality},
                                                           {"fewest-hexes", loom::pipeline::Prefer::fewest_hexes}},
             "which of two meshes the run keeps: quality (default: fewer hexes with a scaled Jacobian <= 0, then "
             "< 0.2, then fewer hexes) or fewest-hexes");
  app.add_flag_callback("--no-fill", [&o] { o.closure = loom::pipeline::Closure::none; }, "the same as --closure none");
  app.add_flag("-q,--quiet", o.quiet, "no progress line");
  app.add_flag("--progress", o.progress, "a progress line on stderr as each stage starts and every 5 s, also when stderr is not a terminal");
  app.add_option("--max-seconds", o.max_seconds, "stop the run (status 1, nothing written) after this many seconds")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-memory", o.max_memory, "cap the memory the run may allocate, in MB (status 1 when it needs more)")
      ->check(CLI::PositiveNumber);
}

}  // namespace loom::cli
