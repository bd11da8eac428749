#pragma once
// Every simple quadrangulation of the sphere with all vertex degrees >= 3,
// up to isomorphism (reflections included): OEIS A078666 (1, 0, 1, 1, 3, 3,
// 12, 19, 64, 155, 510, ... for 6, 7, 8, ... quads), and among them the
// 3-connected ones, A007022 (1, 0, 1, 1, 3, 3, 11, 18, 58, 139, 451, ...).
//
// Grown size by size from the pseudo-double wheels by three expansions that
// keep the class: a vertex split (+1 quad: a vertex is cut in two along two
// of its edges and a quad opens between the halves), a hex glued onto one
// edge (+2) and a hex glued onto one quad (+4). Completeness is not taken on
// trust: tests/test_quadmap.cpp compares the counts with both sequences.
#include <functional>
#include <vector>

#include "src/quadmap/canonical.hpp"
#include "src/quadmap/quad_map.hpp"

namespace loom::quadmap {

struct QuadrangulationClass {
  int quads = 0;
  /// Canonical codes (canonical_unoriented), sorted: index i is quadrangulation i of this size.
  std::vector<Code> codes;
  std::vector<bool> three_connected;  ///< per code
};

/// The classes for 6..max_quads quads, smallest first. `progress` (if set) is
/// called after each size.
std::vector<QuadrangulationClass> enumerate_quadrangulations(
    int max_quads, const std::function<void(const QuadrangulationClass&)>& progress = {});

/// The 3-connected quadrangulations with exactly `quads` quads, in the order
/// of enumerate_quadrangulations (their canonical maps, vertices 0..n-1).
std::vector<QuadMap> three_connected_quadrangulations(int quads);

/// The maps one vertex split away from `m` (every vertex, every pair of its
/// edges leaving both halves of degree >= 3).
std::vector<QuadMap> vertex_splits(const QuadMap& m);

}  // namespace loom::quadmap
