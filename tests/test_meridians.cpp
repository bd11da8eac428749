// The existence test for hex meshes of solids with handles (Erickson 2014):
// linking numbers, the surface's homology, the meridians and the refusal.
#include <algorithm>
#include <filesystem>

#include <doctest/doctest.h>

#include "src/check/hex_boundary.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/linking.hpp"
#include "src/mesh/meridians.hpp"
#include "src/mesh/surface_homology.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

std::vector<Vec3> square(Vec3 centre, int plane) {  // side 2, in the plane normal to axis `plane`
  std::vector<Vec3> corners;
  for (auto [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    Vec3 p = centre;
    p[(plane + 1) % 3] += a;
    p[(plane + 2) % 3] += b;
    corners.push_back(p);
  }
  return corners;
}

// The boundary of the unit cubes of an a x b x c grid whose centres `keep`.
template <class Keep>
QuadSurface carved_boundary(int a, int b, int c, Keep keep) {
  HexMesh grid = gen::hexgrid(a, b, c);
  std::erase_if(grid.hexes, [&](const Hex& h) {
    Vec3 centre{0, 0, 0};
    for (std::uint32_t v : h) centre = centre + 0.125 * grid.points[v];
    return !keep(centre);
  });
  return hex_mesh_boundary(grid);
}

std::string refusal(QuadSurface s) {
  try {
    validate_surface(s, "S");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("linking numbers of squares: a Hopf link is 1, apart or side by side 0") {
  const auto ring = square({0, 0, 0}, 2);
  CHECK(std::abs(*linking_number(ring, square({1, 0, 0}, 1))) == 1);
  CHECK(*linking_number(ring, square({5, 0, 0}, 1)) == 0);
  CHECK(*linking_number(ring, square({0, 0, 0.5}, 2)) == 0);
  // Every generic direction gives the same number, up to the orientation.
  for (Vec3 d : {Vec3{0.3, 0.4, 0.86}, Vec3{-0.7, 0.2, 0.3}, Vec3{0.1, -0.9, 0.2}})
    if (auto lk = linking_number_along(ring, square({1, 0, 0}, 1), d)) CHECK(std::abs(*lk) == 1);
}

TEST_CASE("tree-cotree: 2g basis cycles, each its own class; quads bound") {
  for (auto [surface, genus] : {std::pair{gen::box(2, 3, 1), 0}, {gen::torus(5, 4), 1},
                                {gen::torus_chain(4, {3, 5, 4}), 3}}) {
    CAPTURE(genus);
    const SurfaceHomology h = surface_homology(surface);
    REQUIRE(h.rank() == static_cast<std::size_t>(2 * genus));
    auto class_of_walk = [&](const std::vector<std::uint32_t>& walk) {
      HomologyClass c(h.words, 0);
      for (std::size_t k = 0; k < walk.size(); ++k) {
        const std::uint32_t a = std::min(walk[k], walk[(k + 1) % walk.size()]),
                            b = std::max(walk[k], walk[(k + 1) % walk.size()]);
        const auto e = std::find(h.edges.ends.begin(), h.edges.ends.end(), std::array{a, b}) - h.edges.ends.begin();
        REQUIRE(static_cast<std::size_t>(e) < h.edges.ends.size());
        for (std::size_t w = 0; w < h.words; ++w) c[w] ^= h.class_of_edge(e)[w];
      }
      return c;
    };
    for (std::size_t i = 0; i < h.rank(); ++i) {
      HomologyClass unit(h.words, 0);
      unit[i / 64] |= std::uint64_t{1} << (i % 64);
      CHECK(class_of_walk(h.cycles[i]) == unit);
    }
    for (const Quad& q : surface.quads)
      CHECK(class_of_walk({q.begin(), q.end()}) == HomologyClass(h.words, 0));
  }
}

TEST_CASE("a torus's meridian is its tube's circle, not the circle round the axis") {
  SUBCASE("4 x 4: one meridian of 4 edges, even") {
    const MeridianReport r = find_meridians(gen::torus(4, 4));
    CHECK(r.determined);
    REQUIRE(r.meridians.size() == 1);
    CHECK(r.meridians[0].size() == 4);
    CHECK_FALSE(r.odd);
  }
  SUBCASE("4 x 3: the tube's 3 edges are odd") {
    const MeridianReport r = find_meridians(gen::torus(4, 3));
    REQUIRE(r.odd);
    CHECK(r.odd->size() == 3);
  }
  SUBCASE("3 x 4: 3 edges round the axis bound outside only, so a mesh may exist") {
    const MeridianReport r = find_meridians(gen::torus(3, 4));
    CHECK(r.determined);
    CHECK_FALSE(r.odd);
    REQUIRE(r.meridians.size() == 1);
    CHECK(r.meridians[0].size() == 4);
  }
}

TEST_CASE("the boundary of a hex mesh with holes passes: its meridians are even") {
  // A 5 x 3 x 1 plate with two holes, and a 3 x 3 x 2 ring.
  const QuadSurface plate = carved_boundary(5, 3, 1, [](Vec3 c) { return !(c[1] == 1.5 && (c[0] == 1.5 || c[0] == 3.5)); });
  const QuadSurface ring = carved_boundary(3, 3, 2, [](Vec3 c) { return !(c[0] == 1.5 && c[1] == 1.5); });
  for (auto [surface, genus] : {std::pair{plate, 2}, {ring, 1}}) {
    CAPTURE(genus);
    const MeridianReport r = find_meridians(surface);
    CHECK(r.genus == genus);
    CHECK(r.determined);
    CHECK(r.meridians.size() == static_cast<std::size_t>(genus));
    for (const NodeCycle& m : r.meridians) CHECK(m.size() % 2 == 0);
    CHECK_FALSE(r.odd);
  }
}

TEST_CASE("a genus-2 surface with one odd meridian is refused, naming the cycle; all even passes") {
  CHECK(refusal(gen::torus_chain(4, {4, 4})) == "(accepted)");
  const std::string odd = refusal(gen::torus_chain(4, {4, 3}));
  CHECK(odd.find("S: no hex mesh can have this boundary") == 0);
  CHECK(odd.find("(3 edges) bounds a surface inside the solid and is odd") != std::string::npos);
  // Facing inward, the same surface is still judged from the inside.
  QuadSurface inward = gen::torus_chain(4, {3, 4, 4});
  for (Quad& q : inward.quads) std::reverse(q.begin(), q.end());
  CHECK(refusal(inward).find("(3 edges)") != std::string::npos);
  QuadSurface even = gen::torus_chain(6, {4, 6, 4});
  const SurfaceSummary s = validate_surface(even, "S");
  CHECK(s.genus == 3);
  REQUIRE(s.meridians.size() == 3);
  std::vector<std::size_t> lengths;
  for (const NodeCycle& m : s.meridians) lengths.push_back(m.size());
  std::sort(lengths.begin(), lengths.end());
  CHECK(lengths == std::vector<std::size_t>{4, 4, 6});
}

TEST_CASE("loom weave refuses an odd meridian with exit 2, one line, and writes nothing") {
  test::ScratchDir dir("meridians");
  REQUIRE(test::run_cli("gen torus 4 3 -o " + (dir / "t.obj").string()).status == 0);
  const auto r = test::run_cli("weave " + (dir / "t.obj").string() + " -o " + (dir / "t.vtk").string());
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find("no hex mesh can have this boundary") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "t.vtk"));
  const auto stc = test::run_cli("stc " + (dir / "t.obj").string());
  CHECK(stc.status == 2);
  REQUIRE(test::run_cli("gen double-torus 4 4 6 -o " + (dir / "d.obj").string()).status == 0);
  const auto text = test::run_cli("stc " + (dir / "d.obj").string());
  CHECK(text.out.find("genus 2\nmeridian ") != std::string::npos);
  CHECK(text.out.find("(6 edges)") != std::string::npos);
}
