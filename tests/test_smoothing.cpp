// Node placement (src/geometry/placement.hpp through weave::smooth_interior):
// woven meshes of curved parts come out with every hex that placement can make
// valid valid, perturbed grids are untangled, boundary nodes never move,
// good meshes are left bit-identical, and the result is deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "engine/rule_compiler.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/weave/smoothing.hpp"

using namespace loom;

namespace {

std::vector<engine::Rule> shipped_rules() {
  return engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
}

/// The mesh the weave builds before placement, and its boundary-node flags
/// (what pipeline::mesh_surface hands to smooth_interior).
struct Woven {
  HexMesh mesh;
  std::vector<bool> on_boundary;
};

Woven weave_raw(const QuadSurface& surface) {
  stc::Stc stc = stc::build_from_surface(surface);
  auto result = weave::weave(stc, shipped_rules(), {});
  REQUIRE_MESSAGE(result.closed, result.left);
  Woven w;
  w.mesh = stc::to_hex_mesh(stc, &w.on_boundary);
  return w;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

std::size_t moved_nodes(const HexMesh& a, const HexMesh& b, const std::vector<bool>& which) {
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (which[i] && !same_bits(a.points[i], b.points[i])) ++moved;
  return moved;
}

/// Nodes on faces that belong to one hex only.
std::vector<bool> boundary_nodes(const HexMesh& mesh) {
  static constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<std::uint32_t, 4>, int> count;
  for (const Hex& h : mesh.hexes)
    for (const auto& f : faces) {
      std::array<std::uint32_t, 4> key{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  std::vector<bool> on(mesh.points.size(), false);
  for (const auto& [key, n] : count)
    if (n == 1)
      for (auto v : key) on[v] = true;
  return on;
}

QualitySummary quality(const HexMesh& mesh) {
  QualitySummary q;
  q.min_scaled_jacobian = 1;
  double sum = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const double s = scaled_jacobian(mesh, h);
    q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, s);
    sum += s;
    if (s <= 0) ++q.below_zero;
    if (s < 0.2) ++q.below_0_2;
  }
  q.mean_scaled_jacobian = sum / static_cast<double>(mesh.hexes.size());
  return q;
}

/// True when some corner of hex h has its node and three edge neighbours all
/// fixed and a scaled Jacobian <= 0: no placement can make h valid.
bool locked_invalid(const HexMesh& mesh, std::size_t h, const std::vector<bool>& fixed) {
  static constexpr int corner_edges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                             {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  const Hex& hex = mesh.hexes[h];
  for (int k = 0; k < 8; ++k) {
    const int* e = corner_edges[k];
    if (!(fixed[hex[k]] && fixed[hex[e[0]]] && fixed[hex[e[1]]] && fixed[hex[e[2]]])) continue;
    const Vec3& p = mesh.points[hex[k]];
    const Vec3 a = mesh.points[hex[e[0]]] - p, b = mesh.points[hex[e[1]]] - p, c = mesh.points[hex[e[2]]] - p;
    if (dot(a, cross(b, c)) / (norm(a) * norm(b) * norm(c)) <= 0) return true;
  }
  return false;
}

/// hexgrid(a, b, c) with its interior nodes moved by up to `amplitude` in each
/// coordinate (seeded, so the same every run), optionally bent first into an
/// annular sector of `degrees` about the z axis (a curved, concave part).
struct Perturbed {
  HexMesh mesh;
  std::vector<bool> fixed;
};

Perturbed perturbed_grid(int a, int b, int c, double amplitude, unsigned seed, double degrees = 0) {
  Perturbed g{gen::hexgrid(a, b, c), {}};
  g.fixed = boundary_nodes(g.mesh);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
  for (std::size_t i = 0; i < g.mesh.points.size(); ++i) {
    Vec3& p = g.mesh.points[i];
    if (degrees > 0) {
      const double r = 1.0 + p[0], t = degrees * std::numbers::pi / 180.0 * p[1] / b;
      p = {r * std::cos(t), r * std::sin(t), p[2]};
    }
    if (!g.fixed[i] && amplitude > 0)
      for (double& x : p) x += jitter(rng);
  }
  return g;
}

}  // namespace

TEST_CASE("woven curved parts: every hex that placement can make valid is valid") {
  struct Shape {
    std::string name;
    QuadSurface surface;
  };
  const Shape shapes[] = {{"cylinder 4 6", gen::cylinder(4, 6)},
                          {"cubesphere 3", gen::cubesphere(3)},
                          {"cubesphere 6", gen::cubesphere(6)},
                          {"tet4", gen::tet4()}};
  for (const Shape& shape : shapes) {
    CAPTURE(shape.name);
    Woven w = weave_raw(shape.surface);
    const HexMesh raw = w.mesh;
    const QualitySummary before = quality(raw);
    const weave::SmoothingReport report = weave::smooth_interior(w.mesh, w.on_boundary);
    const QualitySummary after = quality(w.mesh);

    CHECK(moved_nodes(raw, w.mesh, w.on_boundary) == 0);  // boundary nodes bit-identical
    CHECK(report.below_zero_after == after.below_zero);
    CHECK(report.below_0_2_after == after.below_0_2);
    // Every hex <= 0 has a corner made of boundary nodes only that is flat or
    // inverted: nothing interior placement can change.
    CHECK(after.below_zero == report.locked_invalid);
    for (std::size_t h = 0; h < w.mesh.hexes.size(); ++h)
      if (scaled_jacobian(w.mesh, h) <= 0) CHECK_MESSAGE(locked_invalid(w.mesh, h, w.on_boundary), "hex " << h);
    CHECK(after.below_0_2 >= report.locked_below_0_2);
    CHECK(after.mean_scaled_jacobian > before.mean_scaled_jacobian);
    MESSAGE(shape.name << ": " << w.mesh.hexes.size() << " hexes; before placement min " << before.min_scaled_jacobian
                       << " mean " << before.mean_scaled_jacobian << ", " << before.below_zero << " <= 0, "
                       << before.below_0_2 << " < 0.2; after min " << after.min_scaled_jacobian << " mean "
                       << after.mean_scaled_jacobian << ", " << after.below_zero << " <= 0 (" << report.locked_invalid
                       << " locked), " << after.below_0_2 << " < 0.2 (" << report.locked_below_0_2 << " locked); "
                       << report.seconds << " s");
  }
}

TEST_CASE("the cubespheres come out valid through the pipeline") {
  for (int n : {3, 6}) {
    CAPTURE(n);
    auto r = pipeline::mesh_surface(gen::cubesphere(n), shipped_rules(), {});
    REQUIRE_MESSAGE(r.mesh.has_value(), r.failure);
    REQUIRE(r.check.has_value());
    CHECK(r.check->valid());
    CHECK(r.check->quality.below_zero == 0);
    CHECK(r.check->quality.min_scaled_jacobian > 0);
    CHECK(r.smoothing.min_after == doctest::Approx(r.check->quality.min_scaled_jacobian));
  }
}

TEST_CASE("perturbed grids are untangled, from the harmonic start and from the input") {
  struct Case {
    int a, b, c;
    double amplitude;
    unsigned seed;
    double degrees;
  };
  // The last two are tangled through and through (most hexes inverted).
  const Case cases[] = {{6, 6, 6, 0.45, 1, 0},   {5, 7, 4, 0.6, 2, 0}, {4, 16, 3, 0.5, 3, 270},
                        {3, 24, 2, 0.3, 4, 350}, {6, 6, 6, 1.5, 5, 0}, {4, 16, 3, 1.5, 6, 270}};
  for (const Case& k : cases) {
    for (auto start : {weave::SmoothingOptions::Start::harmonic_when_tangled, weave::SmoothingOptions::Start::input}) {
      CAPTURE(k.a);
      CAPTURE(k.b);
      CAPTURE(k.degrees);
      CAPTURE(static_cast<int>(start));
      Perturbed g = perturbed_grid(k.a, k.b, k.c, k.amplitude, k.seed, k.degrees);
      const HexMesh input = g.mesh;
      const QualitySummary before = quality(input);
      REQUIRE(before.below_zero > 0);  // the perturbation tangles it
      weave::SmoothingOptions options;
      options.start = start;
      const auto report = weave::smooth_interior(g.mesh, g.fixed, options);
      const QualitySummary after = quality(g.mesh);
      CHECK(report.changed);
      CHECK(report.locked_invalid == 0);
      CHECK(after.below_zero == 0);
      CHECK(after.below_0_2 == 0);
      CHECK(after.min_scaled_jacobian > 0.5);
      CHECK(moved_nodes(input, g.mesh, g.fixed) == 0);
    }
  }
}

TEST_CASE("a structured grid with its interior untouched stays bit-identical") {
  Perturbed g = perturbed_grid(4, 5, 6, 0.0, 1);
  const HexMesh input = g.mesh;
  std::vector<bool> all(input.points.size(), true);

  auto report = weave::smooth_interior(g.mesh, g.fixed);
  CHECK(report.skipped);
  CHECK_FALSE(report.changed);
  CHECK(moved_nodes(input, g.mesh, all) == 0);

  // Even when made to work (every hex counted as poor), nothing moves.
  weave::SmoothingOptions eager;
  eager.improve_below = 2.0;
  for (auto start : {weave::SmoothingOptions::Start::harmonic_when_tangled, weave::SmoothingOptions::Start::harmonic}) {
    eager.start = start;
    report = weave::smooth_interior(g.mesh, g.fixed, eager);
    CHECK_FALSE(report.skipped);
    CHECK_FALSE(report.changed);
    CHECK(moved_nodes(input, g.mesh, all) == 0);
  }

  // The woven L-shape is its structured grid and is left alone too.
  auto r = pipeline::mesh_surface(gen::lshape(3), shipped_rules(), {});
  REQUIRE(r.mesh.has_value());
  CHECK(r.smoothing.skipped);
  CHECK(r.check->quality.min_scaled_jacobian > 0.999);
}

TEST_CASE("placement is deterministic") {
  Woven w = weave_raw(gen::cylinder(4, 6));
  HexMesh first = w.mesh, second = w.mesh;
  weave::smooth_interior(first, w.on_boundary);
  weave::smooth_interior(second, w.on_boundary);
  std::vector<bool> all(first.points.size(), true);
  CHECK(moved_nodes(first, second, all) == 0);

  Perturbed g = perturbed_grid(6, 6, 6, 0.45, 9);
  HexMesh a = g.mesh, b = g.mesh;
  weave::SmoothingOptions options;
  options.start = weave::SmoothingOptions::Start::input;
  weave::smooth_interior(a, g.fixed, options);
  weave::smooth_interior(b, g.fixed, options);
  CHECK(moved_nodes(a, b, std::vector<bool>(a.points.size(), true)) == 0);
}

TEST_CASE("a larger woven part is placed quickly") {
  Woven w = weave_raw(gen::cubesphere(12));
  const HexMesh raw = w.mesh;
  const auto report = weave::smooth_interior(w.mesh, w.on_boundary);
  CHECK(report.below_zero_after == report.locked_invalid);
  CHECK(moved_nodes(raw, w.mesh, w.on_boundary) == 0);
  MESSAGE("cubesphere 12: " << w.mesh.hexes.size() << " hexes placed in " << report.seconds << " s ("
                            << report.harmonic_iterations << " CG iterations, " << report.untangle_sweeps << "+"
                            << report.quality_sweeps << " sweeps); min " << report.min_after << ", mean "
                            << report.mean_after << ", " << report.below_0_2_after << " < 0.2");
}

TEST_CASE("bad arguments are refused") {
  HexMesh mesh = gen::hexgrid(1, 1, 1);
  std::vector<bool> fixed(3, true);
  CHECK_THROWS_AS(weave::smooth_interior(mesh, fixed), std::invalid_argument);
  HexMesh empty;
  CHECK(weave::smooth_interior(empty, {}).skipped);
}
