// Solids with handles meshed as balls: cut along disks spanning their
// meridians, the ball meshed, the disks glued back.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "engine/rule_compiler.hpp"
#include "src/cad/cad_part.hpp"
#include "src/gen/generators.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/pipeline/handle_cuts.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/stc/build.hpp"

using namespace loom;

namespace {

std::vector<engine::Rule> shipped_rules() {
  return engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
}

pipeline::CutSurface cut(const QuadSurface& surface) {
  std::string why_not;
  auto c = pipeline::cut_into_ball(surface, why_not);
  INFO(why_not);
  REQUIRE(c);
  return *c;
}

Vec3 glued_position(const pipeline::CutSurface& c, const QuadSurface& surface, std::uint32_t ball_node) {
  const std::uint32_t g = c.glued[ball_node];
  return g < surface.points.size() ? surface.points[g] : c.disk_points[g - surface.points.size()];
}

pipeline::MeshingResult mesh(const QuadSurface& surface) {
  return pipeline::mesh_surface(surface, shipped_rules(), pipeline::default_meshing_options());
}

}  // namespace

TEST_CASE("a torus cut along its meridian disk is an outward ball; every node glues back where it was") {
  for (auto [n, m] : {std::pair{6, 4}, {5, 6}, {4, 10}}) {
    CAPTURE(n);
    CAPTURE(m);
    const QuadSurface torus = gen::torus(n, m);
    const pipeline::CutSurface c = cut(torus);
    CHECK(c.disks == 1);
    const int a = m / 4, b = m / 2 - m / 4;
    CHECK(c.ball.quads.size() == torus.quads.size() + 2 * static_cast<std::size_t>(a * b));
    CHECK(c.disk_points.size() == static_cast<std::size_t>((a - 1) * (b - 1)));
    QuadSurface ball = c.ball;
    const SurfaceSummary summary = validate_surface(ball, "ball");
    CHECK(summary.genus == 0);
    CHECK(!summary.flipped);
    REQUIRE(c.glued.size() == c.ball.points.size());
    // The copies of a node are pushed apart, never onto each other.
    CHECK(std::set<Vec3>(c.ball.points.begin(), c.ball.points.end()).size() == c.ball.points.size());
    // A quarter of the meridian's shortest edge, at most a quarter of the longest.
    double longest = 0;
    for (const Quad& q : torus.quads)
      for (int k = 0; k < 4; ++k) longest = std::max(longest, norm(torus.points[q[k]] - torus.points[q[(k + 1) % 4]]));
    for (std::uint32_t v = 0; v < c.ball.points.size(); ++v)
      CHECK(norm(c.ball.points[v] - glued_position(c, torus, v)) <= 0.25 * longest + 1e-12);
  }
}

TEST_CASE("a double torus is cut twice, into a ball") {
  const QuadSurface two = gen::torus_chain(4, {4, 6});
  const pipeline::CutSurface c = cut(two);
  CHECK(c.disks == 2);
  QuadSurface ball = c.ball;
  CHECK(validate_surface(ball, "ball").genus == 0);
}

TEST_CASE("a cut refuses a meridian it cannot span: odd, short or not simple") {
  const QuadSurface torus = gen::torus(6, 4);
  std::string why_not;
  CHECK(!pipeline::cut_along_disk(torus, {0, 1, 2}, why_not));
  CHECK(why_not.find("3 edges") != std::string::npos);
  CHECK(!pipeline::cut_along_disk(torus, {0, 1, 0, 1}, why_not));
  CHECK(why_not.find("twice") != std::string::npos);
}

TEST_CASE("tori with an even meridian mesh through the cut, valid by criteria 1-6; N x 4 is the ring of N hexes") {
  for (int n : {3, 4, 7, 20})
    for (int m : {4, 6, 10}) {
      CAPTURE(n);
      CAPTURE(m);
      const auto r = mesh(gen::torus(n, m));
      REQUIRE(r.combinatorially_valid());
      CHECK(r.cut_disks == 1);
      // A thin ring too: its cut's two sides must not be pushed through its hexes.
      if (m == 4) CHECK(r.mesh->hexes.size() == static_cast<std::size_t>(n));
      if (m == 4 && n >= 4) CHECK(r.check->quality.min_scaled_jacobian > 0.7);
      CHECK(r.check->boundary_genus == 1);
    }
}

TEST_CASE("genus 2: the solid whose meridians are all even meshes, cut along two disks") {
  SUBCASE("two tori joined by a tube") {
    const auto r = mesh(gen::torus_chain(4, {4, 4}));
    REQUIRE(r.combinatorially_valid());
    CHECK(r.cut_disks == 2);
    CHECK(r.check->boundary_genus == 2);
  }
  SUBCASE("a plate with two holes, exactly its grid of cubes") {
    for (int k : {1, 2}) {
      CAPTURE(k);
      const auto r = mesh(gen::plate_with_holes(2, k));
      REQUIRE(r.combinatorially_valid());
      CHECK(r.cut_disks == 2);
      CHECK(r.check->boundary_genus == 2);
      CHECK(r.mesh->hexes.size() == static_cast<std::size_t>(13 * k * k * k));
      CHECK(r.source == std::vector(r.mesh->hexes.size(), closure::HexSource::woven));
      CHECK(r.check->quality.min_scaled_jacobian > 0.9);
    }
  }
}

TEST_CASE("a ring of bosses is woven exactly, its grid of cubes, through one cut") {
  // N bosses on a ring of 4 (L - 1) cubes: 8 + 1, 12 + 4 and 24 + 8 cubes.
  for (auto [bosses, cubes] : {std::pair{1, 9}, {4, 16}, {8, 32}}) {
    CAPTURE(bosses);
    const auto r = mesh(gen::ring_of_bosses(bosses, 1));
    REQUIRE(r.combinatorially_valid());
    CHECK(r.cut_disks == 1);
    CHECK(r.mesh->hexes.size() == static_cast<std::size_t>(cubes));
    CHECK(r.source == std::vector(r.mesh->hexes.size(), closure::HexSource::woven));
    CHECK(r.check->quality.min_scaled_jacobian > 0.9);
  }
}

TEST_CASE("where a short meridian turns round one quad at every node, another short one takes the disk") {
  // The bundled flange at size 11: after some cuts, the one meridian left is a
  // 16-edge staircase round a bolt hole's bar, with no node for a disk's corner.
  const auto flange =
      cad::quad_surface_of_part(std::filesystem::path(LOOM_SOURCE_DIR) / "examples" / "flange.geo", 11.0);
  const pipeline::CutSurface c = cut(flange.surface);
  CHECK(c.disks == 5);
  QuadSurface ball = c.ball;
  CHECK(validate_surface(ball, "the cut flange").genus == 0);
}

TEST_CASE("more short meridians than the basis: distinct, each one of a torus's tube circles") {
  const QuadSurface torus = gen::torus(6, 4);
  const MeridianReport report = find_meridians(torus, 10);
  REQUIRE(report.alternatives.size() == 6);  // the six tube circles, no more: the rest are longer
  std::set<std::set<std::uint32_t>> distinct;
  for (const NodeCycle& cycle : report.alternatives) {
    CHECK(cycle.size() == 4);
    distinct.emplace(cycle.begin(), cycle.end());
  }
  CHECK(distinct.size() == 6);
}
