#pragma once
// A ceiling on the quality of every hex mesh bounded by a given quad surface.
// A hex whose face is a boundary quad has, at each corner of that quad, a
// corner Jacobian det[e1 e2 e3] <= |e1 x e2| |e3|, with e1 and e2 the quad's
// edges there: its scaled Jacobian is at most the sine of the quad's angle at
// that corner. So no placement and no connectivity inside can lift a mesh's
// minimum scaled Jacobian above the least such sine of its surface; only a
// better surface mesh can.
#include <cstddef>

#include "src/mesh/quad_surface.hpp"

namespace loom {

struct SurfaceAngleBound {
  /// The least sine of a quad's corner angle over the surface (1 when it has
  /// no quads): no hex mesh bounded by the surface has a minimum scaled
  /// Jacobian above it.
  double least_sine = 1;
  /// The mean over the quads of each quad's least sine: what the hexes on
  /// the boundary can average at most.
  double mean_sine = 1;
  std::size_t quads_below_0_2 = 0;  ///< quads with a corner whose sine is below 0.2
};

SurfaceAngleBound surface_angle_bound(const QuadSurface& surface);

/// The least sine of the quad's four corner angles (0 at a corner with a
/// zero-length edge).
double least_corner_sine(const QuadSurface& surface, const Quad& quad);

}  // namespace loom
