#include "src/gen/sphere_relaxation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "src/gen/sphere_embedding.hpp"

namespace loom::gen {

namespace {

constexpr int kSpreadSweeps = 300;
constexpr int kMobiusSweeps = 20;
constexpr double kSettled = 1e-7;
// Spring weight relative to the barrier. Per node the barrier's pull scales
// like 1/h and a spring's like w h, for edge length h ~ (4π / triangles)^½, so
// w is scaled by triangles / 4π to keep the balance the same at every size.
constexpr double kSpringWeight = 0.03;
constexpr int kUnfoldPasses = 20;

Vec3 normalized(const Vec3& v) { return (1.0 / norm(v)) * v; }

// The Möbius transformation of the sphere that takes the point a of the open
// ball to the centre. It keeps orientation, but can blow a triangle up past a
// hemisphere, which turns it over as a flat triangle.
void move_to_origin(std::vector<Vec3>& points, const Vec3& a) {
  const double a2 = dot(a, a);
  for (Vec3& x : points) {
    const Vec3 d = x - a;
    const double d2 = dot(d, d);
    x = normalized((1 / d2) * ((1 - a2) * d - d2 * a));
  }
}

// Takes the largest of 1, 1/2, 1/4... of the way that turns no triangle over.
void recentre(std::vector<Vec3>& points, const CentredTriangulation& mesh) {
  Vec3 centre{0, 0, 0};
  for (const Vec3& p : points) centre = centre + p;
  centre = (1.0 / double(points.size())) * centre;
  const std::size_t clockwise = clockwise_triangles(points, mesh);
  for (double part = 1; part > 0.01 && norm(centre) > kSettled; part /= 2) {
    std::vector<Vec3> moved = points;
    move_to_origin(moved, part * centre);
    if (clockwise_triangles(moved, mesh) <= clockwise) {
      points.swap(moved);
      return;
    }
  }
}

class Spreader {
 public:
  Spreader(std::vector<Vec3>& points, const CentredTriangulation& mesh)
      : points_(points),
        mesh_(mesh),
        counted_(mesh.triangles.size()),
        spring_(kSpringWeight * double(mesh.triangles.size()) / (4 * std::numbers::pi)) {}

  // Returns the largest move.
  double sweep() {
    // A triangle joins the barrier once it turns counter-clockwise, and then stays so.
    for (std::size_t t = 0; t < counted_.size(); ++t) counted_[t] = turning(points_, mesh_.triangles[t]) > 0;
    double largest = 0;
    for (std::uint32_t i = 0; i < points_.size(); ++i) largest = std::max(largest, move(i));
    return largest;
  }

 private:
  double energy(std::uint32_t node) const {
    double e = 0;
    for (std::uint32_t t : mesh_.fan[node])
      if (counted_[t]) e -= std::log(turning(points_, mesh_.triangles[t]));
    for (std::uint32_t j : mesh_.neighbours[node]) e += spring_ * dot(points_[node] - points_[j], points_[node] - points_[j]);
    return e;
  }

  bool feasible(std::uint32_t node) const {
    for (std::uint32_t t : mesh_.fan[node])
      if (counted_[t] && turning(points_, mesh_.triangles[t]) <= 0) return false;
    return true;
  }

  // One damped Newton step in the tangent plane. With n_t the cross product
  // of triangle t's other two corners, the energy is
  //   -sum_t log(p . n_t) + w sum_j |p - p_j|^2,
  // and moving by d in the tangent plane then renormalising adds (k + 2w p.S)
  // |d|^2 / 2 to second order (k counted triangles, S the neighbours' sum).
  double move(std::uint32_t i) {
    const Vec3 p = points_[i];
    Vec3 gradient{0, 0, 0}, sum{0, 0, 0};
    std::array<std::array<double, 3>, 3> hessian{};
    int counted = 0;
    for (std::uint32_t t : mesh_.fan[i]) {
      if (!counted_[t]) continue;
      const Triangle& tri = mesh_.triangles[t];
      const int c = tri[0] == i ? 0 : tri[1] == i ? 1 : 2;
      const Vec3 n = cross(points_[tri[(c + 1) % 3]], points_[tri[(c + 2) % 3]]);
      const double d = dot(p, n);
      gradient = gradient - (1 / d) * n;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) hessian[r][s] += n[r] * n[s] / (d * d);
      ++counted;
    }
    for (std::uint32_t j : mesh_.neighbours[i]) sum = sum + points_[j];
    gradient = gradient - (2 * spring_) * sum;
    const double curvature = counted + 2 * spring_ * dot(sum, p);
    const Vec3 helper = std::abs(p[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 e1 = normalized(cross(p, helper)), e2 = cross(p, e1);
    auto form = [&hessian](const Vec3& x, const Vec3& y) {
      double f = 0;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) f += x[r] * hessian[r][s] * y[s];
      return f;
    };
    const double a11 = form(e1, e1) + curvature, a12 = form(e1, e2), a22 = form(e2, e2) + curvature;
    const double g1 = dot(gradient, e1), g2 = dot(gradient, e2), det = a11 * a22 - a12 * a12;
    if (!(det > 0) || !(a11 > 0)) return 0;  // not convex here: leave the node
    const Vec3 step = (-(a22 * g1 - a12 * g2) / det) * e1 + (-(a11 * g2 - a12 * g1) / det) * e2;
    const double before = energy(i);
    for (double part = 1; part > 1e-4; part /= 2) {
      points_[i] = normalized(p + part * step);
      if (feasible(i) && energy(i) < before) return norm(points_[i] - p);
    }
    points_[i] = p;
    return 0;
  }

  std::vector<Vec3>& points_;
  const CentredTriangulation& mesh_;
  std::vector<char> counted_;
  double spring_;
};

}  // namespace

void spread_on_sphere(std::vector<Vec3>& points, const CentredTriangulation& mesh) {
  Spreader spreader(points, mesh);
  for (int sweep = 0; sweep < kSpreadSweeps; ++sweep) {
    if (sweep < kMobiusSweeps) recentre(points, mesh);
    if (spreader.sweep() < kSettled) break;
  }
}

void unfold_quads(std::vector<Vec3>& points, const CentredTriangulation& mesh, const std::vector<Quad>& quads) {
  std::vector<std::vector<std::uint32_t>> quads_at(mesh.corner_count);
  for (std::uint32_t f = 0; f < quads.size(); ++f)
    for (std::uint32_t v : quads[f]) quads_at[v].push_back(f);
  auto folded_around = [&](std::uint32_t v) {
    std::size_t n = 0;
    for (std::uint32_t f : quads_at[v]) n += quad_is_folded(points, quads[f]);
    return n;
  };
  // Candidates for node v: towards its neighbours' mean, towards the folded
  // quad's middle, and part of the way towards each neighbour.
  auto candidates = [&](std::uint32_t v, const Quad& quad) {
    const Vec3 p = points[v];
    Vec3 neighbours{0, 0, 0}, middle{0, 0, 0};
    for (std::uint32_t j : mesh.neighbours[v]) neighbours = neighbours + points[j];
    for (std::uint32_t c : quad) middle = middle + points[c];
    std::vector<Vec3> at;
    for (const Vec3& target : {normalized(neighbours), normalized(middle)})
      for (double part : {1.0, 0.5, 0.25}) at.push_back(normalized(p + part * (target - p)));
    for (std::uint32_t j : mesh.neighbours[v])
      for (double part : {0.2, 0.4, 0.6}) at.push_back(normalized(p + part * (points[j] - p)));
    return at;
  };
  for (int pass = 0; pass < kUnfoldPasses; ++pass) {
    bool improved = false;
    for (const Quad& quad : quads) {
      if (!quad_is_folded(points, quad)) continue;
      for (std::uint32_t v : quad) {
        const Vec3 start = points[v];
        const std::size_t clockwise = clockwise_in_fan(points, mesh, v);
        std::size_t best = folded_around(v);
        Vec3 best_at = start;
        for (const Vec3& c : candidates(v, quad)) {
          points[v] = c;
          const std::size_t folded = folded_around(v);
          if (folded < best && clockwise_in_fan(points, mesh, v) <= clockwise) best = folded, best_at = c;
        }
        points[v] = best_at;
        if (best_at != start) {
          improved = true;
          break;
        }
      }
    }
    if (!improved) break;
  }
}

}  // namespace loom::gen
