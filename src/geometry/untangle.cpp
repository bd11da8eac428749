#include "src/geometry/untangle.hpp"

#include <algorithm>
#include <array>
#include <new>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <Eigen/Core>
#include <LBFGS.h>

#include "src/geometry/placement_detail.hpp"

namespace loom::geometry {

namespace {

using detail::kCornerEdges;
using V3 = Eigen::Vector3d;
using Vector = Eigen::VectorXd;

/// Below this the regularised terms of inverted corners overflow doubles.
constexpr double kLeastEps = 1e-8;

/// A Jacobian frame of a hex, J = [a b d]: corner k = 0..7 (its node, then
/// the ends of its three edges, right-handed: a = p1 - p0 ...) or kCentre
/// (Verdict's principal axes over four: a = (p1 - p0 + p2 - p3 + p5 - p4 + p6 -
/// p7) / 4 ..., which a twisted hex can invert with every corner positive).
/// Eight bytes: the nodes are read from the hex.
struct Frame {
  std::uint32_t hex;
  std::uint8_t which;
};
constexpr std::uint8_t kCentre = 8;
constexpr std::uint8_t kFrames = 9;

/// The energy of the free nodes' coordinates, for one eps.
class Energy {
public:
  Energy(const HexMesh& mesh, const std::vector<bool>& fixed, double lambda) : mesh_(mesh), lambda_(lambda) {
    variable_.assign(mesh.points.size(), -1);
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
      if (!fixed[i]) variable_[i] = static_cast<std::int64_t>(free_++);
    double length = 0;
    std::size_t edges = 0;
    auto is_free = [&](std::uint32_t node) { return variable_[node] >= 0; };
    for (std::uint32_t h = 0; h < mesh.hexes.size(); ++h) {
      const Hex& n = mesh.hexes[h];
      for (std::uint8_t k = 0; k < 8; ++k) {
        const int* e = kCornerEdges[k];
        for (int i = 0; i < 3; ++i, ++edges) length += (point(n[e[i]]) - point(n[k])).norm();
        if (is_free(n[k]) || is_free(n[e[0]]) || is_free(n[e[1]]) || is_free(n[e[2]])) frames_.push_back({h, k});
      }
      if (std::any_of(n.begin(), n.end(), is_free)) frames_.push_back({h, kCentre});
    }
    // One reference length for the whole mesh: the volume term asks every
    // frame for the volume of a cube corner of that edge.
    h_ = edges ? length / static_cast<double>(edges) : 1.0;
  }

  std::size_t variables() const { return 3 * free_; }
  double eps = 1;

  Vector start() const {
    Vector x(static_cast<Eigen::Index>(variables()));
    for (std::size_t i = 0; i < variable_.size(); ++i)
      if (variable_[i] >= 0) x.segment<3>(3 * variable_[i]) = point(static_cast<std::uint32_t>(i));
    return x;
  }
  void write(const Vector& x, HexMesh& mesh) const {
    for (std::size_t i = 0; i < variable_.size(); ++i)
      if (variable_[i] >= 0)
        for (int d = 0; d < 3; ++d) mesh.points[i][d] = x[3 * variable_[i] + d];
  }

  double operator()(const Vector& x, Vector& grad) const {
    grad.setZero(x.size());
    double total = 0;
    const double inv_h = 1 / h_, inv_h2 = inv_h * inv_h, inv_h3 = inv_h2 * inv_h;
    for (const Frame& f : frames_) {
      const auto [a, b, d] = columns(x, f);
      const V3 bd = b.cross(d), da = d.cross(a), ab = a.cross(b);
      const double det = a.dot(bd) * inv_h3, trace = (a.squaredNorm() + b.squaredNorm() + d.squaredNorm()) * inv_h2;
      const double root = std::sqrt(eps * eps + det * det), chi = 0.5 * (det + root), dchi = chi / root;
      const double chi23 = std::cbrt(chi * chi);
      total += trace / chi23 + lambda_ * (det * det + 1) / chi;
      const double d_trace = 1 / chi23;
      const double d_det = -2.0 / 3.0 * trace / (chi23 * chi) * dchi +
                           lambda_ * (2 * det / chi - (det * det + 1) * dchi / (chi * chi));
      const V3 ga = 2 * d_trace * inv_h2 * a + d_det * inv_h3 * bd;
      const V3 gb = 2 * d_trace * inv_h2 * b + d_det * inv_h3 * da;
      const V3 gd = 2 * d_trace * inv_h2 * d + d_det * inv_h3 * ab;
      const Hex& n = mesh_.hexes[f.hex];
      if (f.which != kCentre) {
        const int* e = kCornerEdges[f.which];
        add(grad, n[e[0]], ga);
        add(grad, n[e[1]], gb);
        add(grad, n[e[2]], gd);
        add(grad, n[f.which], -(ga + gb + gd));
        continue;
      }
      // Node i's weight in each column is +-1/4 (the signs in columns()).
      const V3 s = 0.25 * (ga + gb + gd), ad = 0.5 * (ga + gd), bd_ = 0.5 * (gb + gd);
      add(grad, n[0], -s);
      add(grad, n[1], s - bd_);
      add(grad, n[2], s - 0.5 * gd);
      add(grad, n[3], s - ad);
      add(grad, n[4], 0.5 * gd - s);
      add(grad, n[5], ad - s);
      add(grad, n[6], s);
      add(grad, n[7], bd_ - s);
    }
    return total;
  }

  /// The least frame determinant (over h^3) of the frames with a free node.
  double min_det(const Vector& x) const {
    double least = detail::kInf;
    for (const Frame& f : frames_) least = std::min(least, det(x, f));
    return least;
  }

  /// Hexes with a frame whose determinant is <= 0 (locked ones included).
  std::size_t inverted_hexes(const Vector& x) const {
    std::size_t inverted = 0;
    for (std::uint32_t h = 0; h < mesh_.hexes.size(); ++h)
      for (std::uint8_t w = 0; w < kFrames; ++w)
        if (!(det(x, {h, w}) > 0)) {
          ++inverted;
          break;
        }
    return inverted;
  }

  double chi(double det) const { return 0.5 * (det + std::sqrt(eps * eps + det * det)); }

private:
  V3 point(std::uint32_t n) const { return detail::to_eigen(mesh_.points[n]); }
  V3 at(const Vector& x, std::uint32_t n) const {
    return variable_[n] >= 0 ? V3(x.segment<3>(3 * variable_[n])) : point(n);
  }
  void add(Vector& grad, std::uint32_t n, const V3& g) const {
    if (variable_[n] >= 0) grad.segment<3>(3 * variable_[n]) += g;
  }
  std::array<V3, 3> columns(const Vector& x, const Frame& f) const {
    const Hex& n = mesh_.hexes[f.hex];
    if (f.which != kCentre) {
      const int* e = kCornerEdges[f.which];
      const V3 p0 = at(x, n[f.which]);
      return {at(x, n[e[0]]) - p0, at(x, n[e[1]]) - p0, at(x, n[e[2]]) - p0};
    }
    V3 p[8];
    for (int i = 0; i < 8; ++i) p[i] = at(x, n[i]);
    return {0.25 * (p[1] - p[0] + p[2] - p[3] + p[5] - p[4] + p[6] - p[7]),
            0.25 * (p[3] - p[0] + p[2] - p[1] + p[7] - p[4] + p[6] - p[5]),
            0.25 * (p[4] - p[0] + p[5] - p[1] + p[6] - p[2] + p[7] - p[3])};
  }
  double det(const Vector& x, const Frame& f) const {
    const auto [a, b, d] = columns(x, f);
    return a.dot(b.cross(d)) / (h_ * h_ * h_);
  }

  const HexMesh& mesh_;
  double lambda_;
  std::vector<std::int64_t> variable_;  ///< per node: index among the free nodes, -1 when fixed
  std::size_t free_ = 0;
  std::vector<Frame> frames_;
  double h_ = 1;
};

}  // namespace

UntangleReport untangle(HexMesh& mesh, const std::vector<bool>& fixed, const UntangleOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (fixed.size() != mesh.points.size()) throw std::invalid_argument("untangle: one fixed flag per node is needed");
  UntangleReport report;
  Energy energy(mesh, fixed, options.lambda);
  Vector x = energy.start();
  report.inverted_before = report.inverted_after = energy.inverted_hexes(x);
  if (report.inverted_before == 0 || energy.variables() == 0) {
    report.untangled = report.inverted_before == 0;
    return report;
  }
  LBFGSpp::LBFGSParam<double> param;
  param.max_iterations = options.max_iterations;
  param.epsilon = 1e-6;
  LBFGSpp::LBFGSSolver<double> solver(param);

  // The eps schedule of Garanzha et al.: start where the worst corner is
  // regularised; then, as each round lowers the energy by a fraction sigma,
  // ask the worst corner for a (1 - sigma) share of its regularised value.
  double least = energy.min_det(x);
  energy.eps = least > 0 ? kLeastEps : std::sqrt(1e-8 + 0.04 * least * least);
  Vector grad;
  double previous = energy(x, grad);
  Vector best = x;
  int improved = 0;  // the last round that lowered the inverted count
  for (; report.rounds < options.max_rounds; ++report.rounds) {
    double value = previous;
    try {
      report.iterations += solver.minimize(energy, x, value);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      // A line search that gave up leaves x at its last trial point: still positions.
      value = energy(x, grad);
    }
    if (!x.allFinite() || !std::isfinite(value)) break;  // eps too small for doubles
    const std::size_t inverted = energy.inverted_hexes(x);
    if (inverted < report.inverted_after) {
      report.inverted_after = inverted;
      best = x;
      improved = report.rounds;
    }
    if (report.rounds - improved > options.patience) break;
    least = energy.min_det(x);
    if (least > 0) break;
    const double sigma = std::max(1 - value / previous, 0.1);
    const double mu = (1 - sigma) * energy.chi(least);
    energy.eps = std::max(least < mu ? 2 * std::sqrt(mu * (mu - least)) : 0.0, kLeastEps);
    previous = energy(x, grad);
  }
  energy.write(best, mesh);
  report.untangled = energy.min_det(best) > 0;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace loom::geometry
