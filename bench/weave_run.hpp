#pragma once
// One measured weave of box n^3 for bench_weave: the rule sets it compares,
// the clocks, peak RSS, and the figures a child process prints back.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace loom::bench {

/// The two rule sets of issue #14 item 9: every shipped rule (what `loom
/// weave` loads), and cross and seam alone (the two rules of the first weave),
/// both from the shipped rules directory.
enum class RuleSet { two, shipped };
inline constexpr RuleSet kRuleSets[] = {RuleSet::two, RuleSet::shipped};

/// The token of --set and of the CSV's `rules` column.
inline const char* set_token(RuleSet s) { return s == RuleSet::two ? "two" : "shipped"; }
inline const char* set_title(RuleSet s) { return s == RuleSet::two ? "cross+seam" : "shipped"; }
inline RuleSet parse_set(const std::string& token) {
  if (token == "two") return RuleSet::two;
  if (token == "shipped") return RuleSet::shipped;
  throw std::runtime_error("bench_weave: unknown rule set '" + token + "' (two, shipped)");
}

/// The strategy each set weaves under: the shipped one for every shipped rule;
/// `priority` for cross and seam, as `loom weave --rules DIR` gives a folder
/// without a strategies/default.strategy (the shipped one names
/// pillow_improper, which that set has not).
inline weave::WeaveOptions weave_options(RuleSet set) {
  weave::WeaveOptions options;
  if (set == RuleSet::two) options.strategy = weave::strategy_named("priority");
  return options;
}

inline std::vector<engine::Rule> load_rules(RuleSet set) {
  const engine::Schema& schema = *stc::StcSchema::get().schema;
  const std::filesystem::path dir = weave::default_rules_dir();
  if (set == RuleSet::shipped) return engine::load_rule_dir(dir, schema);
  std::vector<engine::Rule> rules;
  for (const char* file : {"cross.rule", "seam.rule"}) {
    std::ifstream in(dir / file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("bench_weave: cannot read " + (dir / file).string());
    for (auto& r : engine::compile_rules(text.str(), (dir / file).string(), schema)) rules.push_back(std::move(r));
  }
  return rules;
}

/// CPU time of this (single-threaded) process: on a shared machine it leaves
/// out the time other processes held the core, which wall-clock time does not.
inline double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// CPU and wall-clock time since it was made.
struct Stopwatch {
  using Clock = std::chrono::steady_clock;
  double cpu_start = cpu_now();
  Clock::time_point wall_start = Clock::now();
  double cpu() const { return cpu_now() - cpu_start; }
  double wall() const { return std::chrono::duration<double>(Clock::now() - wall_start).count(); }
};

/// A field of /proc/self/status in bytes (VmHWM: peak RSS, VmRSS: current).
inline std::size_t status_bytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.starts_with(field + ":")) return std::stoull(line.substr(field.size() + 1)) * 1024;
  return 0;
}

/// What one run of one size and rule set measured.
struct RunFigures {
  int n = 0;
  std::size_t hexes = 0, steps = 0, match_attempts = 0, candidates = 0;
  std::size_t id_bound = 0, slot_bound = 0;  ///< the graph after the weave, tombstones included
  bool closed = false, valid = false;
  double build_s = 0, weave_s = 0, primal_s = 0, total_s = 0;  ///< CPU time
  double wall_weave_s = 0, wall_total_s = 0;
  std::size_t base_rss = 0, weave_peak_rss = 0, peak_rss = 0;  ///< VmHWM, bytes

  std::string serialize() const {
    return fmt::format("{} {} {} {} {} {} {} {} {} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {} {} {}", n, hexes, steps,
                       match_attempts, candidates, id_bound, slot_bound, int(closed), int(valid), build_s, weave_s,
                       primal_s, total_s, wall_weave_s, wall_total_s, base_rss, weave_peak_rss, peak_rss);
  }
  static RunFigures parse(const std::string& line) {
    RunFigures f;
    int closed = 0, valid = 0;
    std::istringstream in(line);
    in >> f.n >> f.hexes >> f.steps >> f.match_attempts >> f.candidates >> f.id_bound >> f.slot_bound >> closed >>
        valid >> f.build_s >> f.weave_s >> f.primal_s >> f.total_s >> f.wall_weave_s >> f.wall_total_s >> f.base_rss >>
        f.weave_peak_rss >> f.peak_rss;
    if (!in) throw std::runtime_error("bench_weave: cannot read a child's figures: '" + line + "'");
    f.closed = closed, f.valid = valid;
    return f;
  }
};

/// Growth of the peak RSS over the run's baseline, per hex.
inline double bytes_per_hex(const RunFigures& f, std::size_t peak) {
  return static_cast<double>(std::max(peak, f.base_rss) - f.base_rss) / static_cast<double>(f.hexes);
}

/// One weave of box n^3 with one rule set, stage by stage (the calls
/// mesh_surface makes).
inline RunFigures run_one(int n, RuleSet set) {
  RunFigures f;
  f.n = n;
  QuadSurface surface = gen::box(n, n, n);
  auto rules = load_rules(set);
  f.base_rss = status_bytes("VmHWM");

  Stopwatch total;
  stc::Stc stc = stc::build_from_surface(surface);
  f.build_s = total.cpu();

  Stopwatch weaving;
  weave::WeaveResult woven = weave::weave(stc, std::move(rules), weave_options(set));
  f.weave_s = weaving.cpu();
  f.wall_weave_s = weaving.wall();
  f.weave_peak_rss = status_bytes("VmHWM");
  f.id_bound = stc.graph().id_bound();
  f.slot_bound = stc.graph().slot_bound();

  Stopwatch primal;
  if (woven.closed) {
    std::vector<bool> on_boundary;
    HexMesh mesh = stc::to_hex_mesh(stc, &on_boundary);
    weave::smooth_interior(mesh, on_boundary);
    ValidityReport report = check_hex_mesh(mesh, &surface);
    f.valid = report.combinatorial_valid();
  }
  f.primal_s = primal.cpu();
  f.total_s = total.cpu();
  f.wall_total_s = total.wall();
  f.peak_rss = status_bytes("VmHWM");

  f.hexes = stc.hexes();
  f.steps = woven.steps;
  f.match_attempts = woven.counters.match_attempts;
  f.candidates = woven.counters.candidates;
  f.closed = woven.closed;
  return f;
}

/// The staged run must weave what pipeline::mesh_surface weaves: same steps,
/// hexes and verdict (a guard against the two drifting apart).
inline void check_against_pipeline(const RunFigures& staged, RuleSet set) {
  QuadSurface surface = gen::box(staged.n, staged.n, staged.n);
  pipeline::MeshingOptions options;
  options.weave = weave_options(set);
  pipeline::MeshingResult r = pipeline::mesh_surface(surface, load_rules(set), options);
  if (r.weave.steps != staged.steps || r.stc.hexes() != staged.hexes || r.combinatorially_valid() != staged.valid)
    throw std::logic_error(
        fmt::format("bench_weave: box {}^3, {} rules: mesh_surface made {} hexes in {} steps, the staged run "
                    "{} in {}: update run_one",
                    staged.n, set_title(set), r.stc.hexes(), r.weave.steps, staged.hexes, staged.steps));
}

}  // namespace loom::bench
