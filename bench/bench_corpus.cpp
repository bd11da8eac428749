// bench_corpus: weaves a corpus of surfaces (the generators, and the surface
// files of a folder) under several strategies and rule orderings, and writes
// one row per (input, configuration) as CSV and Markdown, with a summary per
// configuration (closure rate over the random quadrangulations by size band).
//
//   bench_corpus [--dir DIR] [--rules DIR]... [--randquad-max F] [--max-steps N]
//                [--timeout S] [--only TEXT,...] [--shard K/N]
//                [--csv FILE] [--md FILE] [--md-full] [--list]
//   bench_corpus --merge A.csv B.csv ... [--csv FILE] [--md FILE] [--md-full]
//
// Every rule set given by --rules (default: the shipped rules) runs under
// every configuration; with several, the report lists the runs whose outcome
// changed between them. Rows are numbered over the whole corpus (inputs in
// corpus order, then rule sets, then configurations); shard K of N runs the rows whose number is
// K-1 modulo N, so shards are disjoint, cover the corpus, and merge back into
// exactly the table a single run writes. Every mesh a run produces is checked
// again here (check_hex_mesh against the surface, and every scaled Jacobian
// when the run says valid): the `recheck` column says `MISMATCH` if the
// pipeline's verdict is more favourable than the checker's. See bench/README.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"
#include "bench/bench_options.hpp"
#include "bench/corpus_table.hpp"
#include "src/check/validity.hpp"
#include "src/fill/fill.hpp"
#include "src/gen/generators.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/stc/stc.hpp"
#include "src/util/error.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace {

using namespace loom;
using namespace loom::bench;
namespace fs = std::filesystem;

// ---------------------------------------------------------------- corpus

struct Input {
  std::string name;    ///< e.g. "box 2 2 2", "randquad 40 s3", "file part.obj"
  std::string family;  ///< generator name, or "file"
  int faces = 0;       ///< F of randquad (0 otherwise)
  std::function<QuadSurface()> make;
};

struct Config {
  std::string name;
  /// "": the rule set's own strategy (weave::strategy_of); "random": the same
  /// with random picks; "no-backtracking": the same without backtracking
  /// (for the shipped rules, strategies/no_backtracking.strategy); else a spec
  /// for Strategy::parse.
  std::string strategy;
  std::uint64_t seed = 0;
  std::size_t attempts = 1;  ///< MeshingOptions::attempts (random restarts)
};

const std::vector<Config>& configs() {
  static const std::vector<Config> list = {
      {"priority", "", 0},
      {"priority-nobt", "no-backtracking", 0},
      {"random-1", "random", 1},
      {"random-2", "random", 2},
      {"seq-seam-cross", "sequence:seam,cross", 0},
      {"seq-cross-seam", "sequence:cross,seam", 0},
      {"portfolio-16", "", 0, 16},
  };
  return list;
}

std::vector<Input> corpus(int randquad_max, const std::string& dir) {
  std::vector<Input> in;
  auto add = [&](std::string name, std::string family, std::function<QuadSurface()> make, int faces = 0) {
    in.push_back({std::move(name), std::move(family), faces, std::move(make)});
  };
  add("box 2 2 2", "box", [] { return gen::box(2, 2, 2); });
  add("box 3 4 5", "box", [] { return gen::box(3, 4, 5); });
  for (int n : {2, 3, 4}) add(fmt::format("lshape {}", n), "lshape", [n] { return gen::lshape(n); });
  add("cylinder 4 6", "cylinder", [] { return gen::cylinder(4, 6); });
  for (int n : {3, 6}) add(fmt::format("cubesphere {}", n), "cubesphere", [n] { return gen::cubesphere(n); });
  add("tet4", "tet4", [] { return gen::tet4(); });
  add("schneiders", "schneiders", [] { return gen::schneiders(); });
  add("spindle", "spindle", [] { return gen::spindle(); });
  for (int k : {1, 2}) add(fmt::format("bosses {}", k), "bosses", [k] { return gen::bosses(k); });
  add("bosses-free 1", "bosses-free", [] { return gen::bosses_free(1); });
  for (int f = 6; f <= randquad_max; f += 2)
    for (int s = 0; s < 10; ++s)
      add(fmt::format("randquad {} s{}", f, s), "randquad", [f, s] { return gen::randquad(f, std::uint64_t(s)); }, f);
  if (!dir.empty()) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
      std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".obj" || ext == ".off" || ext == ".vtk" || ext == ".vtu" || ext == ".msh"))
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& p : files)
      add("file " + p.filename().string(), "file", [p] {
        QuadSurface s = read_surface(p);
        validate_surface(s, p.string());
        return s;
      });
  }
  return in;
}

// ---------------------------------------------------------------- one run

/// The constructive fill of one input, checked independently (criteria 1-6;
/// its nodes are not placed here). It does not depend on the configuration:
/// computed once an input, for the rows whose weave gave no valid mesh.
struct FillOutcome {
  bool valid = false;
  std::size_t hexes = 0;
  double seconds = 0;
  std::string failure;  ///< the criterion it fails, or why it could not run
};

FillOutcome fill_once(const QuadSurface& surface, const std::vector<fill::Cap>& caps) {
  FillOutcome out;
  auto start = std::chrono::steady_clock::now();
  try {
    fill::FilledMesh f = fill::fill_constructively(surface, caps);
    ValidityReport check = check_hex_mesh(f.mesh, &surface);
    out.valid = check.combinatorial_valid();
    out.hexes = f.mesh.hexes.size();
    if (const CriterionResult* c = check.first_failure(); c && !out.valid)
      out.failure = fmt::format("the fill fails criterion {}", c->number);
  } catch (const InputError& e) {
    out.failure = e.what();
  } catch (const std::exception& e) {  // a bug in the fill: the row says so, the corpus goes on
    out.failure = std::string("error: ") + e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void record_fill(Row& r, const FillOutcome& f) {
  r.filled = f.valid;
  r.fill_hexes = f.hexes;
  r.fill_seconds = f.seconds;
  if (f.hexes && !f.valid)  // the fill must always give a valid mesh
    r.recheck = r.recheck.starts_with("MISMATCH") ? r.recheck + "; " + f.failure : "MISMATCH: " + f.failure;
  else if (!f.failure.empty())
    r.note += "; fill: " + f.failure;
}

/// A directory of rules and the name rows give it.
struct RuleSet {
  std::string name;
  std::vector<engine::Rule> rules;
  engine::Strategy strategy;  ///< its own (weave::strategy_of)
  fs::path dir;               ///< where its closure database is (the template rule's)
};

engine::Strategy strategy_for(const Config& config, const RuleSet& set) {
  engine::Strategy s;
  if (config.strategy.empty()) s = set.strategy;
  else if (config.strategy == "random") s = set.strategy.with_random_picks();
  else if (config.strategy == "no-backtracking") s = set.strategy.without_backtracking();
  else s = weave::strategy_named(config.strategy);
  s.seed = config.seed;
  return s;
}

/// Named by their directories; by their paths as given when two share a name.
std::vector<RuleSet> load_rule_sets(const std::vector<std::string>& dirs) {
  std::vector<std::string> paths = dirs;
  if (paths.empty()) paths.push_back(weave::default_rules_dir().string());
  std::vector<std::string> names;
  for (const auto& p : paths) {
    fs::path path = fs::path(p).lexically_normal();
    if (path.filename().empty()) path = path.parent_path();  // "rules/"
    names.push_back(path.filename().string());
  }
  std::vector<RuleSet> sets;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    bool shared = std::count(names.begin(), names.end(), names[i]) > 1;
    sets.push_back({shared ? paths[i] : names[i], engine::load_rule_dir(paths[i], *stc::StcSchema::get().schema),
                    weave::strategy_of(paths[i]), paths[i]});
  }
  return sets;
}

Row run_one(const Input& input, const QuadSurface& surface, const Config& config, const RuleSet& set,
            bool several_sets, std::size_t max_steps, double timeout) {
  const std::vector<engine::Rule>& rules = set.rules;
  Row r;
  r.input = input.name;
  r.family = input.family;
  r.faces = input.faces;
  r.quads = surface.quads.size();
  r.config = several_sets ? set.name + ":" + config.name : config.name;
  r.rules = set.name;
  pipeline::MeshingOptions options;
  options.database = pipeline::default_meshing_options(set.dir).database;
  options.weave.strategy = strategy_for(config, set);
  options.attempts = config.attempts;
  options.weave.max_steps = max_steps;
  // A wall-clock guard: a run that explodes is stopped (the row says so).
  struct Timeout {
    std::size_t steps;
  };
  auto start = std::chrono::steady_clock::now();
  std::size_t seen = 0;
  // What the attempts a timeout cuts short left behind, so that the row
  // still says what stops the input: the attempt with the fewest whiskers.
  std::size_t attempt = 1, open_attempts = 0, fewest_attempt = 0, fewest = 0;
  std::string fewest_left;
  options.before_attempt = [&](std::size_t next, const engine::Strategy&, const weave::WeaveResult& previous) {
    if (!previous.closed && (!fewest_attempt || previous.whiskers_left < fewest)) {
      fewest_attempt = attempt, fewest = previous.whiskers_left;
      fewest_left = previous.left;
    }
    open_attempts += !previous.closed;
    attempt = next;
  };
  if (timeout > 0)
    options.weave.after_step = [&](const engine::Application&, const stc::Stc&) {
      if (++seen % 16 == 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout)
        throw Timeout{seen};
    };
  try {
    pipeline::MeshingResult m = pipeline::mesh_surface(surface, rules, options);
    r.seconds = m.seconds;
    r.closed = m.weave.closed;
    r.steps = m.weave.steps;
    r.backtracks = m.weave.backtracks;
    r.whiskers_left = m.weave.whiskers_left;
    r.hexes = m.stc.hexes() + m.boundary_layer.hexes_added;
    // Degeneracies met: through-3-cells left by seam_through, doublets
    // pillowed; pillows: every pillow sheet inserted (pillow_* rules, and
    // the boundary layer when the pipeline pillowed it).
    std::size_t degeneracies = 0, pillows = 0;
    for (const auto& [name, n] : m.weave.applications) {
      if (name == "seam_through" || name == "pillow_doublet") degeneracies += n;
      if (name.rfind("pillow_", 0) == 0 && name != "pillow_face") pillows += n;
    }
    r.degeneracies = std::to_string(degeneracies);
    if (m.boundary_layer.hexes_added > 0) ++pillows;
    r.pillows = std::to_string(pillows);
    for (const auto& [name, n] : m.weave.applications) {
      if (name == "cross") r.cross = n;
      else if (name == "seam") r.seam = n;
      else r.other_rules += fmt::format("{}{}={}", r.other_rules.empty() ? "" : ";", name, n);
    }
    r.comb_valid = m.combinatorially_valid();
    r.valid = r.comb_valid && m.check->valid();
    if (m.check) {
      r.min_sj = m.check->quality.min_scaled_jacobian;
      r.mean_sj = m.check->quality.mean_scaled_jacobian;
      r.below_0_2 = m.check->quality.below_0_2;
    }
    if (!r.closed) r.note = m.weave.left;
    else if (!m.failure.empty()) r.note = "primal: " + m.failure;
    else if (m.check && !m.check->combinatorial_valid()) {
      const CriterionResult* c = m.check->first_failure();
      r.note = c ? fmt::format("criterion {} ({}): {}", c->number, c->name, c->detail) : "invalid";
    } else if (m.check && !m.check->valid())
      r.note = fmt::format("{} hexes with scaled Jacobian <= 0", m.check->quality.below_zero);
    else if (m.boundary_layer.hexes_added > 0)
      r.note = fmt::format("boundary layer pillowed (+{} hexes)", m.boundary_layer.hexes_added);
    // An independent second opinion on every mesh: the pipeline must never
    // report success on a mesh the checker rejects.
    if (m.mesh) {
      ValidityReport again = check_hex_mesh(*m.mesh, &surface);
      std::string bad;
      if (r.comb_valid && !again.combinatorial_valid()) bad = "pipeline says criteria 1-6 hold, check disagrees";
      if (r.valid)
        for (std::size_t h = 0; h < m.mesh->hexes.size() && bad.empty(); ++h)
          if (!(scaled_jacobian(*m.mesh, h) > 0)) bad = fmt::format("pipeline says valid, hex {} has SJ <= 0", h);
      if (r.closed && r.comb_valid && r.hexes != m.mesh->hexes.size())
        bad = fmt::format("STC and boundary layer have {} hexes, mesh {}", r.hexes, m.mesh->hexes.size());
      r.recheck = bad.empty() ? "ok" : "MISMATCH: " + bad;
    }
  } catch (const Timeout& t) {
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.steps = t.steps;
    r.note = fmt::format("timeout: stopped after {:g} s and {} applications, in attempt {}", timeout, t.steps, attempt);
    if (attempt > 1)
      r.note += fmt::format("; of the {} before it, {} closed without passing criteria 1-6", attempt - 1,
                            attempt - 1 - open_attempts);
    if (fewest_attempt)
      r.note += fmt::format(", and attempt {} left the fewest: {}", fewest_attempt, fewest_left);
  } catch (const std::exception& e) {
    r.note = std::string("error: ") + e.what();
  }
  return r;
}

// ---------------------------------------------------------------- main

struct Options {
  std::string dir, csv, md;
  std::vector<std::string> rules;
  int randquad_max = 200;
  std::size_t max_steps = 0;
  double timeout = 2;
  std::vector<std::string> only;
  int shard_k = 1, shard_n = 1;
  bool md_full = false, list = false;
  std::vector<std::string> merge;
};

Options parse_options(int argc, char** argv) {
  Options o;
  std::string shard;
  CLI::App app{"Run the corpus under several strategies and rule orderings; write CSV and Markdown", "bench_corpus"};
  app.add_option("--dir", o.dir, "also run every surface file of this directory");
  app.add_option("--randquad-max", o.randquad_max, "largest randquad F in the corpus");
  app.add_option("--max-steps", o.max_steps, "rule applications per run at most (0: the library's limit)");
  app.add_option("--timeout", o.timeout, "wall-clock seconds per run at most");
  app.add_option("--rules", o.rules, "a directory of rules; repeat to compare rule sets (default: the shipped rules)");
  app.add_option("--only", o.only, "only inputs, configurations or rule sets whose name contains one of these")
      ->delimiter(',');
  app.add_option("--shard", shard, "run only shard K of N (rows by index modulo N), e.g. 3/16");
  app.add_option("--csv", o.csv, "write the table as CSV");
  app.add_option("--md", o.md, "write the summary as Markdown");
  app.add_flag("--md-full", o.md_full, "Markdown also lists every row");
  app.add_flag("--list", o.list, "list the runs without running them");
  app.add_option("--merge", o.merge, "merge shard CSVs instead of running");
  loom::bench::parse_or_exit(app, argc, argv);
  if (!shard.empty()) {
    auto slash = shard.find('/');
    if (slash == std::string::npos) throw std::invalid_argument("bench_corpus: --shard wants K/N, e.g. 3/16");
    o.shard_k = std::stoi(shard.substr(0, slash));
    o.shard_n = std::stoi(shard.substr(slash + 1));
    if (o.shard_n < 1 || o.shard_k < 1 || o.shard_k > o.shard_n)
      throw std::invalid_argument("bench_corpus: --shard K/N needs 1 <= K <= N");
  }
  return o;
}

int run(const Options& o) {
  if (!o.merge.empty()) {
    std::vector<Row> rows;
    std::map<std::size_t, std::string> seen;
    for (const auto& f : o.merge)
      for (auto& r : read_csv(f)) {
        if (auto it = seen.find(r.row); it != seen.end())
          throw std::runtime_error(fmt::format("bench_corpus: row {} is in both {} and {}", r.row, it->second, f));
        seen[r.row] = f;
        rows.push_back(std::move(r));
      }
    std::size_t expected = seen.empty() ? 0 : seen.rbegin()->first + 1;
    if (rows.size() != expected)
      std::cerr << fmt::format("bench_corpus: warning: {} rows merged, row numbers go up to {}: a shard is missing\n",
                               rows.size(), expected - 1);
    write_outputs(std::move(rows), o.csv, o.md, o.md_full);
    return 0;
  }

  auto inputs = corpus(o.randquad_max, o.dir);
  const auto& cfgs = configs();
  const auto sets = load_rule_sets(o.rules);
  const std::size_t per_input = sets.size() * cfgs.size();
  auto number = [&](std::size_t i, std::size_t s, std::size_t c) { return (i * sets.size() + s) * cfgs.size() + c; };
  auto selected = [&](std::size_t i, std::size_t s, std::size_t c) {
    bool named = o.only.empty();
    for (const auto& text : o.only)
      named = named || inputs[i].name.find(text) != std::string::npos || cfgs[c].name.find(text) != std::string::npos ||
              sets[s].name.find(text) != std::string::npos;
    return named && number(i, s, c) % std::size_t(o.shard_n) == std::size_t(o.shard_k - 1);
  };
  if (o.list) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      for (std::size_t s = 0; s < sets.size(); ++s)
        for (std::size_t c = 0; c < cfgs.size(); ++c)
          if (selected(i, s, c))
            std::cout << number(i, s, c) << ' ' << inputs[i].name << ' ' << sets[s].name << ' ' << cfgs[c].name << '\n';
    return 0;
  }
  const auto caps = fill::load_caps(fill::default_caps_dir());
  std::vector<Row> rows;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    std::vector<std::size_t> mine;  // s * cfgs.size() + c
    for (std::size_t s = 0; s < sets.size(); ++s)
      for (std::size_t c = 0; c < cfgs.size(); ++c)
        if (selected(i, s, c)) mine.push_back(s * cfgs.size() + c);
    if (mine.empty()) continue;
    std::optional<QuadSurface> surface;
    std::optional<FillOutcome> filled;
    std::string error;
    try {
      surface = inputs[i].make();
    } catch (const std::exception& e) {
      error = std::string("error: input: ") + e.what();
    }
    for (std::size_t k : mine) {
      const std::size_t s = k / cfgs.size(), c = k % cfgs.size();
      Row r;
      if (surface) {
        r = run_one(inputs[i], *surface, cfgs[c], sets[s], sets.size() > 1, o.max_steps, o.timeout);
        if (!r.comb_valid) {
          if (!filled) filled = fill_once(*surface, caps);
          record_fill(r, *filled);
        }
      } else {
        r.input = inputs[i].name, r.family = inputs[i].family, r.faces = inputs[i].faces;
        r.config = sets.size() > 1 ? sets[s].name + ":" + cfgs[c].name : cfgs[c].name;
        r.rules = sets[s].name;
        r.note = error;
      }
      r.row = i * per_input + k;
      std::cerr << fmt::format("[{}] {} / {}: {}{} {} hexes, {:.3f} s{}\n", r.row, r.input, r.config,
                               r.closed ? "closed" : "open", r.valid ? " valid" : r.comb_valid ? " comb-valid" : "",
                               r.hexes, r.seconds, r.recheck.starts_with("MISMATCH") ? "  ** " + r.recheck : "");
      rows.push_back(std::move(r));
    }
  }
  write_outputs(std::move(rows), o.csv, o.md, o.md_full);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse_options(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
}
