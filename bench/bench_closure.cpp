// bench_closure: closure in figures, from whole surfaces.
//
//   bench_closure [--quads A-B] [--randquad LIST] [--seeds N] [--shapes]
//                 [--pipeline [--prefer quality|fewest-hexes] [--strategy S]] [--rules DIR]
//                 [--expansions N] [--weight W] [--irregularity W] [--database FILE]
//                 [--shard K/N] [--csv FILE [--resume]]
//   bench_closure --merge A.csv B.csv ...
//
// Inputs: every 3-connected sphere quadrangulation with A..B quads (gen
// quadrangulation), random quadrangulations (randquad F, seeds 1..N), and
// with --shapes Schneiders' pyramid and the spindle, each also with its
// nodes and quads numbered at random (three renumberings).
//
// Without --pipeline it runs the closure search alone (src/closure/
// shelling_search.hpp) on each whole surface: how many close and in how many
// hexes, expansions and states a second, and where the time went. With
// --pipeline it runs what `loom weave` does by default (the shipped rules, 16
// attempts, cavity closure, the whole-surface fill last) and says which stage
// made each mesh (--prefer: which of two meshes it keeps; --rules and
// --strategy as for loom weave, the database and fill caps following --rules). --shard K/N runs inputs K-1, K-1+N, ...; --csv writes one
// row per input (--resume: after the rows FILE already has, the inputs it
// lacks); --merge sums shard CSVs. Figures, not a test: the machine is
// shared, compare within a run.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "bench/bench_options.hpp"
#include "engine/random_draws.hpp"
#include "engine/rule_compiler.hpp"
#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/fill/cap.hpp"
#include "src/gen/generators.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/quadmap/enumerate.hpp"
#include "src/weave/weave.hpp"

namespace {

using namespace loom;

struct Input {
  std::string name, group;
  QuadSurface surface;
};

/// One input's outcome: a CSV row.
struct Outcome {
  std::string input, group, made_by;
  std::size_t quads = 0, hexes = 0, expanded = 0, states = 0, front_left = 0;
  std::map<std::string, std::size_t> sources;
  bool closed = false, comb_valid = false, valid = false;
  double seconds = 0;
  closure::SearchProfile profile;

  static std::string header() {
    return "input,group,quads,closed,made_by,hexes,woven,searched,database,filled,pillow,comb_valid,valid,"
           "front_left,expanded,states,seconds";
  }
  std::string csv() const {
    auto n = [&](const char* s) { return sources.count(s) ? sources.at(s) : 0; };
    return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.4f}", input, group, quads, closed ? "yes" : "no",
                       made_by, hexes, n("woven"), n("searched"), n("database"), n("filled"), n("pillow"),
                       comb_valid ? "yes" : "no", valid ? "yes" : "no", front_left, expanded, states, seconds);
  }
  static Outcome parse(const std::string& line) {
    std::vector<std::string> f;
    std::stringstream in(line);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    if (f.size() != 17) throw std::runtime_error("bench_closure: not a bench_closure CSV row: " + line);
    Outcome o;
    o.input = f[0], o.group = f[1], o.quads = std::stoul(f[2]), o.closed = f[3] == "yes", o.made_by = f[4];
    o.hexes = std::stoul(f[5]);
    const char* names[] = {"woven", "searched", "database", "filled", "pillow"};
    for (int i = 0; i < 5; ++i) o.sources[names[i]] = std::stoul(f[static_cast<std::size_t>(6 + i)]);
    o.comb_valid = f[11] == "yes", o.valid = f[12] == "yes", o.front_left = std::stoul(f[13]);
    o.expanded = std::stoul(f[14]), o.states = std::stoul(f[15]), o.seconds = std::stod(f[16]);
    return o;
  }
};

/// A surface with its nodes renumbered and its quads reordered and rotated at random.
QuadSurface renumbered(const QuadSurface& s, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint32_t> name(s.points.size());
  for (std::uint32_t i = 0; i < name.size(); ++i) name[i] = i;
  engine::shuffle(name.begin(), name.end(), rng);
  QuadSurface out;
  out.points.resize(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) out.points[name[i]] = s.points[i];
  for (const Quad& q : s.quads) {
    const auto r = static_cast<int>(rng() % 4);
    out.quads.push_back({name[q[r % 4]], name[q[(r + 1) % 4]], name[q[(r + 2) % 4]], name[q[(r + 3) % 4]]});
  }
  engine::shuffle(out.quads.begin(), out.quads.end(), rng);
  return out;
}

struct Summary {
  std::size_t n = 0, closed = 0, comb_valid = 0, valid = 0, most = 0, total = 0, expanded = 0, states = 0;
  std::map<std::string, std::size_t> made_by;
  double seconds = 0;
  closure::SearchProfile profile;
  void add(const Outcome& o) {
    ++n;
    closed += o.closed;
    comb_valid += o.comb_valid;
    valid += o.valid;
    if (o.comb_valid) {
      most = std::max(most, o.hexes);
      total += o.hexes;
    }
    ++made_by[o.made_by.empty() ? "nothing" : o.made_by];
    expanded += o.expanded;
    states += o.states;
    seconds += o.seconds;
    profile.rebuild += o.profile.rebuild;
    profile.canonical += o.profile.canonical;
    profile.database += o.profile.database;
    profile.gluing += o.profile.gluing;
  }
};

void print_summary(const std::vector<Outcome>& all, bool pipeline) {
  std::map<std::string, Summary> groups;
  std::vector<std::string> order;
  for (const Outcome& o : all) {
    if (!groups.count(o.group)) order.push_back(o.group);
    groups[o.group].add(o);
  }
  if (pipeline) {
    std::cout << "| inputs | n | valid 1-6 | valid 1-7 | made by | most hexes | mean hexes | mean s |\n|---|---|---|---|---|---|---|---|\n";
    for (const auto& g : order) {
      const Summary& s = groups[g];
      std::string by;
      for (const auto& [k, v] : s.made_by) by += fmt::format("{}{} {}", by.empty() ? "" : ", ", k, v);
      std::cout << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.2f} |\n", g, s.n, s.comb_valid, s.valid, by,
                               s.comb_valid ? fmt::format("{}", s.most) : "-",
                               s.comb_valid ? fmt::format("{:.1f}", double(s.total) / double(s.comb_valid)) : "-",
                               s.seconds / double(s.n));
    }
    return;
  }
  std::cout << "| inputs | n | closed | valid 1-6 | most hexes | mean hexes | s each | expansions/s | states/s | "
               "time % rebuild / canonical / database+cube / gluings |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& g : order) {
    const Summary& s = groups[g];
    const double t = s.seconds > 0 ? s.seconds : 1;
    const closure::SearchProfile& p = s.profile;
    // The CSV holds no profile: merged shards say so rather than 0 / 0 / 0 / 0.
    const std::string profile = p.rebuild + p.canonical + p.database + p.gluing > 0
        ? fmt::format("{:.0f} / {:.0f} / {:.0f} / {:.0f}", 100 * p.rebuild / t, 100 * p.canonical / t,
                      100 * p.database / t, 100 * p.gluing / t)
        : "- (see the shards' own tables)";
    std::cout << fmt::format("| {} | {} | {} | {} | {} | {} | {:.3f} | {:.0f} | {:.0f} | {} |\n", g, s.n, s.closed,
                             s.comb_valid, s.closed ? fmt::format("{}", s.most) : "-",
                             s.closed ? fmt::format("{:.1f}", double(s.total) / double(s.closed)) : "-",
                             s.seconds / double(s.n), double(s.expanded) / t, double(s.states) / t, profile);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Closure in figures: the search alone, or loom weave's whole pipeline, from whole surfaces");
  std::string quads = "6-16", randquads, database, shard, csv;
  std::vector<std::string> merge;
  int seeds = 3;
  bool shapes = false, pipeline = false, resume = false;
  closure::ClosureOptions options;
  app.add_option("--quads", quads, "3-connected quadrangulations with these quad counts: A-B (even ones), or a list (default 6-16; '' for none)");
  app.add_option("--randquad", randquads, "random quadrangulations: a list of F, or A-B:STEP");
  app.add_option("--seeds", seeds, "random quadrangulations per F: seeds 1..N (default 3)");
  app.add_flag("--shapes", shapes, "Schneiders' pyramid and the spindle, each also renumbered three ways");
  app.add_flag("--pipeline", pipeline, "run loom weave's defaults (weave, cavity closure, fill) instead of the search alone");
  std::string rules_dir = weave::default_rules_dir().string(), strategy;
  app.add_option("--rules", rules_dir,
                 "with --pipeline, as loom weave --rules: the rules, and the database and fill caps they bring "
                 "(default: the shipped rules/)");
  app.add_option("--strategy", strategy,
                 "with --pipeline, as loom weave --strategy (default: the rules' strategies/default.strategy, else priority)");
  app.add_option("--expansions", options.limits.max_expansions, "search budget per cavity (default 4000)");
  app.add_option("--weight", options.limits.weight, "weight of the search's estimate (default 20)");
  app.add_option("--irregularity", options.irregularity_weight,
                 "weight of the hexes' irregularity in the search's cost (default 0: fewest hexes)");
  pipeline::Prefer prefer = pipeline::Prefer::quality;
  app.add_option("--prefer", prefer,
                 "with --pipeline, which of two meshes a run keeps: quality (default, as loom weave) or fewest-hexes "
                 "(the combinatorial corpus's figures)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, pipeline::Prefer>{{"quality", pipeline::Prefer::quality},
                                                                              {"fewest-hexes", pipeline::Prefer::fewest_hexes}},
                                             CLI::ignore_case));
  app.add_option("--growth", options.max_growth, "fronts larger than the start by more than this are not explored (default 8)");
  auto* database_option = app.add_option("--database", database, "database file ('' for none; default: the rules')");
  app.add_option("--shard", shard, "run only inputs K-1, K-1+N, ... (K/N)");
  auto* csv_option = app.add_option("--csv", csv, "write one row per input");
  app.add_option("--merge", merge, "sum these CSVs instead of running");
  app.add_flag("--resume", resume, "keep the rows --csv already has, run only the inputs it lacks, and add theirs")
      ->needs(csv_option);
  loom::bench::parse_or_exit(app, argc, argv);
  if (!database_option->count()) database = pipeline::default_meshing_options(rules_dir).database.string();

  std::vector<Outcome> outcomes;
  auto read_rows = [&outcomes](const std::string& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line))
      if (!line.empty()) outcomes.push_back(Outcome::parse(line));
  };
  if (!merge.empty()) {
    for (const auto& f : merge) read_rows(f);
    print_summary(outcomes, std::any_of(outcomes.begin(), outcomes.end(), [](const Outcome& o) { return !o.made_by.empty(); }));
    return 0;
  }
  int shard_k = 1, shard_n = 1;
  if (!shard.empty()) {
    const auto slash = shard.find('/');
    shard_k = std::stoi(shard.substr(0, slash));
    shard_n = std::stoi(shard.substr(slash + 1));
  }

  std::vector<std::function<Input()>> inputs;
  for (int f : loom::bench::parse_counts(quads)) {
    const auto maps = std::make_shared<const std::vector<quadmap::QuadMap>>(quadmap::three_connected_quadrangulations(f));
    for (std::size_t i = 0; i < maps->size(); ++i)
      inputs.push_back([f, i, maps] {
        return Input{fmt::format("quadrangulation {} {}", f, i), fmt::format("3-connected {} quads", f),
                     gen::quadrangulation((*maps)[i], static_cast<int>(i))};
      });
  }
  if (shapes)
    for (const auto& [name, make] : std::vector<std::pair<std::string, QuadSurface (*)()>>{{"schneiders", gen::schneiders},
                                                                                        {"spindle", gen::spindle}})
      for (int r = 0; r <= 3; ++r)
        inputs.push_back([name, make, r] {
          return Input{r == 0 ? name : fmt::format("{} renumbered {}", name, r), name,
                       r == 0 ? make() : renumbered(make(), static_cast<std::uint64_t>(r))};
        });
  for (int f : loom::bench::parse_counts(randquads))
    for (int seed = 1; seed <= seeds; ++seed)
      inputs.push_back([f, seed] {
        return Input{fmt::format("randquad {} s{}", f, seed), fmt::format("randquad {}", f),
                     gen::randquad(f, static_cast<std::uint64_t>(seed))};
      });

  closure::Database db;
  if (!database.empty()) db = closure::Database::load(database);
  std::vector<engine::Rule> rules;
  engine::Strategy weave_strategy;
  try {
    rules = engine::load_rule_dir(rules_dir, *stc::StcSchema::get().schema);
    weave_strategy = strategy.empty() ? weave::strategy_of(rules_dir) : weave::strategy_named(strategy);
    engine::check_strategy(weave_strategy, rules, weave::strategy_measures());
  } catch (const std::exception& e) {  // a broken rule or strategy file: one line, as loom weave
    std::cerr << "bench_closure: " << e.what() << "\n";
    return 2;
  }
  std::cerr << fmt::format("{} inputs; database {} boundaries; budget {} expansions, weight {}\n", inputs.size(), db.size(),
                           options.limits.max_expansions, options.limits.weight);
  // A run stopped halfway (a session's end, a node's time limit) goes on where it stopped.
  std::set<std::string> done;
  if (resume && std::filesystem::exists(csv)) {
    read_rows(csv);
    for (const Outcome& o : outcomes) done.insert(o.input);
  }
  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv, done.empty() ? std::ios::trunc : std::ios::app);
    if (done.empty()) out << Outcome::header() << "\n";
  }
  for (std::size_t i = static_cast<std::size_t>(shard_k - 1); i < inputs.size(); i += static_cast<std::size_t>(shard_n)) {
    const Input in = inputs[i]();
    if (done.count(in.name)) continue;
    Outcome o;
    o.input = in.name, o.group = in.group, o.quads = in.surface.quads.size();
    if (pipeline) {
      pipeline::MeshingOptions m = pipeline::default_meshing_options(rules_dir);
      m.weave.strategy = weave_strategy;
      m.database = database;
      m.search = options;
      m.prefer = prefer;
      const auto r = pipeline::mesh_surface(in.surface, rules, m);
      o.closed = r.weave.closed, o.made_by = r.made_by, o.seconds = r.seconds;
      o.comb_valid = r.combinatorially_valid(), o.valid = o.comb_valid && r.check->valid();
      o.hexes = r.mesh ? r.mesh->hexes.size() : 0;
      for (auto s : r.source) ++o.sources[closure::source_name(s)];
      o.expanded = r.closure.search.expanded, o.states = r.closure.search.generated;
    } else {
      const auto r = closure::close_cavity(closure::surface_cavity(quadmap::from_surface(in.surface)),
                                           database.empty() ? nullptr : &db, options);
      o.closed = r.closed;
      o.hexes = r.hexes.size();
      if (r.closed) {  // checked independently, nodes at random off the surface
        HexMesh mesh{in.surface.points, r.hexes};
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> u(-0.5, 0.5);
        while (mesh.points.size() < r.vertex_bound) mesh.points.push_back({u(rng), u(rng), u(rng)});
        o.comb_valid = check_hex_mesh(mesh, &in.surface).combinatorial_valid();
      }
      for (auto s : r.source) ++o.sources[closure::source_name(s)];
      o.front_left = r.closed ? 0 : r.left.front.size();
      o.expanded = r.stats.expanded, o.states = r.stats.generated, o.seconds = r.stats.seconds;
      o.profile = r.profile;
    }
    if (out) out << o.csv() << "\n" << std::flush;
    outcomes.push_back(std::move(o));
  }
  print_summary(outcomes, pipeline);
  return 0;
}
