// bench_weave: weave speed and memory on boxes of 10^3 to 10^6 hexes, with the
// shipped rules and with cross and seam alone, side by side (issue #14 item 9).
//
// Weaves gen::box(n,n,n) under the default strategy, as pipeline::mesh_surface
// does, stage by stage so that each is timed on its own: initial STC, weave
// (rule applications), primal (construction, smoothing, validity check); see
// weave_run.hpp. Each run (one size, one rule set) happens in a fresh child
// process (this program re-run with --one N --set S): its peak RSS (VmHWM)
// belongs to that weave alone, so neither rule set's peak, nor the heap the
// allocator keeps after it, can mask or inflate the other's, whichever runs
// first. Within a repeat the two sets run back to back (cross+seam first), so
// both see the same load on a shared machine and their ratio is fair. Figures
// are medians over the repeats. See bench/README.md for the columns.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_options.hpp"
#include "bench/weave_run.hpp"

namespace {

using namespace loom;
using namespace loom::bench;

/// Runs `--one n --set s` in a fresh process and reads back its figures.
RunFigures run_in_child(const std::string& self, int n, RuleSet set) {
  std::string command = fmt::format("'{}' --one {} --set {}", self, n, set_token(set));
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

/// Medians over the repeats of one size and rule set; counts and memory from
/// the first run (the weave is deterministic, and so are they).
struct SetFigures {
  RunFigures first;
  double build_s, weave_s, primal_s, total_s, wall_weave_s, wall_total_s;
  int repeats;
  double hexes() const { return static_cast<double>(first.hexes); }
  double us_total() const { return 1e6 * total_s / hexes(); }  ///< whole weave, µs per hex
  double us_weave() const { return 1e6 * weave_s / hexes(); }
  double bytes_peak() const { return bytes_per_hex(first, first.peak_rss); }
  double attempts() const { return static_cast<double>(first.match_attempts) / hexes(); }
};

SetFigures summarize(const std::vector<RunFigures>& runs) {
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

/// One box side: [0] cross and seam alone, [1] the shipped rules (kRuleSets).
struct SizeFigures {
  SetFigures set[2];
  const SetFigures& two() const { return set[0]; }
  const SetFigures& shipped() const { return set[1]; }
  double ratio_total() const { return shipped().us_total() / two().us_total(); }
  double ratio_weave() const { return shipped().us_weave() / two().us_weave(); }
};

struct Options {
  std::size_t max_hexes = 1'000'000;
  int repeats = 3;
  std::string csv;
  bool in_process = false;  ///< no child processes (for profilers); memory not reported
  int one = 0;              ///< child mode: weave box one^3, print its figures
  std::string set = "shipped";
};

Options parse_options(int argc, char** argv) {
  Options o;
  CLI::App app{"Weave boxes of 10^3 to 10^6 hexes with the shipped rules and with cross and seam alone: "
               "hexes per second and bytes per hex against issue #14 item 9",
               "bench_weave"};
  app.add_option("--max-hexes", o.max_hexes, "largest box to weave (default 10^6)");
  app.add_option("--repeats", o.repeats, "runs per size and rule set (medians are printed)")
      ->check(CLI::PositiveNumber);
  app.add_option("--csv", o.csv, "also write the figures as CSV, one row per size and rule set");
  app.add_flag("--in-process", o.in_process, "no child processes (for profilers; memory not reported)");
  app.add_option("--one", o.one, "child mode: weave box N^3 and print its figures")->group("");
  app.add_option("--set", o.set, "child mode: the rule set, two or shipped")->group("");
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

std::string result_of(const RunFigures& f) {
  return f.closed ? (f.valid ? "valid" : "closed-invalid") : "not-closed";
}

void print_table(const std::vector<SizeFigures>& sizes, bool memory) {
  fmt::print("{:>4} {:>9} | {:^40} | {:^40} | {:^13} |\n", "", "", "cross+seam", "shipped", "shipped/two");
  std::string set_columns = fmt::format("{:>9} {:>7} {:>7} {:>6} {:>7}", "hex/s", "us/hex", "us/wv", "B/hex", "att/hex");
  fmt::print("{:>4} {:>9} | {} | {} | {:>6} {:>6} | {}\n", "n", "hexes", set_columns, set_columns, "whole", "weave",
             "result");
  for (const auto& s : sizes) {
    auto columns = [&](const SetFigures& f) {
      return fmt::format("{:>9.0f} {:>7.2f} {:>7.2f} {:>6} {:>7.1f}", 1e6 / f.us_total(), f.us_total(), f.us_weave(),
                         memory ? fmt::format("{:.0f}", f.bytes_peak()) : std::string("-"), f.attempts());
    };
    std::string result = result_of(s.two().first) == result_of(s.shipped().first)
                             ? result_of(s.shipped().first)
                             : fmt::format("{}/{}", result_of(s.two().first), result_of(s.shipped().first));
    if (s.two().first.hexes != s.shipped().first.hexes)
      result += fmt::format(" (cross+seam: {} hexes)", s.two().first.hexes);
    fmt::print("{:>4} {:>9} | {} | {} | {:>6.2f} {:>6.2f} | {}\n", s.shipped().first.n, s.shipped().first.hexes,
               columns(s.two()), columns(s.shipped()), s.ratio_total(), s.ratio_weave(), result);
  }
}

/// "met" or "NOT met, 3.1x short".
std::string verdict(bool met, double factor, const char* way) {
  return met ? std::string("met") : fmt::format("NOT met, {:.1f}x {}", factor, way);
}

/// Issue #14 item 9, for the whole weave of a box on one core (the stages
/// mesh_surface runs), with the shipped rules, which is what `loom weave` loads.
/// Each target is judged at the box that does worst, since it holds for every
/// size from 10^3 to 10^6; "flat" allows 10% (the noise of one run here).
void print_item9(const std::vector<SizeFigures>& sizes, bool memory) {
  constexpr double kFlat = 1.10, kHexesPerSecond = 250'000, kGoal = 1e6, kBytes = 500, kCost = 1.3;
  if (sizes.empty()) return;
  auto worst = [&](auto key) {
    return *std::max_element(sizes.begin(), sizes.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  };
  auto box = [](const SizeFigures& s) { return fmt::format("{}^3", s.shipped().first.n); };
  fmt::print("\nagainst item 9 (whole weave: build, weave, primal, smoothing, check; one core, CPU time; "
             "shipped rules, cross+seam alone in brackets):\n");
  const SizeFigures &small = sizes.front(), &large = sizes.back();
  if (sizes.size() > 1) {
    double flat = large.shipped().us_total() / small.shipped().us_total();
    fmt::print("  time per hex, {} vs {} hexes: {:.2f} [{:.2f}]; target 1.00 (flat, up to {:.2f}): {}\n",
               large.shipped().first.hexes, small.shipped().first.hexes, flat,
               large.two().us_total() / small.two().us_total(), kFlat, verdict(flat <= kFlat, flat, "slower"));
  }
  const SizeFigures& slowest = worst([](const SizeFigures& s) { return s.shipped().us_total(); });
  double rate = 1e6 / slowest.shipped().us_total();
  fmt::print("  hexes/s, slowest box ({}): {:.0f} [{:.0f}]; target >= {:.0f} (goal {:.0f}): {}{}\n", box(slowest),
             rate, 1e6 / slowest.two().us_total(), kHexesPerSecond, kGoal,
             verdict(rate >= kHexesPerSecond, kHexesPerSecond / rate, "short"),
             rate < kGoal ? fmt::format(", {:.0f}x short of the goal", kGoal / rate) : std::string());
  if (memory) {
    const SizeFigures& fattest = worst([](const SizeFigures& s) { return s.shipped().bytes_peak(); });
    double bytes = fattest.shipped().bytes_peak();
    fmt::print("  peak bytes/hex, worst box ({}): {:.0f} [{:.0f}], at {}: {:.0f} [{:.0f}]; target <= {:.0f}: {}\n",
               box(fattest), bytes, fattest.two().bytes_peak(), box(large), large.shipped().bytes_peak(),
               large.two().bytes_peak(), kBytes, verdict(bytes <= kBytes, bytes / kBytes, "over"));
  } else {
    fmt::print("  peak bytes/hex: not measured (--in-process)\n");
  }
  const SizeFigures& costliest = worst([](const SizeFigures& s) { return s.ratio_total(); });
  double cost = costliest.ratio_total();
  fmt::print("  shipped / cross+seam time per hex, worst box ({}): {:.2f} (weave alone {:.2f}); target <= {:.1f}: {}\n",
             box(costliest), cost, costliest.ratio_weave(), kCost, verdict(cost <= kCost, cost / kCost, "over"));
}

/// Under the table: each set's time per hex relative to the smallest box; at
/// the largest, each stage's share, the graph's size per hex and how busy the
/// machine was (shipped rules).
void print_notes(const std::vector<SizeFigures>& sizes) {
  if (sizes.empty()) return;
  for (int i = 0; i < 2; ++i) {
    std::string trend;
    for (const auto& s : sizes)
      trend += fmt::format("{}{:.2f}", trend.empty() ? "" : ", ", s.set[i].us_total() / sizes.front().set[i].us_total());
    if (sizes.size() > 1)
      fmt::print("whole-weave time per hex relative to the smallest box, {}: {} (1.00 = flat)\n", set_title(kRuleSets[i]),
                 trend);
  }
  const SetFigures& b = sizes.back().shipped();
  fmt::print("shipped rules at {} hexes: build {:.0f}%, weave {:.0f}%, primal+smoothing+check {:.0f}% of the total\n",
             b.first.hexes, 100 * b.build_s / b.total_s, 100 * b.weave_s / b.total_s, 100 * b.primal_s / b.total_s);
  fmt::print("graph after the weave at {} hexes: {:.1f} element ids and {:.1f} incidence slots per hex\n",
             b.first.hexes, static_cast<double>(b.first.id_bound) / b.hexes(),
             static_cast<double>(b.first.slot_bound) / b.hexes());
  fmt::print("wall-clock / CPU time of the weave at {} hexes: {:.2f} (above 1: the machine was busy)\n", b.first.hexes,
             b.wall_weave_s / b.weave_s);
}

void write_csv(const std::string& path, const std::vector<SizeFigures>& sizes, bool memory) {
  std::ofstream out(path);
  out << "rules,n,hexes,steps,match_attempts,candidates,id_bound,slot_bound,repeats,"
         "build_s,weave_s,primal_s,total_s,wall_weave_s,wall_total_s,"
         "hexes_per_s_weave,hexes_per_s_total,us_per_hex_weave,us_per_hex_total,"
         "bytes_per_hex_weave,bytes_per_hex_peak,closed,valid\n";
  for (const auto& size : sizes)
    for (int i = 0; i < 2; ++i) {
      const SetFigures& s = size.set[i];
      const RunFigures& f = s.first;
      auto per_hex = [&](std::size_t peak) {
        return memory ? fmt::format("{:.1f}", bytes_per_hex(f, peak)) : std::string();
      };
      out << fmt::format(
          "{},{},{},{},{},{},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.0f},{:.0f},{:.4f},{:.4f},{},{},{},{}"
          "\n",
          set_token(kRuleSets[i]), f.n, f.hexes, f.steps, f.match_attempts, f.candidates, f.id_bound, f.slot_bound,
          s.repeats, s.build_s, s.weave_s, s.primal_s, s.total_s, s.wall_weave_s, s.wall_total_s,
          s.hexes() / s.weave_s, s.hexes() / s.total_s, s.us_weave(), s.us_total(), per_hex(f.weave_peak_rss),
          per_hex(f.peak_rss), int(f.closed), int(f.valid));
    }
  if (!out) throw std::runtime_error("bench_weave: cannot write " + path);
}

int run(int argc, char** argv) {
  Options o = parse_options(argc, argv);
  if (o.one > 0) {
    std::puts(run_one(o.one, parse_set(o.set)).serialize().c_str());
    return 0;
  }
  std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<SizeFigures> sizes;
  for (int n : box_sides(o.max_hexes)) {
    std::vector<RunFigures> runs[2];
    for (int r = 0; r < o.repeats; ++r)
      for (int i = 0; i < 2; ++i)
        runs[i].push_back(o.in_process ? run_one(n, kRuleSets[i]) : run_in_child(self, n, kRuleSets[i]));
    SizeFigures size;
    for (int i = 0; i < 2; ++i) {
      if (sizes.empty() && !o.in_process) check_against_pipeline(runs[i].front(), kRuleSets[i]);
      size.set[i] = summarize(runs[i]);
    }
    sizes.push_back(size);
    fmt::print(stderr, "box {}^3: {} hexes, whole weave {:.3f} s cross+seam, {:.3f} s shipped (medians of {})\n", n,
               size.shipped().first.hexes, size.two().total_s, size.shipped().total_s, o.repeats);
  }
  fmt::print("bench_weave: box n x n x n, default strategy; CPU time, medians of {} run(s){}\n", o.repeats,
             o.in_process ? " in this process (no memory figures)" : ", each in a fresh process");
  fmt::print("hex/s, us/hex: whole weave (build, weave, primal, smoothing, check); us/wv: the weave alone; "
             "B/hex: peak RSS growth\n");
  print_table(sizes, !o.in_process);
  print_notes(sizes);
  print_item9(sizes, !o.in_process);
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
