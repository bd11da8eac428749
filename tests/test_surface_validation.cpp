// validate_surface: each rejection, in the documented order, naming the element;
// welding, dropping unused nodes, outward orientation and genus.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;

using loom::test::unit_cube;

namespace {

QuadSurface shifted(QuadSurface s, Vec3 by, std::uint32_t index_offset) {
  for (Vec3& p : s.points) p = p + by;
  for (Quad& q : s.quads)
    for (auto& n : q) n += index_offset;
  return s;
}

QuadSurface joined(const QuadSurface& a, const QuadSurface& b) {
  QuadSurface s = a;
  s.points.insert(s.points.end(), b.points.begin(), b.points.end());
  s.quads.insert(s.quads.end(), b.quads.begin(), b.quads.end());
  return s;
}

// An n x m grid of quads wrapped around a torus (radii 3 and 1), outward.
QuadSurface quad_torus(std::uint32_t n, std::uint32_t m) {
  QuadSurface s;
  const double two_pi = 2 * std::numbers::pi;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j) {
      double u = two_pi * i / n, v = two_pi * j / m;
      s.points.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto id = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * m + (j % m); };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j) s.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

std::string rejection(QuadSurface s, const SurfaceCheckOptions& options = {}) {
  try {
    validate_surface(s, "S", options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the unit cube is valid: 8 nodes, 12 edges, 6 quads, genus 0, already outward") {
  QuadSurface s = unit_cube();
  SurfaceSummary summary = validate_surface(s, "cube");
  CHECK(summary.nodes == 8);
  CHECK(summary.edges == 12);
  CHECK(summary.quads == 6);
  CHECK(summary.genus == 0);
  CHECK_FALSE(summary.flipped);
  CHECK(summary.welded_nodes == 0);
  CHECK(summary.unused_nodes == 0);
  CHECK(s.quads == unit_cube().quads);
}

TEST_CASE("an inward surface is flipped to face outward") {
  QuadSurface s = unit_cube();
  for (Quad& q : s.quads) std::reverse(q.begin(), q.end());
  SurfaceSummary summary = validate_surface(s, "cube");
  CHECK(summary.flipped);
  // Reversing each quad again gives the outward cube, up to the starting corner.
  for (std::size_t i = 0; i < s.quads.size(); ++i) {
    Quad q = s.quads[i], expected = unit_cube().quads[i];
    std::rotate(q.begin(), std::find(q.begin(), q.end(), expected[0]), q.end());
    CHECK(q == expected);
  }
}

TEST_CASE("unused nodes are dropped and the quads renumbered") {
  QuadSurface s = shifted(unit_cube(), {0, 0, 0}, 1);
  s.points.insert(s.points.begin(), Vec3{5, 5, 5});
  s.points.push_back({7, 7, 7});
  SurfaceSummary summary = validate_surface(s, "cube");
  CHECK(summary.unused_nodes == 2);
  CHECK(s.points == unit_cube().points);
  CHECK(s.quads == unit_cube().quads);
}

TEST_CASE("a torus has genus 1 and a two-holed surface has genus 2") {
  QuadSurface torus = quad_torus(8, 6);
  SurfaceSummary summary = validate_surface(torus, "torus");
  CHECK(summary.genus == 1);
  CHECK(summary.edges == 2 * summary.quads);
  CHECK_FALSE(summary.flipped);

  // Reversed, the same torus is flipped back.
  QuadSurface inward = quad_torus(8, 6);
  for (Quad& q : inward.quads) std::reverse(q.begin(), q.end());
  CHECK(validate_surface(inward, "torus").flipped);
}

TEST_CASE("the literature's test surfaces are valid spheres") {
  for (std::string file : {"good/schneiders-pyramid.obj", "good/tet-split.obj"}) {
    CAPTURE(file);
    QuadSurface s = read_surface(test::data(file));
    SurfaceSummary summary = validate_surface(s, file);
    CHECK(summary.genus == 0);
    CHECK_FALSE(summary.flipped);
    CHECK(summary.nodes + summary.quads == summary.edges + 2);
  }
}

TEST_CASE("each rejection names the problem and the element") {
  SUBCASE("no quads") { CHECK(contains(rejection(QuadSurface{}), "S: the surface has no quads")); }
  SUBCASE("NaN coordinate") {
    QuadSurface s = unit_cube();
    s.points[6][1] = std::nan("");
    CHECK(contains(rejection(s), "node 6 has a NaN coordinate"));
  }
  SUBCASE("index out of range") {
    QuadSurface s = unit_cube();
    s.quads[2][3] = 40;
    CHECK(contains(rejection(s), "quad 2 refers to node 40, but there are only 8 nodes"));
  }
  SUBCASE("degenerate quad") {
    QuadSurface s = unit_cube();
    s.quads[4] = {2, 3, 7, 3};
    CHECK(contains(rejection(s), "degenerate quad 4 (nodes 2 3 7 3) uses node 3 twice"));
  }
  SUBCASE("duplicated quad, in any rotation or direction") {
    QuadSurface s = unit_cube();
    s.quads.push_back({5, 1, 2, 6});
    CHECK(contains(rejection(s), "duplicated quads 3 and 6"));
  }
  SUBCASE("coincident nodes") {
    QuadSurface s = unit_cube();
    s.points.push_back(s.points[0]);
    s.quads[5] = {3, 8, 4, 7};
    std::string message = rejection(s);
    CHECK(contains(message, "coincident nodes 0 and 8 are both at (0, 0, 0)"));
    CHECK(contains(message, "weld them"));
  }
  SUBCASE("non-manifold edge: two cubes sharing an edge") {
    // The second cube sits diagonally, sharing the first cube's edge 2-6.
    QuadSurface second = shifted(unit_cube(), {1, 1, 0}, 8);
    QuadSurface s = joined(unit_cube(), second);
    // Its corners at (1,1,0) and (1,1,1) are the first cube's nodes 2 and 6.
    for (Quad& q : s.quads)
      for (auto& n : q) n = n == 8 ? 2 : n == 12 ? 6 : n;
    std::string message = rejection(s);
    CHECK(contains(message, "non-manifold edge: the edge between node 2 at (1, 1, 0) and node 6 at (1, 1, 1)"));
    CHECK(contains(message, "shared by 4 quads"));
  }
  SUBCASE("open boundary, reported before the odd count") {
    QuadSurface s = unit_cube();
    s.quads.pop_back();
    std::string message = rejection(s);
    CHECK(contains(message, "open boundary: 4 edges border only one quad"));
  }
  SUBCASE("non-manifold vertex: two cubes sharing a corner") {
    QuadSurface s = joined(unit_cube(), shifted(unit_cube(), {1, 1, 1}, 8));
    for (Quad& q : s.quads)
      for (auto& n : q) n = n == 8 ? 6 : n;
    std::string message = rejection(s);
    CHECK(contains(message, "non-manifold vertex: the quads around node 6 at (1, 1, 1) form 2 separate fans"));
  }
  SUBCASE("inconsistent orientation") {
    QuadSurface s = unit_cube();
    std::reverse(s.quads[3].begin(), s.quads[3].end());
    std::string message = rejection(s);
    CHECK(contains(message, "inconsistent orientation: quads 0 and 3 both run from node 2 to node 1"));
  }
  SUBCASE("two components") {
    QuadSurface s = joined(unit_cube(), shifted(unit_cube(), {3, 0, 0}, 8));
    CHECK(contains(rejection(s), "2 separate components (quad 0 is in the first, quad 6 in the second)"));
  }
  SUBCASE("odd quad count: the 7-quad cube") {
    QuadSurface s = unit_cube();
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.5, 1}};
    s.quads = {{0, 2, 3, 1}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}, {4, 5, 7, 8}, {4, 8, 7, 6}};
    std::string message = rejection(s);
    CHECK(contains(message,
                   "7 quads, an odd number: no hex mesh can exist: each chord uses two boundary quads; an "
                   "odd count can never bound a hex mesh"));
    CHECK(contains(message, "subdivid"));
  }
}

TEST_CASE("welding merges coincident and nearly coincident nodes only when asked") {
  QuadSurface s = unit_cube();
  s.points.push_back(s.points[0] + Vec3{1e-12, 0, 0});
  s.quads[5] = {3, 8, 4, 7};
  // Not identical, so not "coincident": without welding the cube is open at node 8.
  CHECK(contains(rejection(s), "open boundary"));
  SurfaceCheckOptions weld;
  weld.weld = true;
  QuadSurface welded = s;
  SurfaceSummary summary = validate_surface(welded, "S", weld);
  CHECK(summary.welded_nodes == 1);
  CHECK(summary.unused_nodes == 0);
  CHECK(summary.nodes == 8);
  CHECK(welded.quads == unit_cube().quads);

  // A gap larger than the tolerance is not closed.
  weld.weld_tolerance = 1e-14;
  CHECK(contains(rejection(s, weld), "open boundary"));
}

TEST_CASE("welding that collapses a quad reports it") {
  QuadSurface s = unit_cube();
  s.points[5] = s.points[1];  // quads 2 and 3 now have two nodes in one place
  SurfaceCheckOptions weld;
  weld.weld = true;
  CHECK(contains(rejection(s, weld), "after welding, degenerate quad 2"));
}
