#include "src/check/surface_angle_bound.hpp"

#include <algorithm>

namespace loom {

double least_corner_sine(const QuadSurface& surface, const Quad& quad) {
  double least = 1;
  for (int i = 0; i < 4; ++i) {
    const Vec3& at = surface.points[quad[static_cast<std::size_t>(i)]];
    const Vec3 e1 = surface.points[quad[static_cast<std::size_t>((i + 1) % 4)]] - at;
    const Vec3 e2 = surface.points[quad[static_cast<std::size_t>((i + 3) % 4)]] - at;
    const double lengths = norm(e1) * norm(e2);
    least = std::min(least, lengths > 0 ? norm(cross(e1, e2)) / lengths : 0.0);
  }
  return least;
}

SurfaceAngleBound surface_angle_bound(const QuadSurface& surface) {
  SurfaceAngleBound bound;
  if (surface.quads.empty()) return bound;
  double sum = 0;
  for (const Quad& q : surface.quads) {
    const double least = least_corner_sine(surface, q);
    bound.least_sine = std::min(bound.least_sine, least);
    bound.quads_below_0_2 += least < 0.2;
    sum += least;
  }
  bound.mean_sine = sum / static_cast<double>(surface.quads.size());
  return bound;
}

}  // namespace loom
