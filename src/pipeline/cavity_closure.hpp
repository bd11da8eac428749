#pragma once
// Closing what a weave leaves (docs/closure.md): the woven hexes are kept as
// far as they can be part of a valid mesh (closure/cavities.hpp), each cavity
// between them and the surface is closed by search and the database
// (closure/shelling_search.hpp), and where the search stops short, the front
// it reached is filled constructively (fill/fill.hpp). Every woven hex kept
// stays; the whole-surface fill is not used here.
#include <cstddef>
#include <vector>

#include "src/closure/database.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/fill/cap.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::pipeline {

/// A search's budget grows with its front: large fronts take more gluings to
/// close (randquad 200: about 20,000 expansions, 13 s). Fronts of at most 24
/// quads, where gluings are few and paths to the database long, get 50,000.
inline constexpr std::size_t kExpansionsPerQuad = 100;
inline constexpr std::size_t kMostExpansions = 100'000;
inline constexpr std::size_t kSmallFrontQuads = 24;
inline constexpr std::size_t kSmallFrontExpansions = 50'000;
/// Rounds of pulling back round a stuck front before the fill takes it.
inline constexpr std::size_t kMostPullBacks = 6;

struct ClosureReport {
  std::size_t woven = 0;        ///< woven hexes kept
  std::size_t peeled = 0;       ///< woven hexes removed: peeled to leave proper fronts, or pulled back
  std::size_t cavities = 0;     ///< pieces of the front
  std::size_t front_quads = 0;  ///< quads of those fronts, before the search
  std::size_t searched = 0, database = 0, filled = 0;  ///< hexes added, by source
  std::size_t pillowed = 0;         ///< hexes of the pillows round filled cavities
  std::size_t pull_backs = 0;       ///< rounds that pulled back round a stuck front
  std::size_t filled_cavities = 0;  ///< cavities the search left to the fill
  std::size_t fill_quads = 0;       ///< quads of the fronts the fill got
  engine::SearchStats search;       ///< summed over the cavities
  double seconds = 0;
};

struct ClosedMesh {
  /// Every cavity closed; false when one was left and there were no caps to fill it.
  bool complete = true;
  HexMesh mesh;  ///< the surface's points first, in order
  std::vector<closure::HexSource> source;  ///< per hex
  std::vector<bool> on_boundary;           ///< per point: a surface node
  ClosureReport report;
};

/// The mesh of a search from the whole surface (closure::close_symmetric):
/// its hexes over the surface's points and the new ones, which get first
/// positions as close_cavities gives them, and its report by source.
ClosedMesh mesh_of_closure(const QuadSurface& surface, const closure::ClosureResult& closed);

/// What is left of a mesh after a pull-back (without_hexes_on).
struct PulledBack {
  HexMesh mesh;
  std::vector<std::size_t> kept;  ///< per hex of `mesh`: its index in the mesh it came from
};

/// The hexes of `m` but those with a face on `front` (as a set of corners:
/// the hexes a stuck front is pressed against), over the points they use; the
/// first `keep_points` points (the surface's) stay first and in order.
PulledBack without_hexes_on(const HexMesh& m, const std::vector<Quad>& front, std::size_t keep_points);

/// `woven`: hexes over points whose first surface.points.size() are the
/// surface's (stc::woven_over_surface). Each cavity's search gets a budget
/// by its front (above; at least options' budget); when it stops short, the
/// search runs again on what it left, while that keeps shrinking. Where it
/// is stuck even so, the front is pressed against hexes that leave it no
/// way on: those hexes (woven or searched) are pulled back, and the cavities
/// closed again, up to kMostPullBacks times (CAD part bosses-free 3: a
/// 54-quad front stuck after 97,800 expansions closed after three pull-backs).
/// `db` may be null; with no `caps`, a
/// cavity the search does not close stays open (ClosedMesh::complete false).
/// A filled cavity is pillowed (geometry::pillow_region), so that its fill
/// meets the hexes round it in single faces, edges or vertices. Throws
/// InputError when a cavity cannot be filled (the fill's message).
/// `woven_source` says where each hex of `woven` came from (a template rule
/// puts database hexes into a weave); empty means every one is woven.
ClosedMesh close_cavities(const QuadSurface& surface, const HexMesh& woven, const closure::Database* db,
                          const std::vector<fill::Cap>& caps, const closure::ClosureOptions& options,
                          const std::vector<closure::HexSource>& woven_source = {});

}  // namespace loom::pipeline
