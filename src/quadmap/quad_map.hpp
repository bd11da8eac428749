#pragma once
// QuadMap: a closed, oriented quadrangulation given by its quads alone. The
// combinatorial kernel under the enumerator of sphere quadrangulations and the
// closure search (docs/closure.md): no coordinates, only incidence.
//
// Vertices are ids below vertex_bound (an id on no quad is simply unused);
// each quad lists its corners counter-clockwise seen from its outer side. A *dart* is one side of one quad, run in the
// quad's order: dart 4q+i runs from corner i of quad q to corner i+1. On a
// closed oriented surface every dart has a *twin*, the dart of the other quad
// on its edge, running the other way.
//
// A map is *simple* (why_not_simple() returns "") when
//  1. each quad has four distinct corners;
//  2. each dart has exactly one twin (a closed, oriented 2-manifold) and the
//     quads around each vertex form one cycle;
//  3. no two edges join the same two vertices;
//  4. every vertex on a quad is on at least three.
// It is *proper* (why_not_proper() returns "") when it is simple and also
//  5. no edge joins two opposite corners of a quad, and no two quads have the
//     same pair of opposite corners.
// A front that is not proper bounds no valid hex mesh: conditions 3-5 each
// force two hexes to meet in something other than one face, edge or vertex.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::quadmap {

using Vertex = std::uint32_t;
using Dart = std::uint32_t;
inline constexpr Dart no_dart = UINT32_MAX;
inline constexpr Vertex no_vertex = UINT32_MAX;

struct QuadMap {
  std::vector<Quad> quads;
  /// Every vertex id is below this; a vertex on no quad is not part of the map.
  std::uint32_t vertex_bound = 0;

  std::size_t size() const { return quads.size(); }
  Vertex tail(Dart d) const { return quads[d / 4][d % 4]; }
  Vertex head(Dart d) const { return quads[d / 4][(d + 1) % 4]; }
};

inline Dart next_in_quad(Dart d) { return (d & ~3u) | ((d + 1) & 3u); }
inline Dart prev_in_quad(Dart d) { return (d & ~3u) | ((d + 3) & 3u); }

/// twin[d] for every dart; no_dart where no quad runs the other way. When a
/// directed edge is run by two quads, `duplicate` (if given) is set to one of them.
std::vector<Dart> twins(const QuadMap& m, Dart* duplicate = nullptr);

/// Number of quads at each vertex.
std::vector<int> degrees(const QuadMap& m);

/// "" when simple (conditions 1-4 above), otherwise what is wrong, naming the
/// quads or vertices involved.
std::string why_not_simple(const QuadMap& m);
/// "" when proper (conditions 1-5).
std::string why_not_proper(const QuadMap& m);

/// Whether the vertex graph is 3-connected (no vertex pair whose removal
/// disconnects it). O(V^2 (V+E)): meant for small maps.
bool is_three_connected(const QuadMap& m);

/// The same surface with its orientation reversed (each quad's corners read backwards).
QuadMap mirrored(const QuadMap& m);
/// twins(mirrored(m)) from twins(m): dart (q, k) of the mirror image runs
/// dart (q, 3 - k) of m backwards.
std::vector<Dart> mirrored_twins(const std::vector<Dart>& twin);

/// Quads and vertices of the pseudo-double wheel with `quads` quads (even, >= 6):
/// a cycle of `quads` vertices and two hubs, one joined to the even cycle
/// vertices and one to the odd. For 6 quads it is the cube.
QuadMap pseudo_double_wheel(int quads);

/// The map of a quad surface (its points dropped).
QuadMap from_surface(const QuadSurface& s);

}  // namespace loom::quadmap
