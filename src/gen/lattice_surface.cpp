#include "src/gen/lattice_surface.hpp"

namespace loom::gen {

namespace {
LatticePoint step(const LatticePoint& origin, const LatticePoint& du, const LatticePoint& dv, std::int64_t i,
                  std::int64_t j) {
  return {origin[0] + i * du[0] + j * dv[0], origin[1] + i * du[1] + j * dv[1], origin[2] + i * du[2] + j * dv[2]};
}
}  // namespace

std::uint32_t LatticeSurface::node(const LatticePoint& p) {
  auto [it, inserted] = index_.try_emplace(p, static_cast<std::uint32_t>(points_.size()));
  if (inserted) points_.push_back(p);
  return it->second;
}

void LatticeSurface::add_patch(const LatticePoint& origin, const LatticePoint& du, const LatticePoint& dv, int nu,
                               int nv) {
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      quads_.push_back({node(step(origin, du, dv, i, j)), node(step(origin, du, dv, i + 1, j)),
                        node(step(origin, du, dv, i + 1, j + 1)), node(step(origin, du, dv, i, j + 1))});
}

void LatticeSurface::add_axis_rect(int axis, std::int64_t level, int sign, std::int64_t lo1, std::int64_t hi1,
                                   std::int64_t lo2, std::int64_t hi2) {
  const int axis1 = (axis + 1) % 3, axis2 = (axis + 2) % 3;
  LatticePoint origin{}, e1{}, e2{};
  origin[axis] = level;
  origin[axis1] = lo1;
  origin[axis2] = lo2;
  e1[axis1] = 1;
  e2[axis2] = 1;
  // e1 x e2 is +e[axis]; swapping them faces the other way.
  if (sign > 0)
    add_patch(origin, e1, e2, static_cast<int>(hi1 - lo1), static_cast<int>(hi2 - lo2));
  else
    add_patch(origin, e2, e1, static_cast<int>(hi2 - lo2), static_cast<int>(hi1 - lo1));
}

QuadSurface LatticeSurface::finish(double scale) const {
  QuadSurface s;
  s.points.reserve(points_.size());
  for (const auto& p : points_)
    s.points.push_back(
        {static_cast<double>(p[0]) / scale, static_cast<double>(p[1]) / scale, static_cast<double>(p[2]) / scale});
  s.quads = quads_;
  return s;
}

}  // namespace loom::gen
