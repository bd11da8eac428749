#include "src/geometry/placement_detail.hpp"

#include <algorithm>
#include <cmath>

#include "src/check/validity.hpp"

namespace loom::geometry::detail {

int Placer::untangle() {
  std::vector<char> dirty(mesh_.points.size(), 1), next(mesh_.points.size(), 0);
  const double corners = 8.0 * static_cast<double>(mesh_.hexes.size());
  Summary last = summarise();
  int sweeps = 0;
  while (sweeps < opt_.max_untangle_sweeps) {
    ++sweeps;
    update_scales();
    bool moved = false;
    decrease_ = 0;
    regularised_moves_ = 0;
    for (std::uint32_t p = 0; p < mesh_.points.size(); ++p) {
      if (fixed_[p] || !dirty[p] || entry_start_[p] == entry_start_[p + 1]) continue;
      if (untangle_node(p)) {
        moved = true;
        mark_neighbours(p, next);
      }
    }
    if (!moved) break;
    // Go on while the sweep cut the hexes <= 0 or < 0.2, or a tangled
    // node moved, or the energy still fell enough.
    const Summary now = summarise();
    const bool fewer = now.below_zero < last.below_zero || now.below_0_2 < last.below_0_2;
    last = now;
    if (!fewer && regularised_moves_ == 0 && decrease_ < opt_.energy_tolerance * corners) break;
    dirty.swap(next);
    std::fill(next.begin(), next.end(), 0);
  }
  return sweeps;
}

double Placer::energy(const V3& v, double delta2) const {
  double total = 0;
  const double vv = v.squaredNorm();
  for (const Local& l : local_) {
    const double s2 = l.inv_s * l.inv_s, s3 = s2 * l.inv_s;
    const double x = (l.f0 + l.gf.dot(v) + l.cc * vv) * s2 / 3.0;
    double r;
    const double h = regularised((l.sigma0 + l.b.dot(v)) * s3, delta2, r);
    if (!(h > 0)) return kInf;
    total += x * std::sqrt(x) / h;
  }
  return std::isfinite(total) ? total : kInf;
}

double Placer::energy_derivatives(const V3& v, double delta2, V3& grad, M3& hess) const {
  grad.setZero();
  hess.setZero();
  double total = 0;
  for (const Local& l : local_) {
    const double s2 = l.inv_s * l.inv_s, s3 = s2 * l.inv_s;
    const double f = (l.f0 + l.gf.dot(v) + l.cc * v.squaredNorm()) * s2;
    const V3 df = (l.gf + 2.0 * l.cc * v) * s2;
    const V3 ds = l.b * s3;
    double r;
    const double h = regularised((l.sigma0 + l.b.dot(v)) * s3, delta2, r);
    const double h1 = h / r, h2 = 2.0 * delta2 / (r * r * r);  // dh/dsigma, d2h/dsigma2
    // E = phi(F) psi(sigma): phi = (F/3)^1.5, psi = 1/h.
    const double x = f / 3.0, rx = std::sqrt(x);
    const double phi = x * rx, phi1 = 0.5 * rx, phi2 = rx > 0 ? 0.25 / (3.0 * rx) : 0.0;
    const double psi = 1.0 / h, psi1 = -h1 / (h * h), psi2 = 2.0 * h1 * h1 / (h * h * h) - h2 / (h * h);
    if (!(h > 0)) return kInf;
    total += phi * psi;
    grad += phi1 * psi * df + phi * psi1 * ds;
    hess += phi2 * psi * df * df.transpose() + (2.0 * l.cc * s2 * phi1 * psi) * M3::Identity() +
            phi1 * psi1 * (df * ds.transpose() + ds * df.transpose()) + phi * psi2 * ds * ds.transpose();
  }
  return std::isfinite(total) ? total : kInf;
}

bool Placer::untangle_node(std::uint32_t p) {
  const double size = gather(p);
  double sigma_min = kInf;
  for (const Local& l : local_) sigma_min = std::min(sigma_min, l.sigma0 * l.inv_s * l.inv_s * l.inv_s);
  const double eps = opt_.epsilon;
  const double delta2 = sigma_min < eps ? eps * (eps - sigma_min) : 0.0;
  V3 v = V3::Zero();
  V3 grad;
  M3 hess;
  double phi = energy_derivatives(v, delta2, grad, hess);
  if (!std::isfinite(phi)) return false;
  const double phi_start = phi;
  const int steps = delta2 > 0 ? kNewtonStepsTangled : kNewtonSteps;
  for (int it = 0; it < steps; ++it) {
    if (it > 0) energy_derivatives(v, delta2, grad, hess);
    if (!grad.allFinite() || !hess.allFinite()) break;
    Eigen::SelfAdjointEigenSolver<M3> eig;
    eig.computeDirect(hess);
    V3 lambda = eig.eigenvalues().cwiseAbs();
    lambda = lambda.cwiseMax(std::max(lambda.maxCoeff() * 1e-6, 1e-12 / (size * size)));
    const M3& q = eig.eigenvectors();
    V3 d = -(q * (q.transpose() * grad).cwiseQuotient(lambda));
    if (!d.allFinite()) break;
    if (d.norm() > kMaxStep * size) d *= kMaxStep * size / d.norm();
    const double slope = grad.dot(d);
    if (!(slope < 0)) break;
    double t = 1.0, trial = kInf;
    for (int ls = 0; ls < 30; ++ls, t *= 0.5) {
      trial = energy(v + t * d, delta2);
      if (trial <= phi + 1e-4 * t * slope) break;
    }
    if (!(trial <= phi + 1e-4 * t * slope)) break;
    v += t * d;
    phi = trial;
    if (t * d.norm() <= opt_.move_tolerance * size) break;
  }
  if (!apply(p, v, size)) return false;
  if (delta2 == 0)
    decrease_ += phi_start - phi;
  else
    ++regularised_moves_;
  return true;
}

}  // namespace loom::geometry::detail
