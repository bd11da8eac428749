#pragma once
// Gluing one hex onto a quad map: the flips of Bern, Eppstein & Erickson
// ("Flipping cubical meshes"). A hex glued onto k connected quads of the map,
// on their inner side (the side their orientation faces away from), replaces
// them with its 6 - k other faces; so the map changes by 6 - 2k quads.
//
// Every gluing is named by a bottom quad b0 b1 b2 b3 and the set of its sides
// whose neighbour the hex also covers (side i runs b_i -> b_{i+1}):
//   no side        k = 1, a pillow on one quad (4 new vertices)
//   one side       k = 2, a wedge on an edge (2 new vertices)
//   two adjacent   k = 3 round a vertex of degree 3 (cross; 1 new vertex)
//   two opposite   k = 3 along a strip of three quads (no new vertex)
//   three          k = 4 (no new vertex)
//   all four       k = 5, a cup (no new vertex)
// The top corner t_i stands over b_i; a covered side gives the tops at its
// ends, a corner between two covered sides must have degree 3, and the tops
// no covered side gives are new vertices.
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/quadmap/quad_map.hpp"

namespace loom::quadmap {

struct Gluing {
  std::uint32_t bottom = 0;  ///< quad index
  std::uint8_t sides = 0;    ///< bit i: the quad across side i of the bottom is covered too
};

struct GluedHex {
  /// Corners in VTK order, positively oriented when the map's quads face away
  /// from the hex: 0-3 the bottom reversed, 4-7 the tops over them.
  Hex hex{};
  std::array<std::uint32_t, 5> covered{};  ///< quads covered, bottom first
  int k = 0;                                ///< how many
  /// The hex's 6 - k other faces, facing away from it: the top first, then
  /// the uncovered sides in order. New vertices are numbered from the map's
  /// vertex_bound on.
  std::array<Quad, 5> added{};
  std::uint32_t vertex_bound = 0;  ///< of the map afterwards
  /// The map afterwards (glue_hex only): the quads not covered, in order,
  /// then `added`. A vertex whose quads were all covered leaves the map.
  QuadMap after;
};

/// Plans the gluing `g` says, if the hex can be glued and leaves every vertex
/// on the map on three quads or more (false otherwise, `out` unspecified);
/// everything but `after`. Does not check the rest of simplicity (repeated
/// edges) or properness: see why_not_proper().
bool plan_gluing(const QuadMap& m, const std::vector<Dart>& twin, const std::vector<int>& degree, Gluing g,
                 GluedHex& out);
/// The map after a planned gluing.
QuadMap after_gluing(const QuadMap& m, const GluedHex& planned);
/// The twins of the map after a planned gluing, from those before: the
/// kept quads' darts renumbered, and only the darts on the hex's edges matched
/// anew. Equal to twins(after_gluing(m, planned)) when that map runs no
/// directed edge twice.
std::vector<Dart> twins_after_gluing(const QuadMap& m, const std::vector<Dart>& twin, const GluedHex& planned);
/// The degrees of the map after a planned gluing, from those before.
std::vector<int> degrees_after_gluing(const QuadMap& m, const std::vector<int>& degree, const GluedHex& planned);
/// plan_gluing, then `after` too.
bool glue_hex(const QuadMap& m, const std::vector<Dart>& twin, const std::vector<int>& degree, Gluing g,
              GluedHex& out);

/// The hex that fills a map which is the boundary of one cube (6 quads, 8
/// vertices of degree 3), with `bottom` as its bottom; false if the map is not a cube.
bool fill_cube(const QuadMap& m, const std::vector<Dart>& twin, Hex& out);

/// The hex's faces facing outwards, VTK order: 0123 reversed is 0321, ... as
/// in src/check: (0,3,2,1), (4,5,6,7), (0,1,5,4), (1,2,6,5), (2,3,7,6), (3,0,4,7).
std::array<Quad, 6> outward_faces(const Hex& h);

}  // namespace loom::quadmap
