// check_hex_mesh: valid meshes pass, and each kind of breakage is caught by the
// criterion that names it.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "src/check/hex_boundary.hpp"
#include "src/check/hex_sheets.hpp"
#include "src/check/hex_topology.hpp"
#include "src/check/validity.hpp"
#include "src/check/verdict.hpp"
#include "src/gen/generators.hpp"

using namespace loom;

namespace {

/// Numbers of the failed criteria, in order.
std::vector<int> failures(const ValidityReport& r) {
  std::vector<int> numbers;
  for (const auto& c : r.criteria)
    if (!c.passed) numbers.push_back(c.number);
  return numbers;
}

const CriterionResult& criterion(const ValidityReport& r, int number) {
  for (const auto& c : r.criteria)
    if (c.number == number) return c;
  FAIL("criterion ", number, " missing");
  return r.criteria.front();
}

/// hexgrid(a,b,c) keeping only the cells for which keep(i,j,k) holds.
template <class Keep>
HexMesh carved_grid(int a, int b, int c, Keep keep) {
  HexMesh m = gen::hexgrid(a, b, c);
  std::vector<Hex> kept;
  for (int k = 0; k < c; ++k)
    for (int j = 0; j < b; ++j)
      for (int i = 0; i < a; ++i)
        if (keep(i, j, k)) kept.push_back(m.hexes[i + a * (j + b * k)]);
  m.hexes = kept;
  return m;
}

}  // namespace

TEST_CASE("local tables: each face's sides are the hex edges joining its corners") {
  for (int f = 0; f < 6; ++f)
    for (int i = 0; i < 4; ++i) {
      const auto& e = kHexEdgeCorners[kHexFaceEdges[f][i]];
      const int a = kHexFaceCorners[f][i], b = kHexFaceCorners[f][(i + 1) % 4];
      CHECK(std::minmax(e[0], e[1]) == std::minmax(a, b));
    }
}

TEST_CASE("topology of a structured grid: counts of faces and edges") {
  const int a = 3, b = 4, c = 5;
  const HexTopology t = build_hex_topology(gen::hexgrid(a, b, c));
  CHECK(t.face_count == std::uint32_t((a + 1) * b * c + a * (b + 1) * c + a * b * (c + 1)));
  CHECK(t.edge_count == std::uint32_t(a * (b + 1) * (c + 1) + (a + 1) * b * (c + 1) + (a + 1) * (b + 1) * c));
  const auto boundary = std::count(t.face_hex_count.begin(), t.face_hex_count.end(), 1u);
  CHECK(boundary == 2 * (a * b + b * c + c * a));
  CHECK(std::count(t.face_hex_count.begin(), t.face_hex_count.end(), 2u) == std::ptrdiff_t(t.face_count) - boundary);
}

TEST_CASE("the boundary of a hexgrid is the box surface") {
  const QuadSurface s = hex_mesh_boundary(gen::hexgrid(2, 3, 4));
  const QuadSurface box = gen::box(2, 3, 4);
  CHECK(s.quads.size() == box.quads.size());
  CHECK(s.points.size() == box.points.size());
  CHECK(std::set<Vec3>(s.points.begin(), s.points.end()) == std::set<Vec3>(box.points.begin(), box.points.end()));
}

TEST_CASE("scaled Jacobian: cube 1, shear 1/sqrt(1+s^2), degenerate -1") {
  HexMesh m = gen::hexgrid(1, 1, 1);
  CHECK(scaled_jacobian(m, 0) == 1.0);
  for (int top = 4; top < 8; ++top) m.points[m.hexes[0][top]][0] += 1.0;
  CHECK(scaled_jacobian(m, 0) == doctest::Approx(1 / std::sqrt(2.0)));
  m.points[m.hexes[0][1]] = m.points[m.hexes[0][0]];
  CHECK(scaled_jacobian(m, 0) == -1.0);
}

TEST_CASE("a twisted hex: every corner positive, its centre not; criterion 7 holds and the centre is reported") {
  // One hex of quadrangulation 12 4 as placed before the untangler saw centres.
  HexMesh m;
  m.points = {{0.329, 0.577, 0.126}, {0.529, 0.499, 0.198}, {0.399, 0.0, 0.379}, {0.696, 0.776, 0.0},
              {0.3, 0.594, 0.148},   {1.0, 0.48, 0.208},   {0.434, 0.177, 0.337}, {0.0, 0.758, 0.288}};
  m.hexes = {{0, 1, 2, 3, 4, 5, 6, 7}};
  CHECK(scaled_jacobian(m, 0) == doctest::Approx(0.0055).epsilon(0.05));
  CHECK(centre_scaled_jacobian(m, 0) == doctest::Approx(-0.716).epsilon(0.01));
  const ValidityReport r = check_hex_mesh(m);
  CHECK(r.criteria.back().passed);
  CHECK(r.quality.below_zero == 0);
  CHECK(r.quality.verdict_below_zero == 1);
  CHECK(r.quality.min_verdict_scaled_jacobian == doctest::Approx(-0.716).epsilon(0.01));
  CHECK_MESSAGE(verdict_line(r).find("; but 1 hex with every corner positive has a centre Jacobian <= 0") !=
                    std::string::npos,
                verdict_line(r));
  // On a cube and a sheared one the centre is no worse than the corners.
  HexMesh cube = gen::hexgrid(1, 1, 1);
  CHECK(centre_scaled_jacobian(cube, 0) == 1.0);
  for (int top = 4; top < 8; ++top) cube.points[cube.hexes[0][top]][0] += 1.0;
  CHECK(centre_scaled_jacobian(cube, 0) == doctest::Approx(1 / std::sqrt(2.0)));
  CHECK(check_hex_mesh(cube).quality.verdict_below_zero == 0);
}

TEST_CASE("scaled Jacobian does not depend on the scale: 1e-300 and 1e300 give the values of scale 1") {
  HexMesh unit = gen::hexgrid(2, 2, 2);
  unit.points[13] = {1.3, 0.8, 1.1};  // the middle node, off centre: eight different values
  unit.points[0] = {-0.2, 0.1, 0.0};
  for (double scale : {1e-300, 1e300}) {
    CAPTURE(scale);
    HexMesh scaled = unit;
    for (Vec3& p : scaled.points) p = scale * p;
    for (std::size_t h = 0; h < unit.hexes.size(); ++h) {
      CAPTURE(h);
      CHECK(scaled_jacobian(unit, h) > 0.3);
      CHECK(scaled_jacobian(scaled, h) == doctest::Approx(scaled_jacobian(unit, h)).epsilon(1e-12));
    }
    const ValidityReport r = check_hex_mesh(scaled);
    CHECK(r.valid());
    CHECK(r.quality.min_scaled_jacobian == doctest::Approx(check_hex_mesh(unit).quality.min_scaled_jacobian));
  }
  // Edges still too short or too long to measure at all are degenerate.
  HexMesh tiny = unit;
  for (Vec3& p : tiny.points) p = 0.0 * p;
  CHECK(scaled_jacobian(tiny, 0) == -1.0);
  HexMesh huge = unit;
  huge.points[huge.hexes[0][1]] = {1e308, 0, 0};
  huge.points[huge.hexes[0][0]] = {-1e308, 0, 0};
  CHECK(scaled_jacobian(huge, 0) == -1.0);
}

TEST_CASE("a structured grid is valid, with and without its boundary surface") {
  const HexMesh m = gen::hexgrid(3, 4, 5);
  const QuadSurface box = gen::box(3, 4, 5);
  for (const QuadSurface* boundary : {static_cast<const QuadSurface*>(nullptr), &box}) {
    const ValidityReport r = check_hex_mesh(m, boundary);
    CHECK(r.valid());
    CHECK(r.combinatorial_valid());
    CHECK(r.first_failure() == nullptr);
    CHECK(r.criteria.size() == (boundary ? 7u : 6u));
    CHECK(r.hexes == 60);
    CHECK(r.quality.min_scaled_jacobian == 1.0);
    CHECK(r.quality.mean_scaled_jacobian == 1.0);
    CHECK(r.quality.below_0_2 == 0);
    CHECK(r.boundary_components == 1);
    CHECK(r.boundary_genus == 0);
    CHECK(verdict_line(r) == "valid: 60 hexes, min scaled Jacobian 1.000, mean 1.000, 0 below 0.2");
  }
}

TEST_CASE("the swept O-grid is valid and its boundary is the cylinder surface") {
  for (auto [n, h] : {std::pair{1, 1}, {2, 3}, {3, 2}, {5, 4}}) {
    CAPTURE(n);
    CAPTURE(h);
    const QuadSurface surface = gen::cylinder(n, h);
    const ValidityReport r = check_hex_mesh(gen::ogrid_cylinder(n, h), &surface);
    CHECK(failures(r).empty());
    CHECK(r.quality.min_scaled_jacobian > 0.2);
  }
}

TEST_CASE("a ring of hexes is a solid torus: valid, boundary genus 1") {
  const HexMesh ring = carved_grid(3, 3, 2, [](int i, int j, int) { return !(i == 1 && j == 1); });
  const ValidityReport r = check_hex_mesh(ring);
  CHECK(failures(r).empty());
  CHECK(r.boundary_components == 1);
  CHECK(r.boundary_genus == 1);
}

TEST_CASE("a cube with a cavity is valid; its boundary has two pieces") {
  const HexMesh hollow = carved_grid(3, 3, 3, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); });
  const ValidityReport r = check_hex_mesh(hollow);
  CHECK(failures(r).empty());
  CHECK(r.boundary_components == 2);
  const QuadSurface box = gen::box(3, 3, 3);
  const ValidityReport against_box = check_hex_mesh(hollow, &box);
  CHECK(failures(against_box) == std::vector<int>{6});
  CHECK(criterion(against_box, 6).detail.find("is not a surface quad (6 such faces)") != std::string::npos);
}

TEST_CASE("criterion 1: repeated or out-of-range nodes; 2-6 are then not evaluated") {
  HexMesh m = gen::hexgrid(2, 2, 2);
  m.hexes[5][3] = m.hexes[5][6];
  const QuadSurface box = gen::box(2, 2, 2);
  ValidityReport r = check_hex_mesh(m, &box);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 1);
  CHECK(criterion(r, 1).detail == fmt::format("hex 5 uses node {} twice (corners 3 and 6)", m.hexes[5][6]));
  for (int n : {2, 3, 4, 5, 6}) CHECK_FALSE(criterion(r, n).evaluated);
  CHECK(criterion(r, 7).evaluated);
  CHECK(verdict_line(r).find("also fails 7") != std::string::npos);

  m = gen::hexgrid(2, 2, 2);
  m.hexes[7][0] = 1000;
  r = check_hex_mesh(m);
  CHECK(criterion(r, 1).detail == "hex 7 refers to node 1000, but the mesh has 27 nodes");
  CHECK(criterion(r, 7).detail.rfind("hex 7 has scaled Jacobian -1.000", 0) == 0);

  CHECK(criterion(check_hex_mesh(HexMesh{}), 1).detail == "the mesh has no hexes");
}

TEST_CASE("criterion 2: a duplicated hex") {
  HexMesh m = gen::hexgrid(3, 4, 5);
  m.hexes.push_back(m.hexes[17]);
  const ValidityReport r = check_hex_mesh(m);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 2);
  CHECK(r.first_failure()->detail == "hexes 17 and 60 are the same hex (same 8 nodes)");
  // The same nodes in another order are the same hex too.
  HexMesh rotated = gen::hexgrid(1, 1, 1);
  const Hex h = rotated.hexes[0];
  rotated.hexes.push_back({h[1], h[2], h[3], h[0], h[5], h[6], h[7], h[4]});
  CHECK(check_hex_mesh(rotated).first_failure()->detail == "hexes 0 and 1 are the same hex (same 8 nodes)");
}

TEST_CASE("criterion 2: a face in three hexes") {
  HexMesh m = gen::hexgrid(2, 1, 1);
  // A third hex holding the shared face x = 1 as its face 3-0-4-7.
  const Hex left = m.hexes[0];
  const auto fresh = static_cast<std::uint32_t>(m.points.size());
  for (const Vec3& p : {Vec3{1, -1, 0}, Vec3{1, -2, 0}, Vec3{1, -1, 1}, Vec3{1, -2, 1}}) m.points.push_back(p);
  m.hexes.push_back({left[1], fresh, fresh + 1, left[2], left[5], fresh + 2, fresh + 3, left[6]});
  const ValidityReport r = check_hex_mesh(m);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 2);
  CHECK(r.first_failure()->detail ==
        fmt::format("face {}-{}-{}-{} is in 3 hexes: 0, 1, 2", left[1], left[2], left[6], left[5]));
}

TEST_CASE("criterion 3: two hexes sharing two faces (a doublet)") {
  // Hex B wraps around the edge 2-6 of the unit cube A, holding A's faces
  // x = 1 (1-2-6-5) and y = 1 (2-3-7-6).
  HexMesh m = gen::hexgrid(1, 1, 1);
  m.points.push_back({2, 2, 0});
  m.points.push_back({2, 2, 1});
  const Hex a = m.hexes[0];
  m.hexes.push_back({8, a[1], a[2], a[3], 9, a[5], a[6], a[7]});
  const ValidityReport r = check_hex_mesh(m);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 3);
  CHECK(r.first_failure()->detail == "hexes 0 and 1 share 2 faces");
  CHECK(verdict_line(r).rfind("invalid: criterion 3 (no doublets) fails: hexes 0 and 1 share 2 faces", 0) == 0);
}

TEST_CASE("criterion 4: hexes meeting only along an edge, or only at a node") {
  const HexMesh edge_only = carved_grid(2, 2, 1, [](int i, int j, int) { return i == j; });
  ValidityReport r = check_hex_mesh(edge_only);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 4);
  CHECK(r.first_failure()->detail.find("around edge 4-13 the hexes form 2 pieces with 4 boundary faces") == 0);
  CHECK(criterion(r, 5).detail == "the hexes form 2 separate pieces, not one solid");

  const HexMesh node_only = carved_grid(2, 2, 2, [](int i, int j, int k) { return i == j && j == k; });
  r = check_hex_mesh(node_only);
  REQUIRE(r.first_failure() != nullptr);
  CHECK(r.first_failure()->number == 4);
  CHECK(r.first_failure()->detail ==
        "the link of boundary node 13 has 2 pieces, not one disk (0 bad edges, 1 bad node)");
}

TEST_CASE("an inverted hex: mirrored (two pairs swapped) fails only criterion 7") {
  HexMesh m = gen::hexgrid(3, 4, 5);
  Hex& h = m.hexes[23];
  std::swap(h[1], h[3]);
  std::swap(h[5], h[7]);
  const QuadSurface box = gen::box(3, 4, 5);
  const ValidityReport r = check_hex_mesh(m, &box);
  CHECK(failures(r) == std::vector<int>{7});
  CHECK(r.combinatorial_valid());
  CHECK(r.quality.below_zero == 1);
  CHECK(r.quality.min_scaled_jacobian == -1.0);
  CHECK(
      verdict_line(r) ==
      "invalid: criterion 7 (positive scaled Jacobian) fails: hex 23 has scaled Jacobian -1.000 (1 hex at or below 0)");
}

TEST_CASE("a single swapped node pair breaks the topology and inverts the hex") {
  HexMesh m = gen::hexgrid(3, 3, 3);
  std::swap(m.hexes[13][1], m.hexes[13][3]);  // the centre hex
  const ValidityReport r = check_hex_mesh(m);
  const auto failed = failures(r);
  REQUIRE(!failed.empty());
  // The swapped hex meets its neighbours in nodes that are not a shared face
  // (criterion 3), and its edges no longer close up (4).
  CHECK(failed.front() == 3);
  CHECK(std::find(failed.begin(), failed.end(), 4) != failed.end());
  CHECK(failed.back() == 7);
  CHECK_FALSE(r.valid());
}

TEST_CASE("a deleted hex: the boundary no longer matches the box (criterion 6)") {
  const QuadSurface box = gen::box(3, 4, 5);
  SUBCASE("an interior hex leaves a cavity") {
    const HexMesh m = carved_grid(3, 4, 5, [](int i, int j, int k) { return !(i == 1 && j == 2 && k == 2); });
    const ValidityReport r = check_hex_mesh(m, &box);
    CHECK(failures(r) == std::vector<int>{6});
  }
  SUBCASE("a corner hex leaves a notch and an unused node") {
    const HexMesh m = carved_grid(3, 4, 5, [](int i, int j, int k) { return i + j + k > 0; });
    const ValidityReport r = check_hex_mesh(m, &box);
    CHECK(failures(r) == std::vector<int>{6});
    CHECK(criterion(r, 6).detail == "surface node 0 at (0, 0, 0) is not a node of any hex");
  }
  SUBCASE("a hex on a face leaves a dent") {
    const HexMesh m = carved_grid(3, 4, 5, [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 0); });
    const ValidityReport r = check_hex_mesh(m, &box);
    CHECK(failures(r) == std::vector<int>{6});
    CHECK(criterion(r, 6).detail.find("surface quad") == 0);
  }
}

TEST_CASE("criterion 6: coordinates must match exactly") {
  const HexMesh m = gen::hexgrid(2, 2, 2);
  QuadSurface box = gen::box(2, 2, 2);
  box.points[3][0] += 1e-12;
  const ValidityReport r = check_hex_mesh(m, &box);
  CHECK(failures(r) == std::vector<int>{6});
  CHECK(criterion(r, 6).detail.find("surface node 3 at") == 0);
}

TEST_CASE("JSON report carries the verdict and every criterion") {
  HexMesh m = gen::hexgrid(2, 2, 2);
  m.hexes.push_back(m.hexes[0]);
  const auto j = validity_json(check_hex_mesh(m));
  CHECK(j["valid"] == false);
  CHECK(j["hexes"] == 9);
  CHECK(j["criteria"].size() == 6);
  CHECK(j["criteria"][1]["number"] == 2);
  CHECK(j["criteria"][1]["passed"] == false);
  CHECK(j["criteria"][1]["detail"] == "hexes 0 and 8 are the same hex (same 8 nodes)");
  CHECK(j["min_scaled_jacobian"] == 1.0);
  CHECK(j["verdict"].get<std::string>().rfind("invalid: criterion 2", 0) == 0);
}

TEST_CASE("the sheets of a hex mesh from its connectivity: a grid has one per layer of each direction") {
  const HexMesh grid = gen::hexgrid(3, 2, 4);
  const HexSheets sheets = hex_sheets(grid);
  CHECK(sheets.count == 3 + 2 + 4);
  REQUIRE(sheets.of_hex.size() == grid.hexes.size());
  // The hexes of one sheet are a layer: they share the sheet's coordinate.
  std::map<std::uint32_t, std::set<long>> layer;  // sheet -> the rounded coordinate of its hexes' centres
  for (std::size_t h = 0; h < grid.hexes.size(); ++h)
    for (int d = 0; d < 3; ++d) {
      // Direction d crosses the edge 0-1, 0-3 or 0-4 of the hex: the coordinate that edge changes.
      const int corner = std::array<int, 3>{1, 3, 4}[d];
      const Vec3& a = grid.points[grid.hexes[h][0]];
      const Vec3& b = grid.points[grid.hexes[h][corner]];
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (std::abs(b[k] - a[k]) > std::abs(b[axis] - a[axis])) axis = k;
      layer[sheets.of_hex[h][d]].insert(std::lround(2 * (a[axis] + b[axis])));
    }
  for (const auto& [sheet, coordinates] : layer) CHECK(coordinates.size() == 1);
  // Three sheets per hex, all different.
  for (const auto& three : sheets.of_hex) CHECK(std::set<std::uint32_t>(three.begin(), three.end()).size() == 3);
  // A single hex lies on three sheets.
  CHECK(hex_sheets(gen::hexgrid(1, 1, 1)).count == 3);
}
