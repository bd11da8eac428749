#pragma once
// Whether any hex mesh can have a given quad surface as its boundary.
//
// Erickson (DCG 2014, after Eppstein 1999): a quad surface bounds a hex mesh of
// the solid it encloses if and only if it has an even number of quads and every
// cycle of its edges that bounds a surface inside the solid has an even number
// of edges. On a sphere every cycle bounds and every cycle is even (the quads
// make the graph bipartite). On a surface of genus g the cycles that bound
// inside, up to cycles that bound on the surface, form a space of dimension g:
// the meridians (a torus's small circle, not its large one).
//
// They are found from the embedding, by linking numbers (Alexander duality): a
// cycle bounds inside exactly when, pushed a little inward, it links no cycle
// of the surface pushed a little outward. Every quad being even, a cycle's
// parity depends on its class only, so checking a basis of the meridians
// checks them all.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom {

/// A closed walk of surface nodes, the first not repeated at the end; its
/// length is its number of edges.
using NodeCycle = std::vector<std::uint32_t>;

struct MeridianReport {
  int genus = 0;
  /// False when the linking numbers could not be trusted (a surface that meets
  /// itself, or one too thin for the push): nothing below is then known.
  bool determined = true;
  /// A basis of the meridians, shortest found first (short, not proven shortest).
  std::vector<NodeCycle> meridians;
  /// With find_meridians(surface, n): up to n more short cycles bounding
  /// inside, shortest first (MeridianSearch::alternatives).
  std::vector<NodeCycle> alternatives;
  /// A short meridian with an odd number of edges, if there is one: then no
  /// hex mesh has this boundary.
  std::optional<NodeCycle> odd;
};

/// Requires a surface that validate_surface accepts, facing outward.
MeridianReport find_meridians(const QuadSurface& surface, std::size_t alternatives = 0);

/// "a-b-c-a (3 edges)": the nodes, the first repeated at the end, at most
/// `shown` of them before an ellipsis.
std::string describe_cycle(const NodeCycle& cycle, std::size_t shown = 12);

}  // namespace loom
