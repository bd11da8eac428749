// Global untangling (src/geometry/untangle.hpp): all free nodes moved at once
// until no hex corner or centre with a free node is inverted; fixed nodes never move.
#include <doctest/doctest.h>

#include <random>

#include "src/check/hex_boundary.hpp"
#include "src/check/criteria.hpp"
#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/fill/cap.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/untangle.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/weave/weave.hpp"
#include "engine/rule_compiler.hpp"

using namespace loom;

namespace {
/// A 6 x 6 x 6 grid whose interior nodes are thrown up to 1.5 cells away.
HexMesh scrambled_grid(std::uint64_t seed, std::vector<bool>& fixed) {
  HexMesh mesh = gen::hexgrid(6, 6, 6);
  std::vector<std::uint32_t> boundary;
  hex_mesh_boundary(mesh, &boundary);
  fixed.assign(mesh.points.size(), false);
  for (std::uint32_t n : boundary) fixed[n] = true;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> shift(-1.5, 1.5);
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if (!fixed[i])
      for (int d = 0; d < 3; ++d) mesh.points[i][d] += shift(rng);
  return mesh;
}
}  // namespace

TEST_CASE("a scrambled grid is untangled, its boundary untouched, the same way every time") {
  for (std::uint64_t seed : {1, 2, 3}) {
    std::vector<bool> fixed;
    HexMesh mesh = scrambled_grid(seed, fixed);
    const HexMesh before = mesh;
    const geometry::UntangleReport r = geometry::untangle(mesh, fixed);
    CHECK(r.inverted_before > 100);
    CHECK(r.inverted_after == 0);
    CHECK(r.untangled);
    QualitySummary quality;
    CHECK(criteria::positive_scaled_jacobian(mesh, quality).passed);
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
      if (fixed[i]) CHECK(mesh.points[i] == before.points[i]);
    HexMesh again = before;
    geometry::untangle(again, fixed);
    CHECK(again.points == mesh.points);
  }
}

TEST_CASE("nothing to untangle leaves the mesh bit-identical; a wrong fixed vector is refused") {
  HexMesh mesh = gen::hexgrid(3, 3, 3);
  const HexMesh before = mesh;
  std::vector<bool> fixed(mesh.points.size(), false);
  const geometry::UntangleReport r = geometry::untangle(mesh, fixed);
  CHECK(r.inverted_before == 0);
  CHECK(r.rounds == 0);
  CHECK(mesh.points == before.points);
  fixed.pop_back();
  CHECK_THROWS_AS(geometry::untangle(mesh, fixed), std::invalid_argument);
}

TEST_CASE("the untangler sees a hex's centre: a twisted hex with every corner positive is untwisted") {
  HexMesh mesh;
  mesh.points = {{0.329, 0.577, 0.126}, {0.529, 0.499, 0.198}, {0.399, 0.0, 0.379}, {0.696, 0.776, 0.0},
                 {0.3, 0.594, 0.148},   {1.0, 0.48, 0.208},   {0.434, 0.177, 0.337}, {0.0, 0.758, 0.288}};
  mesh.hexes = {{0, 1, 2, 3, 4, 5, 6, 7}};
  REQUIRE(scaled_jacobian(mesh, 0) > 0);
  REQUIRE(centre_scaled_jacobian(mesh, 0) < 0);
  const std::vector<bool> fixed(8, false);
  const geometry::UntangleReport r = geometry::untangle(mesh, fixed);
  CHECK(r.inverted_before == 1);
  CHECK(r.inverted_after == 0);
  CHECK(centre_scaled_jacobian(mesh, 0) > 0);
  CHECK(scaled_jacobian(mesh, 0) > 0);
}

TEST_CASE("Schneiders' pyramid comes out of loom weave's pipeline with every scaled Jacobian positive") {
  // Before the global untangling: 48 hexes (no boundary layer), 13 of them <= 0.
  const QuadSurface surface = gen::schneiders();
  const pipeline::MeshingOptions options = pipeline::default_meshing_options();
  const auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  const pipeline::MeshingResult r = pipeline::mesh_surface(surface, rules, options);
  REQUIRE(r.combinatorially_valid());
  CHECK(r.mesh->hexes.size() <= 88);
  CHECK(r.check->quality.below_zero == 0);
  CHECK(r.check->quality.min_scaled_jacobian > 0);
}
