#include "src/weave/measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "src/check/edge_valence.hpp"
#include "src/check/validity.hpp"
#include "src/stc/primal.hpp"

namespace loom::weave {

namespace {

std::int64_t thousandths(double x) { return std::llround(1000.0 * x); }
std::int64_t degrees(double radians) { return std::llround(radians * 180.0 / std::numbers::pi); }

/// The angle between two vectors, in radians; 0 when one has no length.
double angle_between(const Vec3& x, const Vec3& y) {
  const double nx = norm(x), ny = norm(y);
  if (!(nx > 0) || !(ny > 0)) return 0;
  return std::acos(std::clamp(dot(x, y) / (nx * ny), -1.0, 1.0));
}

double hex_sj(const std::array<Vec3, 8>& p) {
  double worst = 1.0;
  for (int k = 0; k < 8; ++k) {
    const auto& n = hex_corner_neighbours(k);
    worst = std::min(worst, corner_scaled_jacobian(p[k], p[n[0]], p[n[1]], p[n[2]]));
  }
  return worst;
}

/// A front face's corners, centroid, outward normal (the side away from the
/// unmeshed region, as its node cycle runs) and mean edge length.
struct FaceShape {
  Vec3 centroid, normal;
  double edge = 0;
};

}  // namespace

std::int64_t inverted_hexes(const stc::Stc& stc) {
  const engine::Graph& g = stc.graph();
  std::int64_t inverted = 0;
  for (engine::Id h = 0; h < g.id_bound(); ++h) {
    if (!g.alive(h) || g.kind(h) != stc.ids().hex) continue;
    std::array<Vec3, 8> corners{};
    bool placed = true;
    for (unsigned k = 0; k < 8 && placed; ++k) {
      const engine::Id n = stc::corner_node(stc, h, k);
      const Vec3* p = n == engine::no_element ? nullptr : stc.position(n);
      if (p) corners[k] = *p;
      placed = p != nullptr;
    }
    inverted += placed && !(hex_sj(corners) > 0);
  }
  return inverted;
}

std::int64_t irregular_edges(const stc::Stc& stc) {
  const engine::Graph& g = stc.graph();
  const auto& ids = stc.ids();
  std::int64_t irregular = 0;
  std::vector<engine::Id> hexes;
  for (engine::Id e = 0; e < g.id_bound(); ++e) {
    if (!g.alive(e) || g.kind(e) != ids.edge) continue;
    hexes.clear();
    bool closed = true, on_boundary = false;
    for (engine::SlotId s : g.incoming(e)) {
      if (g.slot_port(s) != ids.face_edge) continue;
      const engine::Id f = g.slot_owner(s);
      on_boundary |= g.get(f, ids.face_boundary) >= 0;  // its ideal is the surface's, not 4
      for (unsigned side = 0; side < 2; ++side) {
        const engine::Id h = g.at(f, ids.face_cell, side);
        if (h == engine::no_element) closed = false;  // a front face: more hexes may come
        else hexes.push_back(h);
      }
    }
    if (on_boundary) continue;
    std::sort(hexes.begin(), hexes.end());
    irregular += edge_irregularity(static_cast<int>(std::unique(hexes.begin(), hexes.end()) - hexes.begin()), closed);
  }
  return irregular;
}

void add_geometric_measures(engine::Actions& actions, const stc::Stc& stc) {
  const engine::KindId node = stc.ids().node;
  auto params = [node](std::initializer_list<const char*> names) {
    std::vector<engine::ActionParameter> out;
    for (const char* n : names) out.push_back({n, node});
    return out;
  };
  // Every measure reads positions through this, so an unplaced node is one clear error.
  auto at = [&stc](std::span<const engine::Id> args, std::size_t i) -> const Vec3& {
    const Vec3* p = stc.position(args[i]);
    if (!p) throw std::runtime_error(fmt::format("node {} has no position yet", args[i]));
    return *p;
  };

  auto shape = [&stc, at](engine::Id f) {
    std::array<engine::Id, 4> n{};
    for (unsigned i = 0; i < 4; ++i) n[i] = stc.face_node(f, i);
    const std::span<const engine::Id> nodes(n);
    FaceShape s;
    s.centroid = 0.25 * (at(nodes, 0) + at(nodes, 1) + at(nodes, 2) + at(nodes, 3));
    s.normal = cross(at(nodes, 2) - at(nodes, 0), at(nodes, 3) - at(nodes, 1));
    for (std::size_t i = 0; i < 4; ++i) s.edge += 0.25 * norm(at(nodes, (i + 1) % 4) - at(nodes, i));
    return s;
  };
  const engine::KindId face = stc.ids().face;

  actions.add_measure("corner_sj", params({"v", "a", "b", "c"}),
                      [at](const engine::Graph&, std::span<const engine::Id> n) {
                        return thousandths(corner_scaled_jacobian(at(n, 0), at(n, 1), at(n, 2), at(n, 3)));
                      });
  actions.add_measure("hex_sj", params({"v", "a", "b", "c", "ab", "bc", "ca"}),
                      [at](const engine::Graph&, std::span<const engine::Id> n) {
                        const Vec3 &v = at(n, 0), &a = at(n, 1), &b = at(n, 2), &c = at(n, 3);
                        // VTK order: v c ca a on one face, b bc (far) ab on the other.
                        const std::array<Vec3, 8> hex{v, c, at(n, 6), a, b, at(n, 5), a + b + c - 2.0 * v, at(n, 4)};
                        return thousandths(hex_sj(hex));
                      });
  actions.add_measure("angle", params({"a", "v", "b"}),
                      [at](const engine::Graph&, std::span<const engine::Id> n) {
                        const Vec3& v = at(n, 1);
                        return degrees(angle_between(at(n, 0) - v, at(n, 2) - v));
                      });
  actions.add_measure("dihedral", params({"a", "b", "c", "d"}),
                      [at](const engine::Graph&, std::span<const engine::Id> n) {
                        const Vec3 &a = at(n, 0), &b = at(n, 1), &c = at(n, 2), &d = at(n, 3);
                        // Front faces face away from the unmeshed region.
                        const Vec3 out1 = cross(b - a, c - b), out2 = cross(a - b, d - a);
                        const double between = angle_between(out1, out2);
                        const bool convex = dot(d - a, out1) <= 0;
                        return degrees(convex ? std::numbers::pi - between : std::numbers::pi + between);
                      });
  actions.add_measure("gap", params({"u", "a", "b"}),
                      [at](const engine::Graph&, std::span<const engine::Id> n) {
                        const Vec3 &u = at(n, 0), &a = at(n, 1), &b = at(n, 2);
                        const double size = 0.5 * (norm(a - u) + norm(b - u));
                        return size > 0 ? thousandths(norm(a - b) / size) : std::int64_t{0};
                      });
  actions.add_measure("facing", {{"f", face}, {"g", face}},
                      [shape](const engine::Graph&, std::span<const engine::Id> n) {
                        return degrees(angle_between(shape(n[0]).normal, -1.0 * shape(n[1]).normal));
                      });
  actions.add_measure("distance", {{"f", face}, {"g", face}},
                      [shape](const engine::Graph&, std::span<const engine::Id> n) {
                        const FaceShape f = shape(n[0]), g = shape(n[1]);
                        const double size = 0.5 * (f.edge + g.edge);
                        return size > 0 ? thousandths(norm(f.centroid - g.centroid) / size) : std::int64_t{0};
                      });
}

}  // namespace loom::weave
