#pragma once
// Builds quad surfaces whose nodes lie on an integer lattice: patches are added
// in lattice coordinates and nodes at the same lattice point are welded, so
// shared nodes are exact by construction. Nodes are numbered in order of first
// use, which makes the result deterministic.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::gen {

using LatticePoint = std::array<std::int64_t, 3>;

class LatticeSurface {
 public:
  /// Adds nu x nv quads with corners origin + i*du + j*dv. Each quad is ordered
  /// (i,j) (i+1,j) (i+1,j+1) (i,j+1), so its right-hand normal is du x dv:
  /// pass du, dv with du x dv pointing out of the solid.
  void add_patch(const LatticePoint& origin, const LatticePoint& du, const LatticePoint& dv, int nu, int nv);

  /// Adds the unit-step rectangle on the plane x[axis] = level spanning
  /// [lo1,hi1] along axis+1 and [lo2,hi2] along axis+2 (cyclically), facing
  /// the direction `sign` (+1 or -1) along `axis`.
  void add_axis_rect(int axis, std::int64_t level, int sign, std::int64_t lo1, std::int64_t hi1, std::int64_t lo2,
                     std::int64_t hi2);

  /// The surface with each lattice point p placed at p / scale.
  QuadSurface finish(double scale) const;

  /// The lattice point of each node, in node order.
  const std::vector<LatticePoint>& lattice_points() const { return points_; }

 private:
  std::uint32_t node(const LatticePoint& p);

  std::map<LatticePoint, std::uint32_t> index_;
  std::vector<LatticePoint> points_;
  std::vector<Quad> quads_;
};

}  // namespace loom::gen
