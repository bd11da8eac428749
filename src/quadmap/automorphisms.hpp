#pragma once
// The symmetries of a quad map: its orientation-preserving automorphisms, as
// permutations of its vertices. A map's canonical code is read from one
// start dart per automorphism (canonical.hpp), so reading the vertex labels
// from each of those darts and matching them with the first gives them all.
#include <vector>

#include "src/quadmap/quad_map.hpp"

namespace loom::quadmap {

/// p[v] is the image of vertex v; an id on no quad is its own image.
using Permutation = std::vector<Vertex>;

/// Every orientation-preserving automorphism of a connected simple map, the
/// identity first, in the order of the canonical code's start darts.
std::vector<Permutation> automorphisms(const QuadMap& m);

/// The least k > 0 with p^k the identity.
int order_of(const Permutation& p);

/// One element of each conjugacy class (under `group`) that `elements`
/// meet, the first met of each: elements conjugate by a symmetry of the map
/// act alike on it.
std::vector<Permutation> up_to_conjugacy(const std::vector<Permutation>& elements,
                                         const std::vector<Permutation>& group);

}  // namespace loom::quadmap
