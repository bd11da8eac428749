#pragma once
// A cavity: what is left to mesh, and what it must fit against.
//
// The front is the cavity's boundary as a quad map whose quads face away from
// the cavity (towards the hexes already there, or out of the solid where the
// quad is on the surface). Each front quad has an owner: the hex on its
// other side, an index into `hexes`, or -1 for a surface quad. `hexes` holds
// every hex a new hex could touch (the placed hexes with a corner on the
// front will do). Vertex ids are the cavity's own; hexes use the same ids.
//
// Shelling a cavity glues one hex at a time onto its front (hex_glue.hpp),
// keeping the front proper (quad_map.hpp) and every new hex meeting every
// other properly (hex_meeting.hpp): the two conditions under which the
// hexes, once the front is empty, make a valid mesh of the cavity.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/quadmap/quad_map.hpp"
#include "src/util/by_corner.hpp"

namespace loom::closure {

struct Cavity {
  quadmap::QuadMap front;
  std::vector<std::int32_t> owner;  ///< per front quad
  std::vector<Hex> hexes;
};

/// A cavity bounded by a whole surface (no hex yet): every owner -1.
Cavity surface_cavity(const quadmap::QuadMap& surface);

/// "" when the front is proper and every front quad's owner has that quad as
/// a face; otherwise what is wrong.
std::string why_not_closable(const Cavity& c);

/// Lookup of the hexes at each vertex, for meeting checks.
class HexesAtVertex {
public:
  explicit HexesAtVertex(const std::vector<Hex>& hexes);
  void add(const Hex& hex, std::int32_t index);
  /// The hexes with `v` as a corner (empty for a vertex no hex has).
  const std::vector<std::int32_t>& at(std::uint32_t v) const;

private:
  std::vector<std::vector<std::int32_t>> at_;
  std::vector<std::int32_t> none_;
};

/// The quads of a map at each of its vertices, by quad index, for checks near a few quads.
class QuadsAtVertex : public ByCorner<std::uint32_t> {
public:
  explicit QuadsAtVertex(const quadmap::QuadMap& m)
      : ByCorner(
            m.size(), [&m](std::size_t q) -> const Quad& { return m.quads[q]; },
            [](std::size_t q) { return static_cast<std::uint32_t>(q); }) {}
};

/// Whether the front after a gluing onto `before` is still proper, checked
/// only where the gluing changed it (the quads it added, against every quad
/// sharing a vertex with them): no directed edge run twice, no edge joining
/// opposite corners of a quad, no two quads with the same opposite corners.
bool glued_front_is_proper(const quadmap::QuadMap& before, const QuadsAtVertex& at, const quadmap::GluedHex& glued);

/// Whether `hex`, glued onto the front quads `covered`, meets every other
/// front quad in no more than a vertex or an edge of both: the hex that later
/// covers that quad from the cavity would meet `hex` there. Only quads at the
/// hex's corners can fail.
bool touches_front_properly(const Hex& hex, const quadmap::QuadMap& front, const QuadsAtVertex& at,
                            const std::vector<std::uint32_t>& covered);

}  // namespace loom::closure
