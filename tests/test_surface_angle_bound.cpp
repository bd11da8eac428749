// The surface's ceiling on quality (check/surface_angle_bound.hpp): what it
// measures, that it bounds the hexes behind the surface, and how loom weave
// reports it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "src/check/hex_boundary.hpp"
#include "src/check/surface_angle_bound.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/io/surface_io.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

/// x += k y: quads in the xy planes become parallelograms whose sine is 1 / sqrt(1 + k^2).
void shear(std::vector<Vec3>& points, double k) {
  for (Vec3& p : points) p[0] += k * p[1];
}

double least_scaled_jacobian(const HexMesh& mesh) {
  double least = 1;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) least = std::min(least, scaled_jacobian(mesh, h));
  return least;
}

}  // namespace

TEST_CASE("surface angle bound: squares give 1; a sheared box gives the sine of its parallelograms") {
  HexMesh grid = gen::hexgrid(3, 2, 2);
  const SurfaceAngleBound square = surface_angle_bound(hex_mesh_boundary(grid));
  CHECK(square.least_sine == doctest::Approx(1.0));
  CHECK(square.mean_sine == doctest::Approx(1.0));
  CHECK(square.quads_below_0_2 == 0);

  shear(grid.points, 5.0);
  const QuadSurface boundary = hex_mesh_boundary(grid);
  const SurfaceAngleBound sheared = surface_angle_bound(boundary);
  const double sine = 1 / std::sqrt(26.0);
  CHECK(sheared.least_sine == doctest::Approx(sine));
  // The two xy faces hold 3 x 2 quads each; the other faces keep right angles.
  CHECK(sheared.quads_below_0_2 == 12);
  CHECK(sheared.mean_sine == doctest::Approx((12 * sine + (boundary.quads.size() - 12)) / boundary.quads.size()));
  // An affine grid reaches its ceiling, and nothing goes above it.
  CHECK(least_scaled_jacobian(grid) == doctest::Approx(sine));

  // The interior cannot lift the minimum: move an inner node anywhere.
  for (double dx : {-0.3, 0.0, 0.4})
    for (double dy : {-0.2, 0.3}) {
      HexMesh moved = gen::hexgrid(3, 2, 2);
      shear(moved.points, 5.0);
      for (Vec3& p : moved.points)  // the two inner nodes, (1,1,1) and (2,1,1) before the shear
        if (p[1] == 1 && p[2] == 1 && p[0] > 5.5 && p[0] < 7.5) p = {p[0] + dx, p[1] + dy, p[2]};
      REQUIRE(surface_angle_bound(hex_mesh_boundary(moved)).least_sine == doctest::Approx(sheared.least_sine));
      CHECK(least_scaled_jacobian(moved) <= sheared.least_sine + 1e-12);
    }
}

TEST_CASE("surface angle bound: a degenerate quad bounds at 0; no quads, at 1") {
  QuadSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};  // three corners on a line
  s.quads = {{0, 1, 2, 3}};
  const SurfaceAngleBound b = surface_angle_bound(s);
  CHECK(b.least_sine == doctest::Approx(0.0));
  CHECK(b.quads_below_0_2 == 1);
  CHECK(surface_angle_bound(QuadSurface{}).least_sine == 1);
}

TEST_CASE("loom weave says when the surface caps the quality below 0.2, and the report gives the bound") {
  test::ScratchDir dir("surface-bound");
  REQUIRE(test::run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  QuadSurface box = read_surface(dir / "box.obj");
  shear(box.points, 5.0);
  write_surface(dir / "sheared.obj", box);
  const auto r = test::run_cli("weave " + (dir / "sheared.obj").string() + " -o " + (dir / "sheared.vtk").string() +
                               " --report " + (dir / "sheared.json").string());
  REQUIRE(r.status == 0);
  CHECK(r.err.find("loom: note: 8 quads of the surface have a corner angle whose sine is below 0.2 (the least "
                   "0.196): no hex mesh bounded by it has every scaled Jacobian above 0.196") != std::string::npos);
  const auto report = nlohmann::json::parse(test::slurp(dir / "sheared.json"));
  CHECK(report["surface_angle_bound"]["least_sine"].get<double>() == doctest::Approx(1 / std::sqrt(26.0)));
  CHECK(report["surface_angle_bound"]["quads_below_0_2"] == 8);
  CHECK(report["min_scaled_jacobian"].get<double>() <= report["surface_angle_bound"]["least_sine"].get<double>() + 1e-9);

  // An unsheared box says nothing of it.
  const auto plain = test::run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "box.vtk").string());
  REQUIRE(plain.status == 0);
  CHECK(plain.err.find("loom: note") == std::string::npos);
}
