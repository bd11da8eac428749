#pragma once
// A mesh on its way out of mesh_surface (internal to src/pipeline/): its
// placement, its check, and its adoption as the result.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "src/check/validity.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/weave/smoothing.hpp"

namespace loom::pipeline {

/// Fewer hexes <= 0, or as many and fewer < 0.2.
bool improves(const weave::SmoothingReport& a, const weave::SmoothingReport& b);

/// A mesh on its way out: its hexes' sources and the nodes placement must not move.
struct Candidate {
  HexMesh mesh;
  std::vector<closure::HexSource> source;
  std::vector<bool> fixed;
  weave::SmoothingReport smoothing;
  std::optional<ValidityReport> check;
  geometry::BoundaryLayerReport layer;
  bool valid() const { return check && check->combinatorial_valid(); }
  /// "criterion N (name) fails: detail" for the first criterion that fails.
  std::string why_invalid() const;
};

/// Adds one placement and its seconds to the result's figures as it goes out
/// of scope (whether the placement returned or threw).
class PlacementTally {
public:
  explicit PlacementTally(MeshingResult& r) : r_(r) {}
  PlacementTally(const PlacementTally&) = delete;
  PlacementTally& operator=(const PlacementTally&) = delete;
  ~PlacementTally() {
    ++r_.placements;
    r_.placement_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  MeshingResult& r_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Node placement, and the boundary layer when it helps. A hex with two faces
/// on one flat part of the boundary has corners whose four nodes are all on
/// the boundary: locked, whatever placement does. When some locked corner is
/// below 0.2 the layer goes in first (placing the mesh without it would be
/// wasted work); otherwise the mesh is placed, and a layer is tried when
/// hexes <= 0 or < 0.2 are left, and kept when it does better.
void place(Candidate& c, const QuadSurface& surface, MeshingResult& r);

/// Takes `c` as the result.
void adopt(MeshingResult& r, Candidate&& c, std::string made_by);

}  // namespace loom::pipeline
