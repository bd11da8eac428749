#pragma once
// Decides whether a quad surface can bound a hex mesh of a solid, and says
// precisely why not.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include "src/mesh/meridians.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

struct SurfaceCheckOptions {
  /// Merge nodes closer than `weld_tolerance` (relative to the bounding-box
  /// diagonal) before checking. Off by default: coincident nodes are an error.
  bool weld = false;
  double weld_tolerance = 1e-9;
};

struct SurfaceSummary {
  std::size_t nodes = 0, edges = 0, quads = 0;
  int genus = 0;
  std::size_t welded_nodes = 0;  ///< nodes removed by welding
  std::size_t unused_nodes = 0;  ///< nodes removed because no quad used them
  bool flipped = false;          ///< the surface faced inward and was flipped
  /// A basis of the cycles that bound inside the solid (meridians.hpp), empty
  /// on a sphere; not known if the linking numbers could not be trusted.
  std::vector<NodeCycle> meridians;
  bool meridians_known = true;
};

/// Validates (and, if asked, welds) `surface` in place. Throws InputError naming
/// `where` (usually the file) and the first problem found, in this order:
/// no faces; NaN/inf coordinates; degenerate quads (repeated node); duplicated
/// quads; coincident nodes (unless welded); non-manifold edges (more
/// than two quads); open boundary (count of boundary edges); non-manifold
/// vertices (a vertex whose quads form several fans); inconsistent orientation;
/// several components; an odd number of quads (no hex mesh can exist); two
/// quads meeting improperly (see quads_meeting_improperly); a cycle with an
/// odd number of edges that bounds inside the solid (no hex mesh can exist,
/// meridians.hpp).
/// Unused nodes are dropped (counted in the summary). Surfaces oriented
/// inward are flipped to face outward.
SurfaceSummary validate_surface(QuadSurface& surface, const std::string& where,
                                const SurfaceCheckOptions& options = {});

/// Two quads (by index, the first found in quad order) that share two or more
/// nodes other than as one common edge: two opposite corners of one of them,
/// say. No hex mesh whose hexes meet properly (criterion 3 of validity.md) has
/// them as boundary quads: the hexes on them would share a diagonal of one,
/// which only a shared face could hold. nullopt when every two quads meet in
/// one edge, one node or not at all.
std::optional<std::pair<std::size_t, std::size_t>> quads_meeting_improperly(const QuadSurface& surface);

}  // namespace loom
