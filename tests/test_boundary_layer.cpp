// Pillowing the boundary layer (src/geometry/boundary_layer.hpp) and its use
// by the pipeline: the boundary is unchanged, no hex keeps two boundary faces,
// and the flat-capped cylinder, whose woven hexes have corners locked flat on
// the caps, comes out valid.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <map>

#include <nlohmann/json.hpp>

#include "engine/rule_compiler.hpp"
#include "src/check/hex_boundary.hpp"
#include "src/check/hex_topology.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/geometry/placement.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

/// For each hex, how many of its faces no other hex has.
std::vector<int> boundary_faces_per_hex(const HexMesh& mesh) {
  std::map<std::array<std::uint32_t, 4>, int> count;
  auto key = [&](const Hex& h, const std::array<int, 4>& f) {
    std::array<std::uint32_t, 4> k{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
    std::sort(k.begin(), k.end());
    return k;
  };
  for (const Hex& h : mesh.hexes)
    for (const auto& f : kHexFaceCorners) ++count[key(h, f)];
  std::vector<int> per_hex;
  for (const Hex& h : mesh.hexes) {
    int n = 0;
    for (const auto& f : kHexFaceCorners) n += count[key(h, f)] == 1;
    per_hex.push_back(n);
  }
  return per_hex;
}

std::vector<engine::Rule> shipped_rules() {
  return engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
}

}  // namespace

TEST_CASE("a grid's boundary layer: one hex per boundary quad, the boundary unchanged") {
  HexMesh mesh = gen::hexgrid(2, 3, 1);
  const HexMesh original = mesh;
  const QuadSurface surface = hex_mesh_boundary(original);
  std::vector<bool> fixed(mesh.points.size(), false);
  std::vector<std::uint32_t> surface_node;
  hex_mesh_boundary(original, &surface_node);
  for (auto v : surface_node) fixed[v] = true;

  const auto layer = geometry::pillow_boundary_layer(mesh, fixed);
  CHECK(layer.hexes_added == surface.quads.size());
  CHECK(layer.hexes_added == 2 * (2 * 3 + 3 * 1 + 1 * 2));
  CHECK(layer.nodes_added == surface.points.size());
  CHECK(mesh.hexes.size() == original.hexes.size() + layer.hexes_added);
  CHECK(mesh.points.size() == original.points.size() + layer.nodes_added);
  CHECK(fixed.size() == mesh.points.size());
  CHECK(std::count(fixed.begin(), fixed.end(), true) == static_cast<long>(surface_node.size()));
  for (std::size_t i = 0; i < original.points.size(); ++i)
    CHECK(std::memcmp(&mesh.points[i], &original.points[i], sizeof(Vec3)) == 0);
  for (int n : boundary_faces_per_hex(mesh)) CHECK(n <= 1);

  // The copies start on the boundary (zero-thickness hexes); placement moves them.
  const auto placed = geometry::place_nodes(mesh, fixed);
  CHECK(placed.below_zero_after == 0);
  const ValidityReport check = check_hex_mesh(mesh, &surface);
  CHECK_MESSAGE(check.valid(), (check.first_failure() ? check.first_failure()->detail : std::string("SJ <= 0")));
  CHECK(check.quality.min_scaled_jacobian > 0.2);
}

TEST_CASE("the pipeline pillows the cylinder's boundary layer and the cylinder comes out valid") {
  const QuadSurface surface = gen::cylinder(4, 6);
  auto r = pipeline::mesh_surface(surface, shipped_rules(), {});
  REQUIRE_MESSAGE(r.mesh.has_value(), r.failure);
  REQUIRE(r.check.has_value());
  CHECK(r.check->valid());
  CHECK(r.check->quality.below_zero == 0);
  CHECK(r.check->quality.min_scaled_jacobian > 0.2);
  CHECK(r.boundary_layer.hexes_added == surface.quads.size());
  CHECK(r.mesh->hexes.size() == r.stc.hexes() + surface.quads.size());
  for (int n : boundary_faces_per_hex(*r.mesh)) CHECK(n <= 1);
  // Without the layer, the woven hexes with two faces on a cap are flat.
  auto raw = stc::build_from_surface(surface);
  REQUIRE(weave::weave(raw, shipped_rules(), {}).closed);
  std::vector<bool> on_boundary;
  HexMesh unpillowed = stc::to_hex_mesh(raw, &on_boundary);
  const auto locked = geometry::locked_corners(unpillowed, on_boundary);
  CHECK(locked.invalid > 0);
  CHECK(locked.least <= 0);
  CHECK(weave::smooth_interior(unpillowed, on_boundary).locked_invalid == locked.invalid);
  // With the layer nothing is locked: every corner has a free node.
  geometry::pillow_boundary_layer(unpillowed, on_boundary);
  CHECK(geometry::locked_corners(unpillowed, on_boundary).below_0_2 == 0);
}

TEST_CASE("a mesh that placement makes good enough keeps its woven hexes") {
  for (const QuadSurface& surface : {gen::lshape(4), gen::cubesphere(3), gen::tet4()}) {
    auto r = pipeline::mesh_surface(surface, shipped_rules(), {});
    REQUIRE_MESSAGE(r.mesh.has_value(), r.failure);
    CHECK(r.check->valid());
    CHECK(r.boundary_layer.hexes_added == 0);
    CHECK(r.mesh->hexes.size() == r.stc.hexes());
  }
}

TEST_CASE("loom weave says when it pillowed the boundary layer, and the report counts its hexes") {
  loom::test::ScratchDir dir("layer");
  REQUIRE(loom::test::run_cli("gen cylinder 4 6 -o " + (dir / "c.obj").string()).status == 0);
  const auto r = loom::test::run_cli("weave " + (dir / "c.obj").string() + " -o " + (dir / "c.vtk").string() +
                                     " --report " + (dir / "c.json").string());
  REQUIRE_MESSAGE(r.status == 0, r.err);  // 0: every scaled Jacobian > 0 (it was 3 without the layer)
  CHECK(r.out.find("woven: 352 hexes") == 0);
  CHECK(r.out.find("boundary layer pillowed (+192 hexes)") != std::string::npos);
  const auto j = nlohmann::json::parse(loom::test::slurp(dir / "c.json"));
  CHECK(j["woven_hexes"] == 160);
  CHECK(j["hexes"] == 352);  // what was written: the woven hexes and the layer
  CHECK(j["hex_sources"]["woven"] == 160);
  CHECK(j["hex_sources"]["pillow"] == 192);
  CHECK(j["boundary_layer_hexes"] == 192);
  CHECK(j["below_zero"] == 0);
  CHECK(j["quality_by_source"]["woven"]["hexes"] == 160);
  CHECK(j["quality_by_source"]["pillow"]["hexes"] == 192);
  CHECK(j["quality_by_source"]["pillow"]["inverted"] == 0);
  CHECK(!j["quality_by_source"].contains("searched"));  // a source with no hexes is left out
  // Woven core and layer: 80 interior edges of three hexes, every other one of four.
  CHECK(j["interior_edge_valences"].size() == 2);
  CHECK(j["interior_edge_valences"]["3"] == 80);
  CHECK(j["irregular_interior_edges"] == 80);
  CHECK(loom::test::run_cli("check " + (dir / "c.vtk").string() + " --boundary " + (dir / "c.obj").string()).status == 0);
}

TEST_CASE("a boundary layer taken back leaves the hexes as they were; anything else is refused") {
  const HexMesh grid = gen::hexgrid(3, 2, 2);
  HexMesh pillowed = grid;
  std::vector<bool> fixed(grid.points.size(), true);
  const auto layer = geometry::pillow_boundary_layer(pillowed, fixed);
  REQUIRE(layer.hexes_added == 32);
  HexMesh taken_back = pillowed;
  REQUIRE(geometry::remove_boundary_layer(taken_back, layer.hexes_added));
  CHECK(taken_back.hexes == grid.hexes);
  // The last hexes of a grid are no layer: their "copies" are ordinary nodes.
  HexMesh plain = grid;
  CHECK(!geometry::remove_boundary_layer(plain, 4));
  CHECK(plain.hexes == grid.hexes);
  CHECK(!geometry::remove_boundary_layer(plain, grid.hexes.size() + 1));
}
