#pragma once
// Why a placed hex is inverted (scaled Jacobian <= 0), as far as the mesh's
// connectivity and its fixed boundary can tell (docs/geometry.md). Given with
// the mesh it is about, so that a user sees which hexes no placement can fix
// and which ones the untangler could not.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom::geometry {

enum class InversionCause : std::uint8_t {
  none,  ///< scaled Jacobian > 0
  /// A corner <= 0 whose node and its three neighbours in the hex are all on
  /// the boundary, which placement never moves: no placement can fix it
  /// (a hex with two faces on one flat or concave part of the surface).
  locked_corner,
  /// On an interior edge with kCrowdedEdge hexes or more round it: the
  /// dihedral angles there average 360/N degrees, and this is where the
  /// untangler's failures cluster (docs/results.md). No proof that a
  /// placement does not exist.
  crowded_edge,
  unexplained,  ///< neither: the untangler stopped in a local minimum
};
inline constexpr std::size_t kInversionCauses = 4;
inline constexpr std::uint32_t kCrowdedEdge = 6;

/// "none", "locked_corner", "crowded_edge", "unexplained" (the report's keys).
const char* cause_name(InversionCause cause);

struct InversionDiagnosis {
  std::vector<InversionCause> cause;  ///< per hex
  std::array<std::size_t, kInversionCauses> count{};
  std::uint32_t most_crowded = 0;  ///< the most hexes round an interior edge of an inverted hex
  std::size_t inverted() const { return count[1] + count[2] + count[3]; }
  std::size_t of(InversionCause c) const { return count[static_cast<std::size_t>(c)]; }
};

/// Boundary nodes are those of the faces that one hex holds. A mesh failing
/// criterion 1 (8 distinct nodes per hex, within the points) has no topology
/// to go by: its inverted hexes are all unexplained.
InversionDiagnosis diagnose_inversions(const HexMesh& mesh);

/// "4 with a corner locked by the boundary (...), 12 on interior edges of 6
/// to 9 hexes, 8 where the untangler stopped short with no such cause": the
/// parts with a count > 0; "" when no hex is inverted.
std::string describe(const InversionDiagnosis& d);

}  // namespace loom::geometry
