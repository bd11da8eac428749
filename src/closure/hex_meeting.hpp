#pragma once
// How two hexes of a valid mesh may meet (validity.md, criteria 2 and 3, as
// Verhetsel et al. state them): in nothing, one vertex, one edge of both, or
// one face of both, and a face of both only where the mesh means them to
// share it. Hexes are VTK-ordered corner lists.
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::closure {

/// The corners of `a` that are also corners of `b`, as a bit set over a's 8 corners.
std::uint8_t shared_corners(const Hex& a, const Hex& b);

/// Whether the corners of `hex` in `corners` (bit set) are the two ends of
/// one of its edges.
bool is_hex_edge(std::uint8_t corners);
/// Whether they are the four corners of one of its faces.
bool is_hex_face(std::uint8_t corners);

/// Whether a hex `glued` onto the quads `onto` (faces of it, on a front)
/// meets a hex `other` already placed as a valid mesh allows: in nothing, in
/// one vertex, in one edge of both that lies on one of those quads, or in one
/// of those quads. An edge elsewhere would be an edge of `other` the new hex
/// reaches round the outside of the front, with two fans of hexes round it.
bool meets_as_glued(const Hex& glued, const Hex& other, const std::vector<const Quad*>& onto);

}  // namespace loom::closure
