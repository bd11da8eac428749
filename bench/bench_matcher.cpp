// bench_matcher: cost per match of the anchored matcher, against a hand-written
// loop over the same ports (the lower bound) and Boost's VF2 run from scratch.
//
// Hosts: STCs of n x n x n hex grids, ~10^3 to ~10^6 elements. Patterns:
//   pair    two hexes sharing a face (3 variables)
//   hex     a hex, its six faces and the three chords through them (10 variables)
// The anchored matcher and the hand-written loop enumerate every match; VF2's
// cost per match grows with |V|, so only its first K matches are timed. Every
// figure is a median over repeats. See bench/README.md for the columns.
#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_options.hpp"
#include "engine/matcher.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/vf2_reference.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"

namespace {

using namespace loom;
using engine::Id;
using engine::no_element;

constexpr const char* kPairRule = R"(
rule pair {
  match {
    f: face
    a, b: hex
    f.cell[0] == a
    f.cell[1] == b
  }
})";

constexpr const char* kHexRule = R"(
rule hex {
  match {
    h: hex
    f0, f1, f2, f3, f4, f5: face
    c01, c23, c45: chord
    h.face[0] == f0
    h.face[1] == f1
    h.face[2] == f2
    h.face[3] == f3
    h.face[4] == f4
    h.face[5] == f5
    f0.chord[0] == c01
    f1.chord[0] == c01
    f2.chord[0] == c23
    f3.chord[0] == c23
    f4.chord[0] == c45
    f5.chord[0] == c45
  }
})";

/// CPU time of this (single-threaded) process: on a shared machine it leaves
/// out the time other processes held the core, which wall-clock time does not.
double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double seconds_since(double start) { return cpu_now() - start; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// Defeats dead-code elimination of the loops being timed.
volatile std::uint64_t g_sink = 0;

/// An enumeration: returns the number of matches it found.
using Enumeration = std::function<std::size_t()>;

struct Timing {
  std::size_t matches = 0;
  double ns_per_match = 0;
};

/// Median ns/match over `repeats` timed batches; small graphs run the
/// enumeration several times per batch so that a batch lasts >= ~20 ms.
Timing time_enumeration(const Enumeration& enumerate, int repeats) {
  auto start = cpu_now();
  std::size_t matches = enumerate();
  double once = std::max(seconds_since(start), 1e-7);
  int per_batch = static_cast<int>(std::clamp(0.02 / once, 1.0, 10000.0));
  std::vector<double> ns;
  for (int r = 0; r < repeats; ++r) {
    auto batch = cpu_now();
    for (int i = 0; i < per_batch; ++i) enumerate();
    ns.push_back(1e9 * seconds_since(batch) / (static_cast<double>(per_batch) * static_cast<double>(matches)));
  }
  return {matches, median(ns)};
}

Enumeration anchored(const engine::Graph& g, const engine::Rule& rule) {
  return [&g, &rule] {
    engine::Matcher matcher(g);
    std::size_t count = 0;
    std::uint64_t sum = 0;
    matcher.each(rule, [&](const engine::Match& m) {
      ++count;
      sum += m.elements.back();
      return true;
    });
    g_sink = g_sink + sum;
    return count;
  };
}

/// The pair pattern by hand: every face with a hex on each side.
Enumeration pair_by_hand(const stc::Stc& stc) {
  return [&stc] {
    const engine::Graph& g = stc.graph();
    const auto& ids = stc.ids();
    std::size_t count = 0;
    std::uint64_t sum = 0;
    for (Id f : g.members(ids.face)) {
      Id a = g.at(f, ids.face_cell, 0), b = g.at(f, ids.face_cell, 1);
      if (a == no_element || b == no_element || a == b) continue;
      ++count;
      sum += b;
    }
    g_sink = g_sink + sum;
    return count;
  };
}

/// The hex pattern by hand: six distinct faces, opposite ones on one chord,
/// three distinct chords.
Enumeration hex_by_hand(const stc::Stc& stc) {
  return [&stc] {
    const engine::Graph& g = stc.graph();
    const auto& ids = stc.ids();
    std::size_t count = 0;
    std::uint64_t sum = 0;
    for (Id h : g.members(ids.hex)) {
      std::array<Id, 6> face, chord;
      bool ok = true;
      for (unsigned i = 0; i < 6 && ok; ++i) {
        face[i] = g.at(h, ids.hex_face, i);
        ok = face[i] != no_element && (chord[i] = g.at(face[i], ids.face_chord)) != no_element;
      }
      if (!ok || chord[0] != chord[1] || chord[2] != chord[3] || chord[4] != chord[5]) continue;
      if (chord[0] == chord[2] || chord[0] == chord[4] || chord[2] == chord[4]) continue;
      std::array<Id, 6> sorted = face;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) continue;
      ++count;
      sum += chord[4];
    }
    g_sink = g_sink + sum;
    return count;
  };
}

struct Vf2Timing {
  std::size_t matches = 0;  ///< found (K, or fewer if the graph has fewer)
  double seconds = 0;       ///< median time to find them
  double us_per_match = 0;
};

/// VF2 from scratch, stopped after `k` matches; median of up to `repeats`
/// runs (a single run when one takes more than 2 s).
Vf2Timing time_vf2(const engine::Graph& g, const engine::Rule& rule, std::size_t k, int repeats) {
  std::vector<double> seconds;
  std::size_t found = 0;
  for (int r = 0; r < repeats; ++r) {
    found = 0;
    auto start = cpu_now();
    engine::vf2_matches(g, rule, [&](const std::vector<Id>&) { return ++found < k; });
    seconds.push_back(seconds_since(start));
    if (seconds.back() > 2.0) break;
  }
  double s = median(seconds);
  return {found, s, found ? 1e6 * s / static_cast<double>(found) : 0};
}

/// Graphs this small also get a complete VF2 enumeration: it checks the match
/// count and whether the first K matches cost what an average match costs.
constexpr std::size_t kVf2CompleteUpTo = 10'000;

std::string vf2_complete_note(const engine::Graph& g, const engine::Rule& rule, std::size_t expected, int n,
                              const std::string& name) {
  std::size_t found = 0;
  auto start = cpu_now();
  engine::vf2_matches(g, rule, [&](const std::vector<Id>&) { return ++found, true; });
  double s = seconds_since(start);
  if (found != expected)
    throw std::logic_error(
        fmt::format("bench_matcher: {} at n={}: VF2 found {}, the anchored matcher {}", name, n, found, expected));
  return fmt::format("VF2 complete, {} n={}: {} matches in {:.3f} s, {:.2f} us/match", name, n, found, s,
                     1e6 * s / static_cast<double>(found));
}

struct Options {
  std::size_t max_elements = 1'100'000;
  std::size_t vf2_k = 50;
  double vf2_budget_s = 20;
  int repeats = 5;
  std::string csv;
};

Options parse_options(int argc, char** argv) {
  Options o;
  CLI::App app{"Cost per match: anchored matcher, hand-written loop, VF2 from scratch", "bench_matcher"};
  app.add_option("--max-elements", o.max_elements, "largest STC to measure (elements)");
  app.add_option("--vf2-k", o.vf2_k, "VF2: time only its first K matches")->check(CLI::PositiveNumber);
  app.add_option("--vf2-budget", o.vf2_budget_s, "VF2: skip larger graphs once K matches take longer (seconds)");
  app.add_option("--repeats", o.repeats, "repeats (medians are printed)")->check(CLI::PositiveNumber);
  app.add_option("--csv", o.csv, "also write the table as CSV");
  loom::bench::parse_or_exit(app, argc, argv);
  return o;
}

/// Elements of the STC of an n^3 grid: hexes, faces, edges, nodes, sheets, chords.
std::size_t grid_elements(std::size_t n) {
  return n * n * n + 3 * n * n * (n + 1) + 3 * n * (n + 1) * (n + 1) + (n + 1) * (n + 1) * (n + 1) + 3 * n + 3 * n * n;
}

struct Row {
  std::string pattern;
  int n = 0;
  std::size_t elements = 0, matches = 0;
  double anchored_ns = 0, hand_ns = 0;
  Vf2Timing vf2;
  bool vf2_run = false;
};

void print_row(const Row& r) {
  std::string vf2 = r.vf2_run ? fmt::format("{:>10.2f} {:>9.0f} {:>9.2f}", r.vf2.us_per_match,
                                            1e3 * r.vf2.us_per_match / r.anchored_ns, r.vf2.seconds)
                              : fmt::format("{:>10} {:>9} {:>9}", "skipped", "-", "-");
  fmt::print("{:<5} {:>3} {:>9} {:>9} {:>11.1f} {:>8.1f} {} {:>9.2f}\n", r.pattern, r.n, r.elements, r.matches,
             r.anchored_ns, r.hand_ns, vf2, r.anchored_ns / r.hand_ns);
}

void write_csv(const std::string& path, const std::vector<Row>& rows, std::size_t k) {
  std::ofstream out(path);
  out << "pattern,n,elements,matches,anchored_ns_per_match,hand_ns_per_match,vf2_k,vf2_found,vf2_seconds,"
         "vf2_us_per_match,vf2_over_anchored,anchored_over_hand\n";
  for (const Row& r : rows) {
    out << fmt::format("{},{},{},{},{:.3f},{:.3f},{},", r.pattern, r.n, r.elements, r.matches, r.anchored_ns, r.hand_ns,
                       k);
    if (r.vf2_run)
      out << fmt::format("{},{:.6f},{:.3f},{:.1f},", r.vf2.matches, r.vf2.seconds, r.vf2.us_per_match,
                         1e3 * r.vf2.us_per_match / r.anchored_ns);
    else
      out << ",,,,";
    out << fmt::format("{:.3f}\n", r.anchored_ns / r.hand_ns);
  }
  if (!out) throw std::runtime_error("bench_matcher: cannot write " + path);
}

int run(int argc, char** argv) {
  Options o = parse_options(argc, argv);
  const auto& schema = *stc::StcSchema::get().schema;
  struct Pattern {
    std::string name;
    engine::Rule rule;
    std::function<Enumeration(const stc::Stc&)> by_hand;
    bool vf2_on = true;  ///< false once VF2 went over budget on a smaller graph
  };
  std::vector<Pattern> patterns;
  patterns.push_back({"pair", engine::compile_rules(kPairRule, "pair.rule", schema).at(0), pair_by_hand});
  patterns.push_back({"hex", engine::compile_rules(kHexRule, "hex.rule", schema).at(0), hex_by_hand});

  fmt::print(
      "bench_matcher: STC of an n^3 hex grid; CPU ns or us per match, medians of {} repeats; VF2: first {} matches\n",
      o.repeats, o.vf2_k);
  fmt::print("{:<5} {:>3} {:>9} {:>9} {:>11} {:>8} {:>10} {:>9} {:>9} {:>9}\n", "rule", "n", "elements", "matches",
             "anchor_ns", "hand_ns", "vf2_us", "vf2/anch", "vf2_s", "anch/hand");
  std::vector<Row> rows;
  std::vector<std::string> notes;
  for (int n : {5, 10, 22, 50}) {
    if (grid_elements(static_cast<std::size_t>(n)) > o.max_elements) break;
    stc::Stc stc = stc::build_from_hex_mesh(gen::hexgrid(n, n, n));
    const engine::Graph& g = stc.graph();
    for (Pattern& p : patterns) {
      Row r;
      r.pattern = p.name, r.n = n, r.elements = g.size();
      Timing a = time_enumeration(anchored(g, p.rule), o.repeats);
      Timing h = time_enumeration(p.by_hand(stc), o.repeats);
      if (a.matches != h.matches)
        throw std::logic_error(fmt::format("bench_matcher: {} at n={}: anchored found {}, hand-written {}", p.name, n,
                                           a.matches, h.matches));
      r.matches = a.matches, r.anchored_ns = a.ns_per_match, r.hand_ns = h.ns_per_match;
      if (g.size() <= kVf2CompleteUpTo) notes.push_back(vf2_complete_note(g, p.rule, r.matches, n, p.name));
      if (p.vf2_on) {
        r.vf2 = time_vf2(g, p.rule, o.vf2_k, std::min(o.repeats, 3));
        r.vf2_run = true;
        if (r.vf2.seconds > o.vf2_budget_s) p.vf2_on = false;
      }
      print_row(r);
      std::fflush(stdout);
      rows.push_back(r);
    }
  }
  for (const std::string& note : notes) fmt::print("{}\n", note);
  for (const Pattern& p : patterns) {
    auto skipped =
        std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.pattern == p.name && !r.vf2_run; });
    if (skipped != rows.end())
      fmt::print("VF2 on '{}' skipped from n={}: {} matches took over {} s on the size before\n", p.name, skipped->n,
                 o.vf2_k, o.vf2_budget_s);
  }
  if (!o.csv.empty()) write_csv(o.csv, rows, o.vf2_k);
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
