// bench_untangle: the global untangler (src/geometry/untangle.hpp) in figures.
//
//   bench_untangle [--sizes 10,20,30,46] [--scramble S] [--seed N] [--quads A-B]
//                  [--mesh FILE [--optimize] [--layers N]]
//
// Speed: n x n x n hex grids whose interior nodes are thrown up to S cell
// lengths away (the boundary fixed), untangled; seconds per 10^5 hexes,
// inverted hexes before and after, rounds. Success: `loom weave`'s pipeline on
// every 3-connected quadrangulation with A..B quads (cavity closure and search
// included), and how many of its meshes come out with every scaled Jacobian
// above 0 (criterion 7), with the untangler's rounds. Figures, not a test: the
// machine is shared, compare within one run. A given mesh (--mesh): untangled,
// or with --optimize placed as loom weave places (every hex below 1 improved),
// after --layers N boundary layers; quality before and after.
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_options.hpp"
#include "engine/rule_compiler.hpp"
#include "src/check/hex_boundary.hpp"
#include "src/check/criteria.hpp"
#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/fill/cap.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/geometry/placement.hpp"
#include "src/geometry/untangle.hpp"
#include "src/io/hex_io.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/quadmap/enumerate.hpp"
#include "src/weave/weave.hpp"

namespace {

using namespace loom;

void speed(const std::vector<int>& sizes, double scramble, std::uint64_t seed) {
  std::printf("| grid | hexes | inverted before | inverted after | untangled | rounds | L-BFGS iterations | seconds | s per 10^5 hexes |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  for (int n : sizes) {
    HexMesh mesh = gen::hexgrid(n, n, n);
    std::vector<std::uint32_t> boundary;
    hex_mesh_boundary(mesh, &boundary);
    std::vector<bool> fixed(mesh.points.size(), false);
    for (std::uint32_t v : boundary) fixed[v] = true;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> shift(-scramble, scramble);
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
      if (!fixed[i])
        for (int d = 0; d < 3; ++d) mesh.points[i][d] += shift(rng);
    const geometry::UntangleReport r = geometry::untangle(mesh, fixed);
    std::printf("| %d^3 | %zu | %zu | %zu | %s | %d | %d | %.2f | %.2f |\n", n, mesh.hexes.size(), r.inverted_before,
                r.inverted_after, r.untangled ? "yes" : "no", r.rounds, r.iterations, r.seconds,
                r.seconds * 1e5 / static_cast<double>(mesh.hexes.size()));
    std::fflush(stdout);
  }
}

QualitySummary quality_of(const HexMesh& mesh) {
  QualitySummary q;
  criteria::positive_scaled_jacobian(mesh, q);
  return q;
}

std::string quality_cell(const QualitySummary& q) {
  return fmt::format("{:.3f} / {:.3f}, {}, {}", q.min_scaled_jacobian, q.mean_scaled_jacobian, q.below_zero,
                     q.below_0_2);
}

/// What to do to each --mesh file, its boundary nodes fixed.
struct FileRun {
  geometry::UntangleOptions untangle;
  bool optimize = false;  ///< the whole placement, every hex improved, instead of the untangler alone
  int layers = 0;         ///< boundary layers pillowed first
};

/// Each mesh file untangled (or optimized) from its written positions: does a
/// longer run untangle more, and how far can placement raise the quality of a
/// given connectivity? Quality is min / mean scaled Jacobian, hexes <= 0, < 0.2.
void files(const std::vector<std::string>& paths, const FileRun& run) {
  if (paths.empty()) return;
  std::printf("\n| mesh | hexes | layers | before | after | rounds | seconds |\n|---|---|---|---|---|---|---|\n");
  for (const auto& path : paths) {
    HexMesh mesh = read_hex_mesh(path);
    std::vector<std::uint32_t> boundary;
    hex_mesh_boundary(mesh, &boundary);
    std::vector<bool> fixed(mesh.points.size(), false);
    for (std::uint32_t v : boundary) fixed[v] = true;
    const QualitySummary before = quality_of(mesh);
    for (int i = 0; i < run.layers; ++i) geometry::pillow_boundary_layer(mesh, fixed);
    int rounds = 0;
    double seconds = 0;
    if (run.optimize) {
      geometry::PlacementOptions options;
      options.improve_below = 1.0;
      // The copies of a new layer sit on the surface: start from the harmonic placement.
      options.start = run.layers > 0 ? geometry::PlacementOptions::Start::harmonic
                                     : geometry::PlacementOptions::Start::input;
      const geometry::PlacementReport r = geometry::place_nodes(mesh, fixed, options);
      rounds = r.global_rounds;
      seconds = r.seconds;
    } else {
      const geometry::UntangleReport r = geometry::untangle(mesh, fixed, run.untangle);
      rounds = r.rounds;
      seconds = r.seconds;
    }
    std::printf("| %s | %zu | %d | %s | %s | %d | %.1f |\n", path.c_str(), mesh.hexes.size(), run.layers,
                quality_cell(before).c_str(), quality_cell(quality_of(mesh)).c_str(), rounds, seconds);
    std::fflush(stdout);
  }
}

void success(const std::vector<int>& counts) {
  if (counts.empty()) return;
  const auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  std::printf("\n| quads | inputs | valid 1-6 | every SJ > 0 | untangler ran | of those, every SJ > 0 | mean s |\n"
              "|---|---|---|---|---|---|---|\n");
  for (int f : counts) {
    std::size_t inputs = 0, valid = 0, positive = 0, ran = 0, ran_positive = 0;
    double seconds = 0;
    const auto maps = quadmap::three_connected_quadrangulations(f);
    for (std::size_t i = 0; i < maps.size(); ++i) {
      const pipeline::MeshingOptions m = pipeline::default_meshing_options();
      const auto r = pipeline::mesh_surface(gen::quadrangulation(maps[i], static_cast<int>(i)), rules, m);
      ++inputs;
      seconds += r.seconds;
      if (!r.combinatorially_valid()) continue;
      ++valid;
      const bool good = r.check->valid();
      positive += good;
      if (r.smoothing.global_rounds > 0) {
        ++ran;
        ran_positive += good;
      }
    }
    std::printf("| %d | %zu | %zu | %zu | %zu | %zu | %.1f |\n", f, inputs, valid, positive, ran, ran_positive,
                seconds / static_cast<double>(inputs));
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("The global untangler in figures: speed on scrambled grids, success on loom weave's closures");
  std::string sizes = "10,20,30,46", quads = "6-12";
  double scramble = 1.5;
  std::uint64_t seed = 1;
  app.add_option("--sizes", sizes, "grid sizes n (n^3 hexes; default 10,20,30,46: up to about 10^5)");
  app.add_option("--scramble", scramble, "interior nodes moved up to this many cell lengths (default 1.5: nearly every hex inverted)");
  app.add_option("--seed", seed, "of the scrambling (default 1)");
  app.add_option("--quads", quads, "3-connected quadrangulations with A-B quads for the success rate ('' for none; default 6-12)");
  std::vector<std::string> meshes;
  FileRun run;
  app.add_option("--mesh", meshes, "also untangle these hex mesh files, boundary fixed (repeatable)");
  app.add_option("--rounds", run.untangle.max_rounds, "with --mesh: the untangler's most rounds");
  app.add_option("--patience", run.untangle.patience, "with --mesh: rounds without progress before it gives up");
  app.add_option("--lambda", run.untangle.lambda, "with --mesh: weight of the volume term");
  app.add_flag("--optimize", run.optimize,
               "with --mesh: run the whole placement (untangling, then quality) on every hex below 1 instead");
  app.add_option("--layers", run.layers, "with --mesh: pillow this many boundary layers first")->check(CLI::NonNegativeNumber);
  loom::bench::parse_or_exit(app, argc, argv);
  files(meshes, run);
  speed(loom::bench::parse_counts(sizes), scramble, seed);
  success(loom::bench::parse_counts(quads));
  return 0;
}
