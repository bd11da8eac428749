#include "src/geometry/linking.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace loom {

namespace {

struct Projected {
  double x, y, height;
};

std::vector<Projected> project(const std::vector<Vec3>& polygon, const Vec3& u, const Vec3& w, const Vec3& d) {
  std::vector<Projected> out;
  out.reserve(polygon.size());
  for (const Vec3& p : polygon) out.push_back({dot(p, u), dot(p, w), dot(p, d)});
  return out;
}

double orient(const Projected& p, const Projected& q, const Projected& r) {
  return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

double extent(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0;
  for (const auto* polygon : {&a, &b})
    for (const Vec3& p : *polygon)
      for (double c : p) largest = std::max(largest, std::abs(c));
  return std::max(largest, 1e-300);
}

}  // namespace

std::optional<long> linking_number_along(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& direction) {
  const Vec3 d = (1.0 / norm(direction)) * direction;
  const Vec3 helper = std::abs(d[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 u = cross(d, helper);
  u = (1.0 / norm(u)) * u;
  const Vec3 w = cross(d, u);  // (u, w, d) is right-handed
  const std::vector<Projected> pa = project(a, u, w, d), pb = project(b, u, w, d);
  const double scale = extent(a, b), area_tolerance = 1e-13 * scale * scale, height_tolerance = 1e-12 * scale;
  long a_over_b = 0, b_over_a = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const Projected &p = pa[i], &p2 = pa[(i + 1) % pa.size()];
    const double min_x = std::min(p.x, p2.x), max_x = std::max(p.x, p2.x);
    const double min_y = std::min(p.y, p2.y), max_y = std::max(p.y, p2.y);
    for (std::size_t j = 0; j < pb.size(); ++j) {
      const Projected &q = pb[j], &q2 = pb[(j + 1) % pb.size()];
      if (std::max(q.x, q2.x) < min_x || std::min(q.x, q2.x) > max_x || std::max(q.y, q2.y) < min_y ||
          std::min(q.y, q2.y) > max_y)
        continue;
      const double o1 = orient(p, p2, q), o2 = orient(p, p2, q2), o3 = orient(q, q2, p), o4 = orient(q, q2, p2);
      for (double o : {o1, o2, o3, o4})
        if (std::abs(o) <= area_tolerance) return std::nullopt;
      if ((o1 > 0) == (o2 > 0) || (o3 > 0) == (o4 > 0)) continue;
      const double s = o3 / (o3 - o4), t = o1 / (o1 - o2);
      const double height_a = p.height + s * (p2.height - p.height), height_b = q.height + t * (q2.height - q.height);
      if (std::abs(height_a - height_b) <= height_tolerance) return std::nullopt;
      const long sign = ((p2.x - p.x) * (q2.y - q.y) - (p2.y - p.y) * (q2.x - q.x)) > 0 ? 1 : -1;
      (height_a > height_b ? a_over_b : b_over_a) += sign;
    }
  }
  // Two closed curves in the plane cross with signs summing to zero; if they
  // do not here, rounding decided a crossing.
  if (a_over_b + b_over_a != 0) return std::nullopt;
  return a_over_b;
}

std::optional<long> linking_number(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  static constexpr std::array<Vec3, 4> kDirections{
      {{0.5773, 0.6181, 0.5333}, {-0.3141, 0.2718, 0.9091}, {0.8660, -0.1414, 0.4790}, {0.1732, 0.9487, -0.2646}}};
  for (const Vec3& d : kDirections)
    if (auto lk = linking_number_along(a, b, d)) return lk;
  return std::nullopt;
}

}  // namespace loom
