#pragma once
// Closing a symmetric surface by symmetric shelling: a hex is glued onto the
// surface together with its image under a symmetry of order 2, so the front
// stays symmetric and each step places a pair. Every front reached is then
// closed by close_cavity (without symmetry) on a small budget, and the
// fewest hexes in all win.
//
// Why: the plain search glues one hex at a time from the cheapest front, and
// on the surfaces with two poles of high degree it keeps meeting the same
// fronts. On the octagonal trapezohedron (quadrangulation 16 439) it never
// finds fewer than 78 hexes, even at 1,000,000 expansions or with a database
// of every mesh of up to 9 hexes; five symmetric pairs and a search on the
// 32-quad front they leave give 68 (docs/results.md).
//
// A beam search (engine/beam_search.hpp) over pairs: each level keeps the
// fronts whose inner search closed them in the fewest hexes. It runs once for
// each class of symmetries of order 2 (conjugate ones act alike). Orbits of 4
// or 8 hexes grow the front past the bound within two levels (measured on
// 16 439), so only order 2 is used. Deterministic.
#include "engine/beam_search.hpp"
#include "src/closure/database.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/quadmap/quad_map.hpp"

namespace loom::closure {

struct SymmetricOptions {
  /// 16 439: 68 hexes at width 10 and depth 5 (20 s a class of symmetries); 30 is no better.
  engine::BeamLimits beam{10, 6, 10'000, 600.0, 1.0};
  /// The search that closes each front the pairs reach.
  ClosureOptions each{{1'000, 1'000'000, 600.0, 20.0}, 8};
  /// Fronts larger than the surface by more than this are not kept.
  int max_growth = 16;
};

/// The fewest hexes found over every class of symmetries of order 2 (not
/// closed when the surface has none, or no front reached was closed). Hexes
/// are numbered as close_cavity numbers them: new vertices from the
/// surface's vertex_bound on. `stats` sums the beams' and their inner
/// searches' (expansions, states), so its rates compare with close_cavity's.
ClosureResult close_symmetric(const quadmap::QuadMap& surface, const Database* db, const SymmetricOptions& options);

}  // namespace loom::closure
