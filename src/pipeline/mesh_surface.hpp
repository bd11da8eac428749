#pragma once
// Surface in, hex mesh out: initial STC, weave, primal construction, node
// placement, validity check. The one entry point `loom weave` and the tests use.
#include <optional>
#include <string>
#include <vector>

#include "src/check/validity.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/stc/stc.hpp"
#include "src/weave/smoothing.hpp"
#include "src/weave/weave.hpp"

namespace loom::weave {

struct MeshingResult {
  stc::Stc stc;                          ///< the weave's final state
  WeaveResult weave;
  std::optional<HexMesh> mesh;           ///< when the weave closed and dualized
  std::optional<ValidityReport> check;   ///< of `mesh`, against the surface
  SmoothingReport smoothing;             ///< of the mesh as returned
  /// Hexes and nodes added by pillowing the boundary layer (zero when it was
  /// not needed): done when placement leaves hexes <= 0, kept when it helps.
  geometry::BoundaryLayerReport boundary_layer;
  std::string failure;                   ///< why there is no mesh, when the weave closed
  /// The mesh is the constructive fill's (WeaveOptions::fill_caps): no weave
  /// gave one. `weave` and `stc` still describe the last attempt.
  bool filled = false;
  std::string fill_failure;              ///< why the fill could not run, when it was asked for
  double seconds = 0;                    ///< of all attempts
  std::size_t attempts = 1;              ///< weaves run (see WeaveOptions::attempts)
  engine::Strategy strategy;             ///< of the last attempt, the one reported
  /// The mesh is written: closed and criteria 1-6 hold (geometry may still be bad).
  bool combinatorially_valid() const { return mesh && check && check->combinatorial_valid(); }
};

/// Weaves a validated, outward-oriented surface with `rules` (again, under
/// other strategies, as WeaveOptions::attempts allows). A rule that
/// fails while it runs throws engine::RuleError naming its file and line.
MeshingResult mesh_surface(const QuadSurface& surface, std::vector<engine::Rule> rules, const WeaveOptions& options);

}  // namespace loom::weave
