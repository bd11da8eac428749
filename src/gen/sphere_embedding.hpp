#pragma once
// Places the nodes of a combinatorial quadrangulation of the sphere on the unit
// sphere, for gen::randquad.
#include <cstddef>
#include <random>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::gen {

/// Positions on the unit sphere for nodes 0..node_count-1 of `quads` (a closed,
/// simple quadrangulation of the sphere, counter-clockwise seen from outside),
/// with the quads counter-clockwise seen from outside and, where the
/// relaxation manages it, not folded. `rng` picks the quad the layout starts
/// from.
std::vector<Vec3> embed_on_sphere(const std::vector<Quad>& quads, std::size_t node_count, std::mt19937_64& rng);

/// Whether a quad is folded seen from outside: projected onto the plane normal
/// to the sum of its corners, fewer than three of its corners turn left (a
/// simple counter-clockwise quad has four, or three if it is not convex).
bool quad_is_folded(const std::vector<Vec3>& points, const Quad& quad);

/// Number of folded quads.
std::size_t folded_quad_count(const std::vector<Vec3>& points, const std::vector<Quad>& quads);

}  // namespace loom::gen
