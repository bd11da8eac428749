// bench_corpus: weaves a corpus of surfaces (the generators, and the surface
// files of a folder) under several strategies and rule orderings, and writes
// one row per (input, configuration) as CSV and Markdown, with a summary per
// configuration (closure rate over the random quadrangulations by size band).
//
//   bench_corpus [--dir DIR] [--randquad-max F] [--max-steps N] [--timeout S]
//                [--only TEXT] [--shard K/N]
//                [--csv FILE] [--md FILE] [--md-full] [--list]
//   bench_corpus --merge A.csv B.csv ... [--csv FILE] [--md FILE] [--md-full]
//
// Rows are numbered over the whole corpus (inputs in corpus order, then
// configurations in order); shard K of N runs the rows whose number is
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
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/stc/stc.hpp"
#include "src/weave/pipeline.hpp"

namespace {

using namespace loom;
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
  std::string strategy;
  std::uint64_t seed = 0;
  bool backtracking = true;
  std::size_t attempts = 1;  ///< WeaveOptions::attempts (random restarts)
};

const std::vector<Config>& configs() {
  static const std::vector<Config> list = {
      {"priority", "priority", 0, true},
      {"priority-nobt", "priority", 0, false},
      {"random-1", "random", 1, true},
      {"random-2", "random", 2, true},
      {"seq-seam-cross", "sequence:seam,cross", 0, true},
      {"seq-cross-seam", "sequence:cross,seam", 0, true},
      {"portfolio-16", "priority", 0, true, 16},
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

// ---------------------------------------------------------------- rows

const std::vector<std::string> kColumns = {
    "row", "input", "family", "faces", "quads", "config", "closed", "valid", "comb_valid", "hexes", "steps",
    "cross", "seam", "other_rules", "backtracks", "whiskers_left", "degeneracies", "pillows", "min_sj", "mean_sj",
    "below_0_2", "seconds", "recheck", "note"};

struct Row {
  std::size_t row = 0;
  std::string input, family;
  int faces = 0;
  std::size_t quads = 0;
  std::string config;
  bool closed = false, valid = false, comb_valid = false;
  std::size_t hexes = 0, steps = 0, cross = 0, seam = 0;
  std::string other_rules;
  std::size_t backtracks = 0, whiskers_left = 0;
  std::string degeneracies = "n/a", pillows = "n/a";
  std::optional<double> min_sj, mean_sj;
  std::size_t below_0_2 = 0;
  double seconds = 0;
  std::string recheck;  ///< "ok", "MISMATCH: ...", or "" (no mesh)
  std::string note;     ///< why it failed (the weave's `left`, a failure, an exception)

  std::vector<std::string> fields() const {
    auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : std::string(); };
    return {std::to_string(row), input, family, std::to_string(faces), std::to_string(quads), config,
            closed ? "yes" : "no", valid ? "yes" : "no", comb_valid ? "yes" : "no", std::to_string(hexes),
            std::to_string(steps), std::to_string(cross), std::to_string(seam), other_rules,
            std::to_string(backtracks), std::to_string(whiskers_left), degeneracies, pillows, opt(min_sj),
            opt(mean_sj), std::to_string(below_0_2), fmt::format("{:.4f}", seconds), recheck, note};
  }
  static Row from(const std::vector<std::string>& f) {
    if (f.size() != kColumns.size())
      throw std::runtime_error(fmt::format("bench_corpus: a CSV row has {} fields, not {}", f.size(), kColumns.size()));
    Row r;
    std::size_t i = 0;
    auto num = [&] { return std::size_t(std::stoull(f[i++])); };
    auto str = [&] { return f[i++]; };
    auto yes = [&] { return f[i++] == "yes"; };
    auto opt = [&]() -> std::optional<double> {
      const std::string& s = f[i++];
      if (s.empty()) return std::nullopt;
      return std::stod(s);
    };
    r.row = num();
    r.input = str();
    r.family = str();
    r.faces = int(num());
    r.quads = num();
    r.config = str();
    r.closed = yes();
    r.valid = yes();
    r.comb_valid = yes();
    r.hexes = num();
    r.steps = num();
    r.cross = num();
    r.seam = num();
    r.other_rules = str();
    r.backtracks = num();
    r.whiskers_left = num();
    r.degeneracies = str();
    r.pillows = str();
    r.min_sj = opt();
    r.mean_sj = opt();
    r.below_0_2 = num();
    r.seconds = std::stod(str());
    r.recheck = str();
    r.note = str();
    return r;
  }
};

// ---------------------------------------------------------------- CSV

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else out.back() += c;
    } else if (c == '"') quoted = true;
    else if (c == ',') out.emplace_back();
    else out.back() += c;
  }
  return out;
}

void write_csv(const std::string& file, const std::vector<Row>& rows) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("bench_corpus: cannot write " + file);
  for (std::size_t i = 0; i < kColumns.size(); ++i) out << (i ? "," : "") << kColumns[i];
  out << '\n';
  for (const auto& r : rows) {
    auto f = r.fields();
    for (std::size_t i = 0; i < f.size(); ++i) out << (i ? "," : "") << csv_field(f[i]);
    out << '\n';
  }
}

std::vector<Row> read_csv(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("bench_corpus: cannot read " + file);
  std::string line;
  if (!std::getline(in, line) || csv_split(line) != kColumns)
    throw std::runtime_error("bench_corpus: " + file + " is not a bench_corpus CSV (header differs)");
  std::vector<Row> rows;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(Row::from(csv_split(line)));
  return rows;
}

// ---------------------------------------------------------------- one run

Row run_one(const Input& input, const QuadSurface& surface, const Config& config,
            const std::vector<engine::Rule>& rules, std::size_t max_steps, double timeout) {
  Row r;
  r.input = input.name;
  r.family = input.family;
  r.faces = input.faces;
  r.quads = surface.quads.size();
  r.config = config.name;
  weave::WeaveOptions options;
  options.strategy = engine::Strategy::parse(config.strategy);
  options.strategy.seed = config.seed;
  if (!config.backtracking) options.max_backtracks = 0;
  options.attempts = config.attempts;
  options.max_steps = max_steps;
  // A wall-clock guard: a run that explodes is stopped (the row says so).
  struct Timeout {
    std::size_t steps;
  };
  auto start = std::chrono::steady_clock::now();
  std::size_t seen = 0;
  if (timeout > 0)
    options.after_step = [&](const engine::Application&, const stc::Stc&) {
      if (++seen % 16 == 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout)
        throw Timeout{seen};
    };
  try {
    weave::MeshingResult m = weave::mesh_surface(surface, rules, options);
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
    r.note = fmt::format("timeout: stopped after {:.0f} s and {} applications", timeout, t.steps);
  } catch (const std::exception& e) {
    r.note = std::string("error: ") + e.what();
  }
  return r;
}

// ---------------------------------------------------------------- reports

struct Band {
  int lo, hi;
  std::string name() const { return fmt::format("{}-{}", lo, hi); }
};
const std::vector<Band> kBands = {{6, 20}, {22, 50}, {52, 100}, {102, 200}};

std::string rate(std::size_t k, std::size_t n) {
  if (n == 0) return "-";
  return fmt::format("{}/{} ({:.1f}%)", k, n, 100.0 * double(k) / double(n));
}

std::vector<std::string> config_order(const std::vector<Row>& rows) {
  std::vector<std::string> names;
  for (const auto& c : configs()) names.push_back(c.name);
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), r.config) == names.end()) names.push_back(r.config);
  std::vector<std::string> present;
  for (const auto& n : names)
    if (std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.config == n; })) present.push_back(n);
  return present;
}

std::string md_row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) {
    std::string e;
    for (char ch : c) e += ch == '|' ? std::string("\\|") : std::string(1, ch);
    s += " " + e + " |";
  }
  return s + "\n";
}
std::string md_header(const std::vector<std::string>& cells) {
  std::string s = md_row(cells) + "|";
  for (std::size_t i = 0; i < cells.size(); ++i) s += "---|";
  return s + "\n";
}

std::string summary_md(const std::vector<Row>& rows) {
  std::string out;
  auto cfgs = config_order(rows);
  out += "### Per configuration\n\n";
  std::vector<std::string> head = {"config", "runs", "closed", "valid 1-6", "valid 1-7", "randquad closed"};
  for (const auto& b : kBands) head.push_back("F " + b.name());
  head.insert(head.end(), {"backtracks", "recheck mismatches", "errors/timeouts", "seconds"});
  out += md_header(head);
  std::string best;
  double best_rate = -1;
  std::size_t best_closed = 0;
  for (const auto& c : cfgs) {
    std::size_t runs = 0, closed = 0, comb = 0, valid = 0, rq = 0, rq_closed = 0, bt = 0, mism = 0, errors = 0;
    double secs = 0;
    std::vector<std::size_t> bn(kBands.size()), bc(kBands.size());
    for (const auto& r : rows) {
      if (r.config != c) continue;
      ++runs;
      closed += r.closed, comb += r.comb_valid, valid += r.valid, bt += r.backtracks, secs += r.seconds;
      mism += r.recheck.starts_with("MISMATCH");
      errors += r.note.starts_with("error:") || r.note.starts_with("timeout:");
      if (r.family == "randquad") {
        ++rq, rq_closed += r.closed;
        for (std::size_t b = 0; b < kBands.size(); ++b)
          if (r.faces >= kBands[b].lo && r.faces <= kBands[b].hi) ++bn[b], bc[b] += r.closed;
      }
    }
    std::vector<std::string> cells = {c, std::to_string(runs), rate(closed, runs), rate(comb, runs),
                                      rate(valid, runs), rate(rq_closed, rq)};
    for (std::size_t b = 0; b < kBands.size(); ++b) cells.push_back(rate(bc[b], bn[b]));
    cells.insert(cells.end(), {std::to_string(bt), std::to_string(mism), std::to_string(errors),
                               fmt::format("{:.1f}", secs)});
    out += md_row(cells);
    double key = rq ? double(rq_closed) / double(rq) : double(closed) / double(runs);
    if (key > best_rate || (key == best_rate && closed > best_closed)) best = c, best_rate = key, best_closed = closed;
  }
  out += "\n";
  if (!best.empty()) {
    out += fmt::format("Closes most: **{}** ({:.1f}% of randquad; {} runs closed in all).\n\n", best,
                       100.0 * best_rate, best_closed);
    std::vector<const Row*> fails;
    for (const auto& r : rows)
      if (r.config == best && !r.comb_valid) fails.push_back(&r);
    if (!fails.empty()) {
      out += fmt::format("What stops {} ({} runs without a mesh passing criteria 1-6; up to 12 shown, smallest first):\n\n",
                         best, fails.size());
      std::stable_sort(fails.begin(), fails.end(), [](const Row* a, const Row* b) { return a->quads < b->quads; });
      for (std::size_t i = 0; i < fails.size() && i < 12; ++i)
        out += fmt::format("- `{}` ({} quads): {}\n", fails[i]->input, fails[i]->quads, fails[i]->note);
      out += "\n";
    }
  }
  return out;
}

std::string rows_md(const std::vector<Row>& rows, bool randquad_too) {
  std::string out = md_header({"input", "quads", "config", "closed", "valid", "comb. valid", "hexes", "steps", "cross",
                               "seam", "other", "backtracks", "whiskers left", "degeneracies", "pillows", "min SJ",
                               "mean SJ", "< 0.2", "seconds", "recheck"});
  for (const auto& r : rows) {
    if (!randquad_too && r.family == "randquad") continue;
    auto f = r.fields();
    out += md_row({r.input, std::to_string(r.quads), r.config, f[6], f[7], f[8], f[9], f[10], f[11], f[12],
                   r.other_rules.empty() ? "-" : r.other_rules, f[14], f[15], r.degeneracies, r.pillows,
                   f[18].empty() ? "-" : f[18], f[19].empty() ? "-" : f[19], f[20], fmt::format("{:.3f}", r.seconds),
                   r.recheck.empty() ? "-" : r.recheck});
  }
  return out;
}

std::string randquad_md(const std::vector<Row>& rows) {
  // Closed runs per F (10 seeds each), one column per configuration.
  auto cfgs = config_order(rows);
  std::map<int, std::map<std::string, std::pair<int, int>>> by_f;  // F -> config -> (closed, runs)
  for (const auto& r : rows)
    if (r.family == "randquad") {
      auto& c = by_f[r.faces][r.config];
      c.first += r.closed, c.second += 1;
    }
  if (by_f.empty()) return {};
  std::vector<std::string> head = {"F"};
  head.insert(head.end(), cfgs.begin(), cfgs.end());
  std::string out = md_header(head);
  for (const auto& [f, m] : by_f) {
    std::vector<std::string> cells = {std::to_string(f)};
    for (const auto& c : cfgs) {
      auto it = m.find(c);
      cells.push_back(it == m.end() ? "-" : fmt::format("{}/{}", it->second.first, it->second.second));
    }
    out += md_row(cells);
  }
  return out;
}

void write_outputs(std::vector<Row> rows, const std::string& csv, const std::string& md, bool md_full) {
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.row < b.row; });
  if (!csv.empty()) write_csv(csv, rows);
  std::string text = "## Summary\n\n" + summary_md(rows);
  std::string rq = randquad_md(rows);
  if (!rq.empty()) text += "### Random quadrangulations: closed runs per F (of 10 seeds)\n\n" + rq + "\n";
  text += md_full ? "### Every run\n\n" : "### Per input (randquad rows in the CSV)\n\n";
  text += rows_md(rows, md_full);
  if (!md.empty()) {
    std::ofstream out(md);
    if (!out) throw std::runtime_error("bench_corpus: cannot write " + md);
    out << text;
  }
  std::cout << summary_md(rows);
}

// ---------------------------------------------------------------- main

struct Options {
  std::string dir, csv, md;
  int randquad_max = 200;
  std::size_t max_steps = 0;
  double timeout = 2;
  std::string only;
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
  app.add_option("--only", o.only, "only inputs or configurations whose name contains TEXT");
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
  if (o.list) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      for (std::size_t c = 0; c < cfgs.size(); ++c)
        if ((i * cfgs.size() + c) % std::size_t(o.shard_n) == std::size_t(o.shard_k - 1))
          std::cout << i * cfgs.size() + c << ' ' << inputs[i].name << ' ' << cfgs[c].name << '\n';
    return 0;
  }
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  std::vector<Row> rows;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    std::vector<std::size_t> mine;
    for (std::size_t c = 0; c < cfgs.size(); ++c)
      if ((i * cfgs.size() + c) % std::size_t(o.shard_n) == std::size_t(o.shard_k - 1)) mine.push_back(c);
    if (mine.empty() || (!o.only.empty() && inputs[i].name.find(o.only) == std::string::npos)) continue;
    std::optional<QuadSurface> surface;
    std::string error;
    try {
      surface = inputs[i].make();
    } catch (const std::exception& e) {
      error = std::string("error: input: ") + e.what();
    }
    for (std::size_t c : mine) {
      Row r;
      if (surface) r = run_one(inputs[i], *surface, cfgs[c], rules, o.max_steps, o.timeout);
      else r.input = inputs[i].name, r.family = inputs[i].family, r.faces = inputs[i].faces, r.config = cfgs[c].name,
           r.note = error;
      r.row = i * cfgs.size() + c;
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
