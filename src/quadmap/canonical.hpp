#pragma once
// Canonical codes of connected simple quad maps: equal codes exactly when
// the maps are isomorphic (tests/test_quadmap.cpp checks this against nauty).
//
// The code starts with the degrees of the start quad's corners (kCodePrefix
// numbers, an invariant that rules out most start darts at once). Then, from
// the start dart, the quads are visited breadth first: the start quad read
// from the start dart's tail, then, in the order their sides are read, the
// quads across those sides, each read from the corner its entering dart
// starts at. Vertices are numbered in the order they are first read, and the
// code is the sequence of numbers read (four per quad). The canonical code is
// the least over every start dart; the start darts that give it are one per
// orientation-preserving automorphism. For a simple map the code is the map
// itself, relabelled, so equal codes mean isomorphic maps.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "src/quadmap/quad_map.hpp"

namespace loom::quadmap {

using Code = std::vector<std::uint16_t>;
/// Numbers before the quads in a code: the start quad's corner degrees.
inline constexpr std::size_t kCodePrefix = 4;
/// Quads a code describes.
inline std::size_t code_quads(const Code& c) { return (c.size() - kCodePrefix) / 4; }

struct CodeHash {
  std::size_t operator()(const Code& c) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint16_t x : c) h = (h ^ x) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

struct Canonical {
  Code code;
  /// The code is the mirror image's (canonical_unoriented only): the map
  /// matches a stored map with this code through an orientation-reversing
  /// isomorphism.
  bool mirrored = false;
  /// Every start dart giving the code, in the map as read (the mirror image's
  /// darts when `mirrored`); one per automorphism.
  std::vector<Dart> starts;
};

/// Up to orientation-preserving isomorphism. The map must be connected and simple.
Canonical canonical_oriented(const QuadMap& m, const std::vector<Dart>& twin);
Canonical canonical_oriented(const QuadMap& m);
/// Up to any isomorphism: the lesser of the map's code and its mirror image's.
Canonical canonical_unoriented(const QuadMap& m);
Canonical canonical_unoriented(const QuadMap& m, const std::vector<Dart>& twin);

/// Canonical number of each vertex (index: vertex) when the code is read from
/// `start`; vertices the reading never reaches stay no_vertex.
std::vector<Vertex> labels_from(const QuadMap& m, const std::vector<Dart>& twin, Dart start);

/// The quads a code describes (vertices 0..n-1 as numbered in it).
QuadMap map_of_code(const Code& code);

/// A code as text: groups of four separated by spaces, numbers by commas
/// ("3,3,4,3 0,1,2,3 1,0,4,5 ...": the prefix, then the quads).
std::string code_text(const Code& code);

}  // namespace loom::quadmap
