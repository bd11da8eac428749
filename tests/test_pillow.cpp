// Pillowing, the operation the degeneracy rules call: a pillow sheet around a
// shrink set keeps every STC invariant and gives a valid hex mesh with the
// same boundary; a pinched node is split back into the surface nodes it
// stood for.
#include <doctest/doctest.h>

#include "src/check/hex_boundary.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/pillow.hpp"
#include "src/weave/smoothing.hpp"

using namespace loom;

namespace {

/// Primal construction, smoothing and the full check against `surface`.
ValidityReport dualize_and_check(const stc::Stc& s, const QuadSurface& surface) {
  std::vector<bool> on_boundary;
  HexMesh mesh = stc::to_hex_mesh(s, &on_boundary);
  weave::smooth_interior(mesh, on_boundary);
  return check_hex_mesh(mesh, &surface);
}

std::string first_failure(const ValidityReport& r) {
  auto* f = r.first_failure();
  return f ? f->name + ": " + f->detail : std::string();
}

}  // namespace

TEST_CASE("a pillow around any one hex of a 3x3x3 grid adds six hexes and stays valid") {
  HexMesh grid = gen::hexgrid(3, 3, 3);
  QuadSurface surface = hex_mesh_boundary(grid);
  for (std::size_t h = 0; h < 27; ++h) {
    CAPTURE(h);
    stc::Stc s = stc::build_from_hex_mesh(grid);
    std::size_t sheets = s.sheets();
    stc::Id hex = s.graph().members(s.ids().hex)[h];
    auto counts = weave::insert_pillow(s, std::span<const stc::Id>(&hex, 1));
    CHECK(counts.hexes == 6);
    CHECK(counts.chords == 3);
    CHECK(s.check_invariants() == "");
    CHECK(s.hexes() == 33);
    CHECK(s.sheets() == sheets + 1);
    auto report = dualize_and_check(s, surface);
    CHECK_MESSAGE(report.valid(), first_failure(report));
  }
}

TEST_CASE("a pillow around the star of a grid node, and around a whole grid, is valid") {
  HexMesh grid = gen::hexgrid(3, 2, 2);
  QuadSurface surface = hex_mesh_boundary(grid);
  stc::Stc s = stc::build_from_hex_mesh(grid);
  auto nodes = s.graph().members(s.ids().node);
  for (stc::Id n : {nodes.front(), nodes[5], nodes[13]}) {
    stc::Stc t = stc::build_from_hex_mesh(grid);
    auto star = weave::hexes_at_node(t, n);
    weave::insert_pillow(t, star);
    CHECK(t.check_invariants() == "");
    CHECK(weave::split_pinched_node(t, n) == 0);
    auto report = dualize_and_check(t, surface);
    CHECK_MESSAGE(report.valid(), first_failure(report));
  }
  auto all = s.graph().members(s.ids().hex);
  auto counts = weave::insert_pillow(s, all);
  CHECK(counts.hexes == surface.quads.size());
  CHECK(s.check_invariants() == "");
  auto report = dualize_and_check(s, surface);
  CHECK_MESSAGE(report.valid(), first_failure(report));
}

TEST_CASE("a pinched shrink set (two hexes sharing one edge only) is pillowed into a valid mesh") {
  // Hexes 0 and 3 of a 2x2x1 grid meet in one edge: around it the set has
  // two sectors, each ending in two faces of its boundary, so every element
  // there is copied once per sector.
  HexMesh grid = gen::hexgrid(2, 2, 1);
  stc::Stc s = stc::build_from_hex_mesh(grid);
  auto hexes = s.graph().members(s.ids().hex);
  std::vector<stc::Id> diagonal{hexes[0], hexes[3]};
  auto counts = weave::insert_pillow(s, diagonal);
  CHECK(counts.hexes == 12);
  CHECK(s.hexes() == 16);
  CHECK(s.check_invariants() == "");
  auto report = dualize_and_check(s, hex_mesh_boundary(grid));
  CHECK_MESSAGE(report.valid(), first_failure(report));
}

TEST_CASE("a through-3-cell (two boundary nodes made one) is pillowed and split back into two") {
  // A U of five hexes (a 3x2x1 grid without hex (1,1)); its two tips are
  // made to share the node (1,2,0) in place of their own corners (1,2,0)
  // and (2,2,0), as a seam between two boundary nodes leaves it.
  HexMesh u = gen::hexgrid(3, 2, 1);
  u.hexes.erase(u.hexes.begin() + 4);
  QuadSurface surface = hex_mesh_boundary(u);
  const std::uint32_t kept = 9, merged = 10;  // (1,2,0) and (2,2,0)
  HexMesh pinched = u;
  for (auto& p : pinched.hexes[4]) if (p == merged) p = kept;
  stc::Stc s = stc::build_from_hex_mesh(pinched);
  // The boundary faces of the second tip stood on (2,2,0).
  const auto& ids = s.ids();
  stc::Id node = stc::no_element;
  for (stc::Id f : s.graph().members(ids.face)) {
    if (!s.is_boundary(f) || s.graph().get(s.face_cell(f, 0), ids.hex_source) != 4) continue;
    for (unsigned k = 0; k < 4; ++k)
      if (s.graph().get(s.face_node(f, k), ids.node_point) == static_cast<std::int32_t>(kept)) {
        s.boundary_points()[static_cast<std::size_t>(s.boundary_index(f))][k] = merged;
        node = s.face_node(f, k);
      }
  }
  REQUIRE(node != stc::no_element);
  {
    std::vector<bool> on_boundary;
    HexMesh before = stc::to_hex_mesh(s, &on_boundary);
    CHECK_FALSE(check_hex_mesh(before, &surface).combinatorial_valid());
  }
  auto star = weave::hexes_at_node(s, node);
  CHECK(star.size() == 2);
  weave::insert_pillow(s, star);
  CHECK(weave::split_pinched_node(s, node) == 1);
  CHECK(s.check_invariants() == "");
  CHECK(s.hexes() == 5 + 12);
  auto report = dualize_and_check(s, surface);
  CHECK_MESSAGE(report.combinatorial_valid(), first_failure(report));
  CHECK_MESSAGE(report.valid(), first_failure(report));
}
