// make_database: builds the closure's database of small hexahedrizations
// (src/closure/database.hpp) and writes it; scripts/make-database.sh runs it
// with the shipped limits. Prints how many boundaries each level reached,
// the time and the peak memory.
#include <sys/resource.h>

#include <chrono>
#include <iostream>
#include <map>

#include <fmt/format.h>

#include "bench/bench_options.hpp"
#include "src/closure/database.hpp"
#include "src/closure/database_improve.hpp"
#include "src/util/error.hpp"

int main(int argc, char** argv) {
  using namespace loom;
  CLI::App app("Builds the closure's database of small hexahedrizations");
  closure::DatabaseLimits limits{255, 24, 18};
  std::string output;
  app.add_option("-o,--output", output, "file to write (rules/closure/database.txt)")->required();
  app.add_option("--max-hexes", limits.max_hexes, "meshes of up to this many hexes (default 255: no limit)")
      ->check(CLI::Range(1, 255));
  app.add_option("--max-quads", limits.max_quads, "grow boundaries of up to this many quads (default 24)")
      ->check(CLI::Range(6, 64));
  app.add_option("--store-quads", limits.store_quads, "keep boundaries of up to this many quads (default 18)")
      ->check(CLI::Range(6, 64));
  app.add_option("--grown-per-boundary", limits.grown_per_boundary,
                 "grow up to this many meshes of each boundary, touching it differently (default 1)")
      ->check(CLI::Range(1, 16));
  std::size_t improve = 0;
  std::string from;
  app.add_option("--from", from, "start from this database file instead of the outward shelling (to improve it)");
  app.add_option("--improve", improve,
                 "then search each entry's boundary with this many expansions and keep smaller meshes (default 0: no)");
  bench::parse_or_exit(app, argc, argv);

  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  closure::Database db;
  try {
    db = !from.empty() ? closure::Database::load(from)
                       : closure::Database::build(limits, [&](int hexes, std::size_t reached) {
                           if (hexes % 5 == 0)
                             std::cerr << fmt::format("{} hexes: {} meshes grown ({:.0f} s)\n", hexes, reached,
                                                      seconds());
                         });
  } catch (const InputError& e) {
    std::cerr << "make_database: " << e.what() << "\n";
    return 2;
  }
  const double built = seconds();
  closure::DatabaseImprovement better;
  if (improve > 0) {
    closure::ClosureOptions options;
    options.limits.max_expansions = improve;
    better = closure::improve_by_search(db, options, [&](const closure::DatabaseImprovement& r) {
      if (r.searched % 500 == 0)
        std::cerr << fmt::format("searched {} entries: {} smaller, {} hexes fewer ({:.0f} s)\n", r.searched, r.improved,
                                 r.hexes_saved, seconds());
    });
  }
  db.save(output);
  std::map<std::size_t, std::pair<std::size_t, std::size_t>> by_quads;  // quads -> (entries, most hexes)
  for (const auto& e : db.entries()) {
    auto& [n, most] = by_quads[quadmap::code_quads(e.code)];
    ++n;
    most = std::max(most, e.hexes());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::cout << fmt::format("wrote {}: {} boundaries of at most {} quads (grown up to {}), {:.0f} s, peak {:.0f} MB\n",
                           output, db.size(), limits.store_quads, limits.max_quads, seconds(),
                           static_cast<double>(usage.ru_maxrss) / 1024.0);
  if (improve > 0)
    std::cout << fmt::format("  the outward shelling took {:.0f} s; the search ({} expansions an entry) gave {} entries "
                             "smaller meshes, {} hexes fewer in all, in {:.0f} s\n",
                             built, improve, better.improved, better.hexes_saved, seconds() - built);
  for (const auto& [quads, stat] : by_quads)
    std::cout << fmt::format("  {:3} quads: {:6} boundaries, at most {} hexes\n", quads, stat.first, stat.second);
  return 0;
}
