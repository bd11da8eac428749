#pragma once
// How deep a hex mesh goes against how thick its part is (issue 32,
// "reporting"). A mesh whose hexes stand more layers deep than the part has
// room for must squeeze them, and its deepest hexes are the inverted ones
// (docs/results.md, the CAD parts). Both are counted in edge lengths.
#include <cstddef>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

/// Hexes and inverted hexes (scaled Jacobian <= 0) by depth: a hex's depth is
/// the most edges any of its corners is from the boundary, so a hex on the
/// boundary of a one-layer mesh is 1 deep. Index 0 is unused; empty when the
/// mesh's hexes do not have 8 distinct nodes each.
struct DepthProfile {
  std::vector<std::size_t> hexes, inverted;
  std::size_t deepest() const { return hexes.empty() ? 0 : hexes.size() - 1; }
};
DepthProfile depth_profile(const HexMesh& mesh);

/// Half the part's thickness, in mean edge lengths of the surface: from a
/// quad's centre along its inward normal to the first other quad the ray
/// meets, halved (how many layers of hexes of the surface's size fit from that
/// quad to the middle). Over every quad, or an even sample of `max_rays` of
/// them on a larger surface; rays that meet nothing (an open or inside-out
/// surface) are left out.
struct SurfaceThickness {
  double max = 0, median = 0;
  std::size_t rays = 0;  ///< rays that met the surface
};
SurfaceThickness surface_half_thickness(const QuadSurface& surface, std::size_t max_rays = 1000);

}  // namespace loom
