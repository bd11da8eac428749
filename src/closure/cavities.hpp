#pragma once
// The cavities a weave leaves: what lies between a surface and the hexes
// woven into it, as fronts the closure can work on (cavity.hpp).
//
// The front is every face used once by the surface and the woven hexes
// together (a surface quad no hex covers, a hex face no other hex or surface
// quad matches). The woven hexes are taken as they are only if they could be
// part of a valid mesh of the surface: every hex with eight distinct corners,
// every pair meeting properly (hex_meeting.hpp), the hexes round every edge
// one piece (joined across faces), every face used at most
// twice and the right way round, and the front proper (quad_map.hpp) with
// every piece of it a sphere. Where that fails, the woven hexes at the
// offending vertices are peeled off (the front moves outwards) and the test
// runs again; it ends at the latest when no woven hex is left, and the
// surface itself is a proper sphere.
#include <cstdint>
#include <vector>

#include "src/closure/cavity.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::closure {

struct Cavities {
  /// The woven hexes kept; vertex ids: the surface's points, then new ones.
  std::vector<Hex> kept;
  /// One cavity per connected piece of the front, vertex ids as `kept`
  /// (each cavity's hexes: the kept hexes with a corner on its front).
  std::vector<Cavity> pieces;
  std::size_t peeled = 0;  ///< woven hexes removed
  std::uint32_t vertex_bound = 0;
};

/// `woven`: hexes over vertex ids where 0..surface.points.size()-1 are the
/// surface's vertices (a hex with an id out of range or repeated is dropped).
/// The surface must be a validated, outward-oriented sphere.
Cavities cavities_left(const QuadSurface& surface, const std::vector<Hex>& woven);

/// The vertices where a front is not proper (quad_map.hpp: repeated corners,
/// open or repeated edges, fewer than three quads, a ring that is not one
/// cycle, an edge or a shared pair of opposite corners); empty when proper.
std::vector<std::uint32_t> improper_vertices(const quadmap::QuadMap& front);

}  // namespace loom::closure
