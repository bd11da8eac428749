// How deep a mesh goes and how thick its part is (check/depth.hpp), as the
// report gives them.
#include <doctest/doctest.h>

#include <algorithm>

#include "src/check/depth.hpp"
#include "src/gen/generators.hpp"

using namespace loom;

TEST_CASE("a hex's depth is the most edges any of its corners is from the boundary") {
  HexMesh grid = gen::hexgrid(4, 4, 4);
  DepthProfile p = depth_profile(grid);
  // The eight hexes round the centre node (two edges in) are 2 deep; the rest 1.
  REQUIRE(p.hexes.size() == 3);
  CHECK(p.hexes[1] == 56);
  CHECK(p.hexes[2] == 8);
  CHECK(p.deepest() == 2);
  CHECK(p.inverted == std::vector<std::size_t>{0, 0, 0});

  // Turned inside out, a hex counts as inverted at its depth.
  auto deep = std::find_if(grid.hexes.begin(), grid.hexes.end(), [&](const Hex& h) {
    const Vec3& centre = grid.points[h[6]];
    return centre[0] == 2 && centre[1] == 2 && centre[2] == 2;  // its far corner is the centre
  });
  REQUIRE(deep != grid.hexes.end());
  std::swap((*deep)[1], (*deep)[3]);
  std::swap((*deep)[5], (*deep)[7]);
  p = depth_profile(grid);
  CHECK(p.inverted == std::vector<std::size_t>{0, 0, 1});

  CHECK(depth_profile(HexMesh{}).hexes.empty());
}

TEST_CASE("half the part's thickness, in the surface's edge lengths") {
  // A 4 x 2 x 2 bar of unit quads: 2 from its ends to the middle, 1 elsewhere.
  const QuadSurface bar = gen::box(4, 2, 2);
  SurfaceThickness t = surface_half_thickness(bar);
  CHECK(t.rays == bar.quads.size());
  CHECK(t.max == doctest::Approx(2.0));
  CHECK(t.median == doctest::Approx(1.0));
  // A sample of rays: every fourth quad.
  t = surface_half_thickness(bar, bar.quads.size() / 4);
  CHECK(t.rays == bar.quads.size() / 4);

  // Inside out, every ray leaves the part: nothing is measured.
  QuadSurface turned = bar;
  for (Quad& q : turned.quads) std::swap(q[1], q[3]);
  t = surface_half_thickness(turned);
  CHECK(t.rays == 0);
  CHECK(t.max == 0);
}
