#pragma once
// Surface in, hex mesh out: the one entry point `loom weave` and the tests
// use. It sits above weave/, closure/ and fill/ and decides which of them
// runs (docs/closure.md):
//   1. weave: the rules, under the strategy, then under the random strategy
//      with seeds 1, 2, ... until a weave gives a mesh passing criteria 1-6
//      (MeshingOptions::attempts);
//   2. cavity closure (unless Closure::none): when no weave did, the woven
//      hexes of the attempt that left the fewest whiskers are kept as far as
//      they can be part of a valid mesh, and each cavity left is closed by
//      search and the database, then (Closure::full) filled where the search
//      stopped short. A surface of at most kDirectSearchQuads quads, and one
//      whose cavities needed the fill, is also closed by search from the
//      surface itself (no woven hex), and the better mesh kept (Prefer);
//   3. whole-surface fill (Closure::full), the last resort.
// A solid with handles (genus > 0) gets one weave (all of them under
// Closure::none); when that does not mesh it, it is cut into a ball along
// disks spanning its meridians, and the ball goes through 1-3.
// Then node placement and the validity check.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/closure/symmetric_search.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/geometry/inversion_causes.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/pipeline/cavity_closure.hpp"
#include "src/stc/stc.hpp"
#include "src/weave/smoothing.hpp"
#include "src/weave/weave.hpp"

namespace loom::pipeline {

enum class Closure {
  none,    ///< the weave's mesh or nothing
  search,  ///< also close cavities by search and the database (no fill)
  full,    ///< also fill what the search leaves, and at last the whole surface
};

/// Surfaces with at most this many quads are also closed by search alone
/// (with a short budget beside a valid woven mesh of at most 72 hexes: it has
/// to beat that one).
inline constexpr std::size_t kDirectSearchQuads = kSmallFrontQuads;

/// Fronts 16 quads larger than the surface, 1,000,000 expansions, room for
/// 20,000,000 open states, and a seconds guard of an hour.
closure::ClosureOptions wide_search_defaults();

/// Which of two meshes, each passing criteria 1-6, the run keeps.
enum class Prefer {
  /// The one with fewer hexes <= 0 once placed, then fewer < 0.2, then fewer
  /// hexes: a mesh a solver accepts beats a smaller one it refuses.
  quality,
  /// The one with fewer hexes (before the boundary layer): the combinatorial
  /// corpus's measure, against the published bounds.
  fewest_hexes,
};

struct MeshingOptions {
  weave::WeaveOptions weave;
  /// Weaves in all (see step 1); deterministic: the same attempts in the same order.
  std::size_t attempts = 1;
  /// Called before each attempt but the first (a trace starts again), with
  /// the weave of the attempt before it.
  std::function<void(std::size_t attempt, const engine::Strategy&, const weave::WeaveResult& previous)> before_attempt;
  /// Called as each stage starts: "weaving", "placing nodes", "closing
  /// cavities", "searching from the surface", "searching symmetric pairs",
  /// "filling the surface"; with handles also "cutting along meridian disks"
  /// and "placing the glued solid" (progress).
  std::function<void(const char* stage)> on_stage;
  Closure closure = Closure::none;
  Prefer prefer = Prefer::quality;
  /// The database file and the fill's caps directory, read when first needed.
  std::filesystem::path database, fill_caps;
  /// The cavity search (irregularity_weight 0 by default: docs/results.md
  /// has what weight 1 gives); a small surface's search against the
  /// published bound counts hexes alone whatever the weight.
  closure::ClosureOptions search;
  /// The wide search a surface of at most 20 quads gets when the searches
  /// before it leave it over 72 hexes (mesh_surface.cpp has the figures),
  /// and, under Prefer::quality, with a hex <= 0.
  closure::ClosureOptions wide_search = wide_search_defaults();
  /// The symmetric search such a surface gets first, when it has a symmetry
  /// of order 2 (closure/symmetric_search.hpp).
  closure::SymmetricOptions symmetric;
};

struct MeshingResult {
  stc::Stc stc;                          ///< the last attempt's final weave state
  weave::WeaveResult weave;              ///< of the last attempt
  std::optional<HexMesh> mesh;           ///< when some stage gave one
  std::vector<closure::HexSource> source;  ///< per hex of `mesh`
  std::optional<ValidityReport> check;   ///< of `mesh`, against the surface
  weave::SmoothingReport smoothing;      ///< of the mesh as returned
  /// Hexes and nodes added by pillowing the boundary layer (zero when it was
  /// not needed): done when placement leaves hexes <= 0, kept when it helps.
  geometry::BoundaryLayerReport boundary_layer;
  std::string failure;                   ///< why a closed weave gave no mesh
  /// Which stage made the mesh: "woven", "closed" (cavity closure), "searched"
  /// (search from the surface itself) or "filled" (whole-surface fill).
  std::string made_by;
  ClosureReport closure;                 ///< of the cavity closure, when it ran
  std::string closure_failure;           ///< why it gave no mesh, when it ran and did not
  std::string fill_failure;              ///< why the whole-surface fill could not run
  /// Why the symmetric or the wide search stopped before its budget ("" when
  /// neither ran, or both ran to their end): the run keeps the mesh it had.
  std::string wide_search_stopped;
  /// Of `mesh` as returned: why each inverted hex is (once, for the warning
  /// line, the report and the cell field).
  geometry::InversionDiagnosis inversions;
  double seconds = 0;                    ///< of everything
  /// Meshes placed (boundary layer, smoothing, untangling) and checked, every
  /// candidate's whether kept or not, and their seconds: on small parts most
  /// of `seconds` (bench/README.md has the profile).
  std::size_t placements = 0;
  double placement_seconds = 0;
  /// Disks the solid was cut along into a ball (0 for a ball, or a solid with
  /// handles the weave meshed whole); the mesh then holds the ball's, glued,
  /// and `stc`, `weave`, `closure` and `strategy` are the ball's.
  int cut_disks = 0;
  /// Weaves of the solid itself before it was cut (the first of `attempts`).
  std::size_t attempts_before_cut = 0;
  std::size_t attempts = 1;              ///< weaves run (the solid's, then the ball's)
  /// The attempt (1 for the first) whose woven hexes the mesh holds: the last
  /// when the weave made the mesh, the one that left the fewest whiskers when
  /// the closure did; 0 when no woven hex is in it (the closure peeled them
  /// all, or a search from the surface or the fill made it).
  std::size_t woven_attempt = 0;
  Prefer prefer = Prefer::quality;       ///< what chose the mesh (MeshingOptions::prefer)
  engine::Strategy strategy;             ///< of the last attempt, the one reported
  /// The mesh passes criteria 1-6 (geometry may still be bad).
  bool combinatorially_valid() const { return mesh && check && check->combinatorial_valid(); }
  bool filled() const { return made_by == "filled"; }
};

/// What `loom weave` runs with no options: 16 attempts, Closure::full,
/// Prefer::quality, and the closure database and fill caps of `rules_dir`
/// (closure/database.txt, fill/), or none where it has none: a rules
/// directory brings its own, as a copy of the shipped rules/ does.
MeshingOptions default_meshing_options(const std::filesystem::path& rules_dir = weave::default_rules_dir());

/// Weaves a validated, outward-oriented surface with `rules`, then closes or
/// fills as MeshingOptions::closure allows. A rule that fails while it runs
/// throws engine::RuleError naming its file and line.
MeshingResult mesh_surface(const QuadSurface& surface, std::vector<engine::Rule> rules, const MeshingOptions& options);

}  // namespace loom::pipeline
