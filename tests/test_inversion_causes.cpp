// Why hexes are inverted (src/geometry/inversion_causes.hpp): a locked corner,
// a crowded interior edge, or neither; and what loom weave says about them.
#include <doctest/doctest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/inversion_causes.hpp"
#include "tests/support.hpp"

using namespace loom;
using geometry::InversionCause;

namespace {

/// The node of `mesh` at `p`.
std::uint32_t node_at(const HexMesh& mesh, Vec3 p) {
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
    if (norm(mesh.points[v] - p) < 1e-12) return v;
  FAIL("no node there");
  return 0;
}

/// Two layers of six hexes round the z axis (a hexagonal prism cut into six
/// kites a layer): the axis is two interior edges of six hexes each, and its
/// middle node is the only node off the boundary.
HexMesh pie() {
  HexMesh m;
  const double pi = std::acos(-1.0);
  for (int layer = 0; layer < 3; ++layer) {
    const double z = layer;
    m.points.push_back({0, 0, z});
    for (int i = 0; i < 6; ++i) m.points.push_back({std::cos(i * pi / 3), std::sin(i * pi / 3), z});
    for (int i = 0; i < 6; ++i) m.points.push_back({std::cos((i + 0.5) * pi / 3), std::sin((i + 0.5) * pi / 3), z});
  }
  auto at = [](int layer, int k) { return static_cast<std::uint32_t>(13 * layer + k); };
  for (int layer = 0; layer < 2; ++layer)
    for (int i = 0; i < 6; ++i) {
      const int r = 1 + i, mid = 7 + i, next = 1 + (i + 1) % 6;
      m.hexes.push_back({at(layer, 0), at(layer, r), at(layer, mid), at(layer, next), at(layer + 1, 0),
                         at(layer + 1, r), at(layer + 1, mid), at(layer + 1, next)});
    }
  return m;
}

}  // namespace

TEST_CASE("an untangled mesh has no inverted hex to explain") {
  for (const HexMesh& m : {gen::hexgrid(2, 3, 1), pie()}) {
    const auto d = geometry::diagnose_inversions(m);
    CHECK(d.inverted() == 0);
    CHECK(d.cause.size() == m.hexes.size());
    for (auto c : d.cause) CHECK(c == InversionCause::none);
    CHECK(geometry::describe(d).empty());
  }
}

TEST_CASE("a corner whose four nodes are on the boundary is locked: no placement can fix it") {
  HexMesh cube = gen::hexgrid(1, 1, 1);
  // The whole hex is boundary; fold one top node below the bottom.
  cube.points[node_at(cube, {0, 0, 1})] = {0, 0, -1};
  REQUIRE(scaled_jacobian(cube, 0) <= 0);
  const auto d = geometry::diagnose_inversions(cube);
  CHECK(d.cause[0] == InversionCause::locked_corner);
  CHECK(d.of(InversionCause::locked_corner) == 1);
  CHECK(d.inverted() == 1);
  CHECK(geometry::describe(d) == "1 with a corner locked by the boundary (no placement can fix it)");
}

TEST_CASE("hexes inverted at a free node on an interior edge of six hexes are put down to that edge") {
  HexMesh m = pie();
  const std::uint32_t middle = node_at(m, {0, 0, 1});
  m.points[middle] = {3, 0.2, 1};  // far out past the rim, so the hexes on the far side fold
  const auto d = geometry::diagnose_inversions(m);
  REQUIRE(d.inverted() > 0);
  CHECK(d.of(InversionCause::crowded_edge) == d.inverted());
  CHECK(d.most_crowded == 6);
  for (std::size_t h = 0; h < m.hexes.size(); ++h)
    CHECK((d.cause[h] == InversionCause::crowded_edge) == (scaled_jacobian(m, h) <= 0));
  CHECK(geometry::describe(d).find("on interior edges of 6 hexes") != std::string::npos);
}

TEST_CASE("hexes inverted round regular interior edges have no cause to name") {
  HexMesh grid = gen::hexgrid(3, 3, 3);
  grid.points[node_at(grid, {1, 1, 1})] = {2.5, 2.5, 2.5};  // an interior node pulled past its neighbours
  const auto d = geometry::diagnose_inversions(grid);
  REQUIRE(d.inverted() > 0);
  CHECK(d.of(InversionCause::unexplained) == d.inverted());
  CHECK(d.most_crowded == 0);
}

TEST_CASE("loom weave names the causes: in its warning, the JSON report and the inversion_cause cell field") {
  test::ScratchDir dir("inversion-causes");
  REQUIRE(test::run_cli("gen randquad 22 --seed 1 -o " + (dir / "r.obj").string()).status == 0);
  const auto r = test::run_cli_unchecked("weave " + (dir / "r.obj").string() + " -o " + (dir / "r.vtk").string() + " --report " +
                               (dir / "r.json").string());
  REQUIRE(r.status == 3);  // closed, with hexes <= 0
  const auto report = nlohmann::json::parse(test::slurp(dir / "r.json"));
  const auto& causes = report.at("inversion_causes");
  const std::size_t named = causes.at("locked_corner").get<std::size_t>() + causes.at("crowded_edge").get<std::size_t>() +
                            causes.at("unexplained").get<std::size_t>();
  CHECK(named == report.at("below_zero").get<std::size_t>());
  CHECK(r.err.find("the cell field inversion_cause names them") != std::string::npos);
  const std::string vtk = test::slurp(dir / "r.vtk");
  CHECK(vtk.find("SCALARS inversion_cause int 1") != std::string::npos);
}
