// Criterion 7 and the scaled Jacobian itself (Verdict's corner form), and the
// centre Verdict also tests, reported beside it.
#include <algorithm>
#include <cmath>

#include "src/check/criteria.hpp"

namespace loom {

namespace {
/// For each corner, the three neighbours whose edges span it (Verdict's triples,
/// VTK order); det[e1,e2,e3] > 0 at every corner of a positively oriented hex.
constexpr std::array<std::array<int, 3>, 8> kCornerEdges{
    {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}}};

/// `e` scaled to length 1; false for a zero-length or non-finite edge. Dividing
/// by the largest component first keeps the squares from overflowing (edges of
/// 1e300) or underflowing (1e-300), so the value does not depend on the scale.
bool normalize(Vec3& e) {
  const double largest = std::max({std::abs(e[0]), std::abs(e[1]), std::abs(e[2])});
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  for (double& x : e) x /= largest;
  const double length = norm(e);  // in [1, sqrt(3)]
  for (double& x : e) x /= length;
  return true;
}
}  // namespace

const std::array<int, 3>& hex_corner_neighbours(int corner) { return kCornerEdges[static_cast<std::size_t>(corner)]; }

double corner_scaled_jacobian(const HexMesh& mesh, std::size_t hex, int corner) {
  const Hex& nodes = mesh.hexes[hex];
  const auto& n = kCornerEdges[static_cast<std::size_t>(corner)];
  for (int i : {corner, n[0], n[1], n[2]})
    if (nodes[static_cast<std::size_t>(i)] >= mesh.points.size()) return -1.0;
  auto at = [&](int i) -> const Vec3& { return mesh.points[nodes[static_cast<std::size_t>(i)]]; };
  return corner_scaled_jacobian(at(corner), at(n[0]), at(n[1]), at(n[2]));
}

double corner_scaled_jacobian(const Vec3& corner, const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 e1 = a - corner, e2 = b - corner, e3 = c - corner;
  if (!normalize(e1) || !normalize(e2) || !normalize(e3)) return -1.0;
  const double value = dot(e1, cross(e2, e3));
  return std::isfinite(value) ? value : -1.0;
}

double centre_scaled_jacobian(const HexMesh& mesh, std::size_t hex) {
  const Hex& n = mesh.hexes[hex];
  for (std::uint32_t v : n)
    if (v >= mesh.points.size()) return -1.0;
  auto p = [&](int i) { return mesh.points[n[static_cast<std::size_t>(i)]]; };
  Vec3 xi = p(1) - p(0) + p(2) - p(3) + p(5) - p(4) + p(6) - p(7);
  Vec3 eta = p(3) - p(0) + p(2) - p(1) + p(7) - p(4) + p(6) - p(5);
  Vec3 zeta = p(4) - p(0) + p(5) - p(1) + p(6) - p(2) + p(7) - p(3);
  if (!normalize(xi) || !normalize(eta) || !normalize(zeta)) return -1.0;
  const double value = dot(xi, cross(eta, zeta));
  return std::isfinite(value) ? value : -1.0;
}

double scaled_jacobian(const HexMesh& mesh, std::size_t hex) {
  double worst = 1.0;
  for (int corner = 0; corner < 8; ++corner) worst = std::min(worst, corner_scaled_jacobian(mesh, hex, corner));
  return worst;
}

namespace criteria {

CriterionResult positive_scaled_jacobian(const HexMesh& mesh, QualitySummary& quality) {
  quality = {};
  if (mesh.hexes.empty()) return failed(7, "the mesh has no hexes");
  double sum = 0;
  std::size_t first_bad = mesh.hexes.size();
  double first_bad_value = 0;
  quality.min_scaled_jacobian = quality.min_verdict_scaled_jacobian = 1.0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const double sj = scaled_jacobian(mesh, h);
    sum += sj;
    quality.min_scaled_jacobian = std::min(quality.min_scaled_jacobian, sj);
    if (sj < 0.2) ++quality.below_0_2;
    const double verdict = std::min(sj, centre_scaled_jacobian(mesh, h));
    quality.min_verdict_scaled_jacobian = std::min(quality.min_verdict_scaled_jacobian, verdict);
    quality.verdict_below_zero += verdict <= 0;
    if (sj <= 0) {
      if (quality.below_zero++ == 0) {
        first_bad = h;
        first_bad_value = sj;
      }
    }
  }
  quality.mean_scaled_jacobian = sum / static_cast<double>(mesh.hexes.size());
  if (quality.below_zero == 0) return passed(7);
  return failed(7, fmt::format("hex {} has scaled Jacobian {:.3f} ({} hex{} at or below 0)", first_bad, first_bad_value,
                               quality.below_zero, quality.below_zero == 1 ? "" : "es"));
}

}  // namespace criteria
}  // namespace loom
