#pragma once
// An all-quad surface mesh from Gmsh, in two halves: what runs inside Gmsh's
// child process (mesh the model's surfaces free, encode the quads as bytes)
// and what runs in Loom after it (decode, orient the patches alike). Used by
// `loom mesh` (cad_part.hpp) and the bosses generators.
#include <string>
#include <string_view>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::cad {

// ---- inside run_gmsh_isolated's child (they call the gmsh:: API) ----

/// Meshes every surface of the current model free and all-quad, Gmsh's
/// largest element size being `size`: Frontal-Delaunay triangles, simple
/// recombination, then the subdivision that splits every triangle into three
/// quads and every quad into four. The subdivision halves each edge, and it
/// makes the count even: a closed mesh of t triangles and q quads has
/// 3t + 4q = 2 * edges, so t is even, and it becomes 3t + 4q quads.
void mesh_free_quads(double size);

/// What mesh_refined_quads made: encode_quads's bytes for the surfaces asked,
/// and how it got there.
struct RefinedQuads {
  std::string bytes;
  double least_sine = 0;  ///< the least corner sine of its quads
  int meshings = 0;       ///< how many meshes were made to choose from
  int balls = 0;          ///< refinement balls the one kept was made with
};

/// mesh_free_quads, then, while a quad has a corner whose sine is below
/// `wanted` and rounds are left, meshes again with Gmsh's size cut to 1.5
/// times such a quad's longest edge within 1.5 of those edges of its centre
/// (the balls of earlier rounds kept). One size for the
/// whole part leaves slivers where a narrow face or a coarse arc forces them,
/// and no hex on such a quad can have a scaled Jacobian above its sine
/// (check/surface_angle_bound.hpp). Keeps the mesh with the greatest least
/// sine (on a tie the first); deterministic.
RefinedQuads mesh_refined_quads(double size, double wanted, const std::vector<int>& surfaces, const std::string& where,
                                const std::string& hint);

/// The quads of `surfaces` (empty: of every surface) with their nodes, as bytes
/// for decode_quads. `where` and `hint` name the caller in the error raised
/// when Gmsh left an element that is not a quad.
std::string encode_quads(const std::vector<int>& surfaces, const std::string& where, const std::string& hint);

// ---- in Loom, after the child ----

/// The surface encode_quads sent; its nodes are numbered in order of first use
/// by the quads, so every node is used. Throws InputError on a short message.
QuadSurface decode_quads(std::string_view bytes, const std::string& where);

/// Gmsh orients each patch by its own parametrisation: flips quads so that each
/// edge is walked in opposite directions by its two quads (a walk across shared
/// edges from the first quad of each component). A surface that cannot be
/// oriented is left for validate_surface to reject.
void orient_consistently(QuadSurface& surface);

}  // namespace loom::cad
