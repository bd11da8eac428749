#pragma once
// What an accepted hex mesh is (docs/validity.md, after the design notes'
// validity.md): combinatorial criteria 1-6 and the scaled Jacobian (7).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

struct CriterionResult {
  int number = 0;    ///< 1..7 as in validity.md
  std::string name;  ///< short name, e.g. "no doublets" (criterion_name(number))
  bool passed = true;
  std::string detail;  ///< first offending element(s) when failed
  /// False when the criterion could not be decided (2-6 need criterion 1 to
  /// hold); such a criterion also has passed == false.
  bool evaluated = true;
};

struct QualitySummary {
  double min_scaled_jacobian = 0, mean_scaled_jacobian = 0;
  std::size_t below_zero = 0;  ///< elements with scaled Jacobian <= 0
  std::size_t below_0_2 = 0;   ///< elements with scaled Jacobian < 0.2
  /// The same with the centre too, as Verdict (ParaView's Mesh Quality)
  /// measures: a twisted hex can have every corner positive and its centre not.
  double min_verdict_scaled_jacobian = 0;
  std::size_t verdict_below_zero = 0;
};

struct ValidityReport {
  std::vector<CriterionResult> criteria;  ///< in order 1..7 (6 only with a boundary)
  QualitySummary quality;
  std::size_t hexes = 0, nodes = 0;
  std::size_t boundary_components = 0;  ///< pieces of the mesh's boundary (when 5 was evaluated)
  int boundary_genus = 0;               ///< summed over those pieces
  bool combinatorial_valid() const;     ///< criteria 1-6 pass
  bool valid() const;                   ///< all pass (7: every element > 0)
  /// The first failed criterion, if any.
  const CriterionResult* first_failure() const;
};

/// "distinct nodes", "faces in one or two hexes", "no doublets", "manifold",
/// "Euler characteristic", "boundary matches surface", "positive scaled Jacobian".
std::string criterion_name(int number);

/// Scaled Jacobian of one hex (criterion 7): minimum over the 8 corners
/// (Verdict's corner edge triples, VTK order) of det[e1,e2,e3]/(|e1||e2||e3|),
/// computed on unit edge vectors so that it does not depend on the scale; -1
/// for a corner with a zero-length or non-finite edge, and for a hex with a
/// node out of range. Verdict's hex_scaled_jacobian also tests the centre
/// (centre_scaled_jacobian; QualitySummary reports both).
double scaled_jacobian(const HexMesh& mesh, std::size_t hex);

/// The same at one corner (0..7, VTK order) of a hex.
double corner_scaled_jacobian(const HexMesh& mesh, std::size_t hex, int corner);

/// The same at a corner at `corner` whose edges run to a, b and c, in the
/// order that makes a corner of a positive hex positive.
double corner_scaled_jacobian(const Vec3& corner, const Vec3& a, const Vec3& b, const Vec3& c);

/// The same at the centre, from the principal axes p1 - p0 + p2 - p3 + p5 -
/// p4 + p6 - p7 and the like (Verdict's): <= 0 on a twisted hex whose corners
/// may all be positive.
double centre_scaled_jacobian(const HexMesh& mesh, std::size_t hex);

/// The three corners joined to `corner` by an edge of the hex, in the order
/// whose edge vectors span a positive corner.
const std::array<int, 3>& hex_corner_neighbours(int corner);

/// Applies every criterion. With `boundary`, criterion 6 compares the mesh's
/// boundary quads with it (same nodes at the same coordinates, one to one).
/// Linear in the mesh size apart from sorting the boundary (O(n log n)).
ValidityReport check_hex_mesh(const HexMesh& mesh, const QuadSurface* boundary = nullptr);

}  // namespace loom
