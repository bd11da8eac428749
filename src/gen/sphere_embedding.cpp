// The embedding in three steps. (1) Tutte's barycentric layout in the plane of
// the centred triangulation (centred_triangulation.hpp) with one quad pinned to
// a square as the outer face, mapped onto the sphere by inverse stereographic
// projection: a valid start but for a few slivers the projection can turn over,
// with the nodes crowded exponentially towards the middle. (2) spread_on_sphere
// evens it out. (3) unfold_quads repairs the few quads that are still folded
// as flat quads (rare; every quad is already a simple polygon on the sphere).
#include "src/gen/sphere_embedding.hpp"

#include <Eigen/SparseCholesky>

#include <array>

#include "src/gen/centred_triangulation.hpp"
#include "src/gen/random_draws.hpp"
#include "src/gen/sphere_relaxation.hpp"

namespace loom::gen {

namespace {

using PlanePoint = std::array<double, 2>;

// Tutte's layout with `outer` pinned to the square with corners (±1, 0),
// (0, ±1): every other node is the mean of its neighbours. The outer quad's
// centre is left out (its only neighbours are pinned: it stays at the mean
// of the corners, outside the picture). The rest is 3-connected, since the
// centred triangulation of a simple quadrangulation has no separating
// triangle, so the layout is a planar straight-line embedding.
std::vector<PlanePoint> tutte_layout(const CentredTriangulation& mesh, const Quad& outer) {
  const std::size_t n = mesh.neighbours.size();
  constexpr std::ptrdiff_t pinned = -1;
  std::vector<PlanePoint> plane(n, PlanePoint{0, 0});
  std::vector<std::ptrdiff_t> unknown(n, 0);
  const std::array<PlanePoint, 4> square{PlanePoint{1, 0}, PlanePoint{0, 1}, PlanePoint{-1, 0}, PlanePoint{0, -1}};
  for (int k = 0; k < 4; ++k) {
    plane[outer[k]] = square[k];
    unknown[outer[k]] = pinned;
  }
  std::ptrdiff_t unknowns = 0;
  for (std::ptrdiff_t& u : unknown)
    if (u != pinned) u = unknowns++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(unknowns, 2);
  for (std::size_t i = 0; i < n; ++i) {
    if (unknown[i] == pinned) continue;
    entries.emplace_back(unknown[i], unknown[i], double(mesh.neighbours[i].size()));
    for (std::uint32_t j : mesh.neighbours[i])
      if (unknown[j] == pinned)
        rhs.row(unknown[i]) += Eigen::RowVector2d(plane[j][0], plane[j][1]);
      else
        entries.emplace_back(unknown[i], unknown[j], -1.0);
  }
  Eigen::SparseMatrix<double> laplacian(unknowns, unknowns);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  const Eigen::MatrixX2d solution = solver.solve(rhs);
  for (std::size_t i = 0; i < n; ++i)
    if (unknown[i] != pinned) plane[i] = {solution(unknown[i], 0), solution(unknown[i], 1)};
  return plane;
}

// Inverse stereographic projection from the south pole: the unit circle goes
// to the equator, the pinned square's outside to the southern hemisphere.
std::vector<Vec3> to_sphere(const std::vector<PlanePoint>& plane) {
  std::vector<Vec3> sphere;
  sphere.reserve(plane.size());
  for (const auto& [x, y] : plane) {
    const double r2 = x * x + y * y;
    sphere.push_back((1 / (r2 + 1)) * Vec3{2 * x, 2 * y, 1 - r2});
  }
  return sphere;
}

}  // namespace

std::vector<Vec3> embed_on_sphere(const std::vector<Quad>& quads, std::size_t node_count, std::mt19937_64& rng) {
  const CentredTriangulation mesh(quads, node_count);
  const std::size_t outer = uniform_index(rng, quads.size());
  std::vector<Vec3> points = to_sphere(tutte_layout(mesh, quads[outer]));
  points[node_count + outer] = {0, 0, -1};
  // Whether the plane's counter-clockwise comes out as the sphere's depends on
  // the pinned square's orientation: mirror if most triangles turn the wrong way.
  if (2 * clockwise_triangles(points, mesh) > mesh.triangles.size())
    for (Vec3& p : points) p[0] = -p[0];
  spread_on_sphere(points, mesh);
  unfold_quads(points, mesh, quads);
  points.resize(node_count);
  return points;
}

bool quad_is_folded(const std::vector<Vec3>& points, const Quad& quad) {
  const Vec3 outward = points[quad[0]] + points[quad[1]] + points[quad[2]] + points[quad[3]];
  int left_turns = 0;
  for (int k = 0; k < 4; ++k) {
    const Vec3 &prev = points[quad[(k + 3) % 4]], &here = points[quad[k]], &next = points[quad[(k + 1) % 4]];
    left_turns += dot(cross(here - prev, next - here), outward) > 0;
  }
  return left_turns < 3;
}

std::size_t folded_quad_count(const std::vector<Vec3>& points, const std::vector<Quad>& quads) {
  std::size_t folded = 0;
  for (const Quad& q : quads) folded += quad_is_folded(points, q);
  return folded;
}

}  // namespace loom::gen
