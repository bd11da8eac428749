#pragma once
// Closing a cavity by search (Verhetsel, Pellerin & Remacle 2019): hexes are
// glued onto the front one at a time (hex_glue.hpp) until what is left is a
// cube or a boundary the database holds, whose mesh then goes in whole.
// Anytime weighted best-first search (engine/search.hpp) over fronts: cost =
// hexes placed + irregularity_weight * irregularity, estimate = a quarter of
// the front's quads (a glued hex removes at most four), lower bound = a sixth
// of them; fronts merged by canonical code. The cheapest closure found within
// the budget wins. Deterministic.
// Irregularity (irregularity.hpp) is where the valid-geometry issue found the
// inverted hexes: interior edges with other than 4 hexes round them.
#include <cstdint>
#include <vector>

#include "engine/search.hpp"
#include "src/closure/cavity.hpp"
#include "src/closure/database.hpp"
#include "src/closure/hex_source.hpp"

namespace loom::closure {

struct ClosureOptions {
  /// Budgets are in expansions, so that a result never depends on the
  /// machine's speed; the seconds are only a guard against a runaway search.
  /// Weight 20 (greedy) closes more than 3 or 6 within a budget: 523 of the
  /// 525 small quadrangulations against 517 and 518 (docs/results.md).
  engine::SearchLimits limits{4'000, 1'000'000, 600.0, 20.0};
  /// Fronts larger than the starting one by more than this are not explored.
  int max_growth = 8;
  /// 0: the fewest hexes, whatever their valences. Weight 1 leaves fewer
  /// hexes inverted on random quadrangulations but closes large cavities
  /// less often (docs/results.md), so 0 is the default everywhere.
  double irregularity_weight = 0;
  /// Memory for the fronts of expanded states kept for their children
  /// (front_store.hpp); the result does not depend on it, only the time.
  std::size_t front_bytes = std::size_t{256} << 20;
};

/// Where a search's time went, in seconds.
struct SearchProfile {
  double rebuild = 0;    ///< rebuilding the fronts of the states expanded
  double canonical = 0;  ///< canonical codes of small fronts (merging, database)
  double database = 0;   ///< placing database meshes and cubes
  double gluing = 0;     ///< trying every gluing and its checks
};

struct ClosureResult {
  bool closed = false;
  /// The hexes placed, in order; their new vertices are numbered from the
  /// cavity's vertex_bound on. When not closed: those of the closest state.
  std::vector<Hex> hexes;
  std::vector<HexSource> source;  ///< per hex: searched or database
  std::uint32_t vertex_bound = 0;  ///< every id used is below it
  /// When not closed: the cavity left at the state with the smallest front
  /// reached (its hexes: the cavity's, then `hexes`).
  Cavity left;
  engine::SearchStats stats;
  SearchProfile profile;
};

ClosureResult close_cavity(const Cavity& cavity, const Database* db, const ClosureOptions& options);

}  // namespace loom::closure
