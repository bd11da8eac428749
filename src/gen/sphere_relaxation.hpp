#pragma once
// The two relaxations of the randquad embedding (gen::embed_on_sphere), on a
// layout of a centred triangulation on the unit sphere. Neither turns a
// counter-clockwise triangle clockwise.
#include <vector>

#include "src/gen/centred_triangulation.hpp"

namespace loom::gen {

/// Evens out the layout: Gauss-Seidel sweeps in which each node moves to the
/// minimum of a log barrier on its counter-clockwise triangles (which pushes
/// triangles towards equal area and keeps them from turning over) plus weak
/// springs on its edges (which keep the triangles compact). The first sweeps
/// also apply a Möbius transformation that moves the centre of mass towards
/// the origin, spreading what the starting layout crowded on one side.
void spread_on_sphere(std::vector<Vec3>& points, const CentredTriangulation& mesh);

/// Greedy repair of quads that are folded seen from outside (folded_quad_count):
/// a corner of such a quad moves to whichever of a few nearby positions leaves
/// the fewest folded quads around it.
void unfold_quads(std::vector<Vec3>& points, const CentredTriangulation& mesh, const std::vector<Quad>& quads);

}  // namespace loom::gen
