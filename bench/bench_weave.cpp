// bench_weave: weave speed and memory on boxes of 10^3 to 10^6 hexes.
//
// Weaves gen::box(n,n,n) with the shipped rules and the default strategy, as
// pipeline::mesh_surface does, stage by stage so that each is timed on its own:
// initial STC, weave (rule applications), primal (construction, smoothing,
// validity check). Each run happens in a fresh child process (this program
// re-run with --one N), so its peak RSS (VmHWM) belongs to that size alone and
// no run inherits the heap of another. Figures are medians over the repeats.
// See bench/README.md for the columns.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"
#include "bench/bench_options.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace {

using namespace loom;
using Clock = std::chrono::steady_clock;

/// CPU time of this (single-threaded) process: on a shared machine it leaves
/// out the time other processes held the core, which wall-clock time does not.
double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// CPU and wall-clock time since it was made.
struct Stopwatch {
  double cpu_start = cpu_now();
  Clock::time_point wall_start = Clock::now();
  double cpu() const { return cpu_now() - cpu_start; }
  double wall() const { return std::chrono::duration<double>(Clock::now() - wall_start).count(); }
};

/// A field of /proc/self/status in bytes (VmHWM: peak RSS, VmRSS: current).
std::size_t status_bytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.starts_with(field + ":")) return std::stoull(line.substr(field.size() + 1)) * 1024;
  return 0;
}

/// What one run of one size measured.
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

/// One weave of box n^3, stage by stage (the calls mesh_surface makes).
RunFigures run_one(int n) {
  RunFigures f;
  f.n = n;
  QuadSurface surface = gen::box(n, n, n);
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  f.base_rss = status_bytes("VmHWM");

  Stopwatch total;
  stc::Stc stc = stc::build_from_surface(surface);
  f.build_s = total.cpu();

  Stopwatch weaving;
  weave::WeaveResult woven = weave::weave(stc, std::move(rules), {});
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
void check_against_pipeline(const RunFigures& staged) {
  QuadSurface surface = gen::box(staged.n, staged.n, staged.n);
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  pipeline::MeshingResult r = pipeline::mesh_surface(surface, std::move(rules), {});
  if (r.weave.steps != staged.steps || r.stc.hexes() != staged.hexes || r.combinatorially_valid() != staged.valid)
    throw std::logic_error(
        fmt::format("bench_weave: box {}^3: mesh_surface made {} hexes in {} steps, the staged run "
                    "{} in {}: update run_one",
                    staged.n, r.stc.hexes(), r.weave.steps, staged.hexes, staged.steps));
}

/// Runs `--one n` in a fresh process and reads back its figures.
RunFigures run_in_child(const std::string& self, int n) {
  std::string command = fmt::format("'{}' --one {}", self, n);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("bench_weave: cannot start " + command);
  std::string out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  if (pclose(pipe) != 0) throw std::runtime_error("bench_weave: child failed: " + command);
  return RunFigures::parse(out);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// Medians over the repeats of one size; counts and memory from the first run
/// (the weave is deterministic, and so are they).
struct SizeFigures {
  RunFigures first;
  double build_s, weave_s, primal_s, total_s, wall_weave_s, wall_total_s;
  int repeats;
};

SizeFigures summarize(const std::vector<RunFigures>& runs) {
  auto med = [&](double RunFigures::*field) {
    std::vector<double> v;
    for (const auto& r : runs) v.push_back(r.*field);
    return median(v);
  };
  return {runs.front(),
          med(&RunFigures::build_s),
          med(&RunFigures::weave_s),
          med(&RunFigures::primal_s),
          med(&RunFigures::total_s),
          med(&RunFigures::wall_weave_s),
          med(&RunFigures::wall_total_s),
          static_cast<int>(runs.size())};
}

struct Options {
  std::size_t max_hexes = 1'000'000;
  int repeats = 3;
  std::string csv;
  bool in_process = false;  ///< no child processes (for profilers); memory not reported
  int one = 0;              ///< child mode: weave box one^3, print its figures
};

Options parse_options(int argc, char** argv) {
  Options o;
  CLI::App app{"Weave boxes of 10^3 to 10^6 hexes: hexes per second and bytes per hex", "bench_weave"};
  app.add_option("--max-hexes", o.max_hexes, "largest box to weave");
  app.add_option("--repeats", o.repeats, "runs per size (medians are printed)")->check(CLI::PositiveNumber);
  app.add_option("--csv", o.csv, "also write the table as CSV");
  app.add_flag("--in-process", o.in_process, "no child processes (for profilers; memory not reported)");
  app.add_option("--one", o.one, "child mode: weave box N^3 and print its figures")->group("");
  loom::bench::parse_or_exit(app, argc, argv);
  return o;
}

/// Box sides: ~10^3, 10^4, 10^5, 10^6 hexes up to max_hexes, plus the largest
/// cube that fits when max_hexes lies between two of them (--max-hexes 8000: 10, 20).
std::vector<int> box_sides(std::size_t max_hexes) {
  std::vector<int> sides;
  for (int n : {10, 22, 46, 100})
    if (static_cast<std::size_t>(n) * n * n <= max_hexes) sides.push_back(n);
  int largest = static_cast<int>(std::cbrt(static_cast<double>(max_hexes)) + 1e-9);
  if (largest >= 1 && (sides.empty() || largest > sides.back()) && largest <= 100) sides.push_back(largest);
  return sides;
}

/// Growth of the peak RSS over the run's baseline, per hex.
double bytes_per_hex(const RunFigures& f, std::size_t peak) {
  return static_cast<double>(std::max(peak, f.base_rss) - f.base_rss) / static_cast<double>(f.hexes);
}

void print_table(const std::vector<SizeFigures>& sizes, bool memory) {
  fmt::print("{:>4} {:>9} {:>9} {:>8} {:>8} {:>8} {:>8} {:>10} {:>10} {:>9} {:>10} {:>8} {:>8} {:>9} {}\n", "n",
             "hexes", "steps", "build_s", "weave_s", "primal_s", "total_s", "hex/s_wv", "hex/s_e2e", "us/hex_wv",
             "us/hex_e2e", "B/hex_wv", "B/hex_pk", "att/hex", "result");
  for (const auto& s : sizes) {
    const RunFigures& f = s.first;
    double hexes = static_cast<double>(f.hexes);
    auto per_hex = [&](std::size_t peak) {
      return memory ? fmt::format("{:.0f}", bytes_per_hex(f, peak)) : std::string("-");
    };
    fmt::print(
        "{:>4} {:>9} {:>9} {:>8.3f} {:>8.3f} {:>8.3f} {:>8.3f} {:>10.0f} {:>10.0f} {:>9.2f} {:>10.2f} {:>8} {:>8} "
        "{:>9.1f} {}\n",
        f.n, f.hexes, f.steps, s.build_s, s.weave_s, s.primal_s, s.total_s, hexes / s.weave_s, hexes / s.total_s,
        1e6 * s.weave_s / hexes, 1e6 * s.total_s / hexes, per_hex(f.weave_peak_rss), per_hex(f.peak_rss),
        static_cast<double>(f.match_attempts) / hexes,
        f.closed ? (f.valid ? "valid" : "closed, invalid") : "not closed");
  }
}

void write_csv(const std::string& path, const std::vector<SizeFigures>& sizes, bool memory) {
  std::ofstream out(path);
  out << "n,hexes,steps,match_attempts,candidates,id_bound,slot_bound,repeats,"
         "build_s,weave_s,primal_s,total_s,wall_weave_s,wall_total_s,"
         "hexes_per_s_weave,hexes_per_s_total,us_per_hex_weave,us_per_hex_total,"
         "bytes_per_hex_weave,bytes_per_hex_peak,closed,valid\n";
  for (const auto& s : sizes) {
    const RunFigures& f = s.first;
    double hexes = static_cast<double>(f.hexes);
    auto per_hex = [&](std::size_t peak) {
      return memory ? fmt::format("{:.1f}", bytes_per_hex(f, peak)) : std::string();
    };
    out << fmt::format(
        "{},{},{},{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.0f},{:.0f},{:.4f},{:.4f},{},{},{},{}\n",
        f.n, f.hexes, f.steps, f.match_attempts, f.candidates, f.id_bound, f.slot_bound, s.repeats, s.build_s,
        s.weave_s, s.primal_s, s.total_s, s.wall_weave_s, s.wall_total_s, hexes / s.weave_s, hexes / s.total_s,
        1e6 * s.weave_s / hexes, 1e6 * s.total_s / hexes, per_hex(f.weave_peak_rss), per_hex(f.peak_rss), int(f.closed),
        int(f.valid));
  }
  if (!out) throw std::runtime_error("bench_weave: cannot write " + path);
}

/// Under the table: the weave's time per hex relative to the smallest box
/// (1.00 everywhere is linear time); at the largest, each stage's share, the
/// graph's size per hex and how busy the machine was.
void print_notes(const std::vector<SizeFigures>& sizes) {
  if (sizes.empty()) return;
  auto us = [](const SizeFigures& s) { return 1e6 * s.weave_s / static_cast<double>(s.first.hexes); };
  std::string trend;
  for (const auto& s : sizes) trend += fmt::format("{}{:.2f}", trend.empty() ? "" : ", ", us(s) / us(sizes.front()));
  if (sizes.size() > 1) fmt::print("weave time per hex relative to the smallest box: {} (1.00 = flat)\n", trend);
  const auto& b = sizes.back();
  fmt::print("at {} hexes: build {:.0f}%, weave {:.0f}%, primal+smoothing+check {:.0f}% of the total\n", b.first.hexes,
             100 * b.build_s / b.total_s, 100 * b.weave_s / b.total_s, 100 * b.primal_s / b.total_s);
  fmt::print("graph after the weave at {} hexes: {:.1f} element ids and {:.1f} incidence slots per hex\n",
             b.first.hexes, static_cast<double>(b.first.id_bound) / static_cast<double>(b.first.hexes),
             static_cast<double>(b.first.slot_bound) / static_cast<double>(b.first.hexes));
  fmt::print("wall-clock / CPU time of the weave at {} hexes: {:.2f} (above 1: the machine was busy)\n", b.first.hexes,
             b.wall_weave_s / b.weave_s);
}

int run(int argc, char** argv) {
  Options o = parse_options(argc, argv);
  if (o.one > 0) {
    std::puts(run_one(o.one).serialize().c_str());
    return 0;
  }
  std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<SizeFigures> sizes;
  for (int n : box_sides(o.max_hexes)) {
    std::vector<RunFigures> runs;
    for (int r = 0; r < o.repeats; ++r) runs.push_back(o.in_process ? run_one(n) : run_in_child(self, n));
    if (sizes.empty() && !o.in_process) check_against_pipeline(runs.front());
    sizes.push_back(summarize(runs));
    fmt::print(stderr, "box {}^3: {} hexes, weave {:.3f} s (median of {})\n", n, runs.front().hexes,
               sizes.back().weave_s, runs.size());
  }
  fmt::print("bench_weave: box n x n x n, shipped rules, default strategy; CPU time, medians of {} run(s){}\n",
             o.repeats, o.in_process ? " in this process (no memory figures)" : ", each in a fresh process");
  print_table(sizes, !o.in_process);
  print_notes(sizes);
  if (!o.csv.empty()) write_csv(o.csv, sizes, !o.in_process);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
