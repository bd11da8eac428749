#include "src/fill/fill.hpp"

#include <algorithm>
#include <stdexcept>

#include "src/fill/fill_plan.hpp"
#include "src/geometry/boundary_layer.hpp"

namespace loom::fill {

namespace {

constexpr std::uint32_t none = UINT32_MAX;

Vec3 operator*(const Vec3& a, double s) { return loom::operator*(s, a); }
Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

double orientation(const std::array<Vec3, 8>& p) {
  Vec3 a = p[1] - p[0], b = p[3] - p[0], c = p[4] - p[0];
  return dot(a, cross(b, c));
}

/// The mesh being filled. Its nodes are made on first use, so that every
/// entity (an edge's midpoint, a quad's diagonal) has one node whichever cap
/// or tet asks for it.
class Builder {
 public:
  Builder(const QuadSurface& s, const FillPlan& fill_plan) : surface(s), plan(fill_plan) {
    out.mesh.points = s.points;
    out.on_boundary.assign(s.points.size(), true);
    for (const auto& p : s.points) centre_ = centre_ + p;
    centre_ = centre_ * (1.0 / static_cast<double>(s.points.size()));
    const std::size_t n = s.points.size(), e = fill_plan.edge_nodes.size(), q = s.quads.size();
    inner_.assign(n, none), white_mid_.assign(n, none), spoke_mid_.assign(n, none);
    edge_mid_.assign(e, none), wall_centre_.assign(e, none), edge_cone_.assign(e, none);
    diagonal_mid_.assign(q, none), diagonal_cone_.assign(q, none);
    triangle_centroid_.assign(2 * q, none), tet_centroid_.assign(2 * q, none);
  }

  std::uint32_t add(const Vec3& p) {
    out.mesh.points.push_back(p);
    out.on_boundary.push_back(false);
    return static_cast<std::uint32_t>(out.mesh.points.size() - 1);
  }
  const Vec3& at(std::uint32_t node) const { return out.mesh.points[node]; }
  std::uint32_t once(std::uint32_t& slot, const Vec3& p) { return slot == none ? slot = add(p) : slot; }

  std::uint32_t inner(std::uint32_t v) { return once(inner_[v], lerp(centre_, surface.points[v], 0.5)); }
  std::uint32_t white_mid(std::uint32_t v) { return once(white_mid_[v], lerp(centre_, surface.points[v], 0.75)); }
  std::uint32_t centre() { return once(centre_node_, centre_); }
  std::uint32_t spoke_mid(std::uint32_t v) { return once(spoke_mid_[v], lerp(centre_, surface.points[v], 0.25)); }
  std::uint32_t edge_mid(std::uint32_t e) {
    auto [u, v] = plan.edge_nodes[e];
    return once(edge_mid_[e], lerp(at(inner(u)), at(inner(v)), 0.5));
  }
  std::uint32_t wall_centre(std::uint32_t e, const Vec3& p) { return once(wall_centre_[e], p); }

  // The inner triangulation's entities of quad q: its diagonal, and its
  // triangle t (0, 1) with corners (corner before apex, apex, corner after).
  std::uint32_t quad_corner(std::uint32_t q, int k) const { return surface.quads[q][(k % 4 + 4) % 4]; }
  int first_apex(std::uint32_t q) const {
    // A triangle's apex is a corner off the diagonal, which joins the black corners.
    return plan.white[surface.quads[q][0]] ? 0 : 1;
  }
  std::uint32_t diagonal_mid(std::uint32_t q) {
    int a = first_apex(q);
    return once(diagonal_mid_[q], lerp(at(inner(quad_corner(q, a + 1))), at(inner(quad_corner(q, a + 3))), 0.5));
  }
  std::uint32_t triangle_centroid(std::uint32_t q, int t) {
    int a = first_apex(q) + 2 * t;
    Vec3 c = (at(inner(quad_corner(q, a - 1))) + at(inner(quad_corner(q, a))) + at(inner(quad_corner(q, a + 1)))) * (1.0 / 3);
    return once(triangle_centroid_[2 * q + t], c);
  }

  void add_hex(const std::array<std::uint32_t, 8>& h) { out.mesh.hexes.push_back(h); }

  void add_core(std::uint32_t q);
  std::uint32_t edge_of(std::uint32_t q, int k) const { return plan.quad_edges[q][(k % 4 + 4) % 4]; }

  FilledMesh out;
  const QuadSurface& surface;
  const FillPlan& plan;

 private:
  Vec3 centre_{};
  std::uint32_t centre_node_ = none;
  std::vector<std::uint32_t> inner_, white_mid_, spoke_mid_, edge_mid_, wall_centre_, edge_cone_;
  std::vector<std::uint32_t> diagonal_mid_, diagonal_cone_, triangle_centroid_, tet_centroid_;

  std::uint32_t cone_centroid(std::uint32_t& slot, std::uint32_t u, std::uint32_t v) {
    return once(slot, (at(u) + at(v) + at(centre())) * (1.0 / 3));
  }
};

/// The two tets of quad q (a triangle and the centre), each split into four
/// hexes, one at each corner: the corner, the midpoints of its three edges,
/// the centroids of its three faces and the tet's centroid.
void Builder::add_core(std::uint32_t q) {
  for (int t = 0; t < 2; ++t) {
    int a = first_apex(q) + 2 * t;
    // Tet vertices 0 1 2 (the triangle, counter-clockwise from outside) and 3 (the centre).
    std::array<std::uint32_t, 3> surface_node = {quad_corner(q, a - 1), quad_corner(q, a), quad_corner(q, a + 1)};
    std::array<std::uint32_t, 4> vertex = {inner(surface_node[0]), inner(surface_node[1]), inner(surface_node[2]), centre()};
    // Triangle edges: 0-1 and 1-2 are surface edges, 2-0 the diagonal.
    auto triangle_edge_mid = [&](int i, int j) {
      if ((i == 2 && j == 0) || (i == 0 && j == 2)) return diagonal_mid(q);
      return edge_mid(edge_of(q, std::min(i, j) == 0 ? a - 1 : a));
    };
    auto mid = [&](int i, int j) {
      if (i == 3 || j == 3) return spoke_mid(surface_node[i == 3 ? j : i]);
      return triangle_edge_mid(i, j);
    };
    auto face = [&](int i, int j, int k) {  // the face with these three vertices
      if (i != 3 && j != 3 && k != 3) return triangle_centroid(q, t);
      int x = i == 3 ? j : i, y = (i == 3 || j == 3) ? k : j;
      if ((x == 0 && y == 2) || (x == 2 && y == 0)) return cone_centroid(diagonal_cone_[q], vertex[0], vertex[2]);
      std::uint32_t e = edge_of(q, std::min(x, y) == 0 ? a - 1 : a);
      return cone_centroid(edge_cone_[e], vertex[x], vertex[y]);
    };
    std::uint32_t centroid =
        once(tet_centroid_[2 * q + t], (at(vertex[0]) + at(vertex[1]) + at(vertex[2]) + at(vertex[3])) * 0.25);
    // Reference coordinates of the tet, positively oriented like every tet of the cone.
    const std::array<Vec3, 4> ref = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, 0}};
    for (int p = 0; p < 4; ++p) {
      int x = (p + 1) % 4, y = (p + 2) % 4, z = (p + 3) % 4;
      std::array<std::uint32_t, 8> h = {vertex[p], mid(p, x), face(p, x, y), mid(p, y),
                                        mid(p, z), face(p, x, z), centroid, face(p, y, z)};
      std::array<Vec3, 8> r = {ref[p],
                               (ref[p] + ref[x]) * 0.5,
                               (ref[p] + ref[x] + ref[y]) * (1.0 / 3),
                               (ref[p] + ref[y]) * 0.5,
                               (ref[p] + ref[z]) * 0.5,
                               (ref[p] + ref[x] + ref[z]) * (1.0 / 3),
                               (ref[0] + ref[1] + ref[2] + ref[3]) * 0.25,
                               (ref[p] + ref[y] + ref[z]) * (1.0 / 3)};
      if (orientation(r) < 0) h = {h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]};
      add_hex(h);
      ++out.core_hexes;
    }
  }
}

const Cap& cap_for(const std::vector<Cap>& caps, std::uint32_t even) {
  for (const auto& c : caps)
    if (c.even_edge == even) return c;
  throw std::logic_error("load_caps guarantees a cap for every even wall");
}

/// The cap of quad q, its corner a at the quad's first black corner.
void add_cap(Builder& b, std::uint32_t q, const std::vector<Cap>& caps) {
  const auto& quad = b.surface.quads[q];
  int r = b.plan.white[quad[0]] ? 1 : 0;
  auto corner = [&](std::uint32_t k) { return quad[(r + k) % 4]; };
  auto edge = [&](std::uint32_t k) { return b.edge_of(q, r + static_cast<int>(k)); };
  std::uint32_t even = 0;
  while (even < 4 && !b.plan.even_edge[edge(even)]) ++even;
  if (even == 4) throw std::logic_error("plan_fill gives every quad one even edge");
  const Cap& cap = cap_for(caps, even);
  std::vector<std::uint32_t> inside(cap.inside.size(), none);
  auto cap_point = [&](const Vec3& p) {  // cap coordinates: top square at z = 1, inner square inset by 1/4 at z = 0
    double inset = 0.25 * (1 - p[2]), span = 1 - 2 * inset;
    double u = std::clamp((p[0] - inset) / span, 0.0, 1.0), v = std::clamp((p[1] - inset) / span, 0.0, 1.0);
    auto bilinear = [&](auto node) {
      return (node(0) * ((1 - u) * (1 - v)) + node(1) * (u * (1 - v)) + node(2) * (u * v) + node(3) * ((1 - u) * v));
    };
    Vec3 top = bilinear([&](int k) { return b.surface.points[corner(k)]; });
    Vec3 bottom = bilinear([&](int k) { return b.at(b.inner(corner(k))); });
    return lerp(bottom, top, p[2]);
  };
  auto node = [&](const CapRole& role) -> std::uint32_t {
    using K = CapRole::Kind;
    switch (role.kind) {
      case K::top: return corner(role.index);
      case K::bottom: return b.inner(corner(role.index));
      case K::white_mid: return b.white_mid(corner(role.index));
      case K::edge_mid: return b.edge_mid(edge(role.index));
      case K::wall_centre: {
        Vec3 c = (b.surface.points[corner(role.index)] + b.surface.points[corner(role.index + 1)] +
                  b.at(b.inner(corner(role.index))) + b.at(b.inner(corner(role.index + 1)))) * 0.25;
        return b.wall_centre(edge(role.index), c);
      }
      case K::diagonal_mid: return b.diagonal_mid(q);
      case K::triangle_centroid: {
        // The cap's triangles have their apexes at b and d; the builder counts from the quad's first apex.
        int apex = r + 1 + 2 * static_cast<int>(role.index);
        return b.triangle_centroid(q, ((apex - b.first_apex(q)) % 4 + 4) % 4 / 2);
      }
      case K::inside: {
        auto& slot = inside[role.index];
        return slot == none ? slot = b.add(cap_point(cap.inside[role.index])) : slot;
      }
    }
    return none;
  };
  for (const auto& hex : cap.hexes) {
    std::array<std::uint32_t, 8> h;
    for (int i = 0; i < 8; ++i) h[i] = node(hex[i]);
    b.add_hex(h);
  }
}

}  // namespace

FilledMesh fill_constructively(const QuadSurface& surface, const std::vector<Cap>& caps) {
  const FillPlan plan = plan_fill(surface);
  Builder b(surface, plan);
  auto& hexes = b.out.mesh.hexes;
  // Each cap is pillowed, so that the caps of a pair meet cleanly across their
  // even wall; each pair is pillowed, so that pairs meet cleanly across odd walls
  // (two even walls can share three nodes of a white corner's vertical edge).
  for (std::uint32_t q = 0; q < surface.quads.size(); ++q) {
    if (plan.mate[q] < q) continue;
    const std::size_t pair_start = hexes.size();
    for (std::uint32_t quad : {q, plan.mate[q]}) {
      const std::size_t cap_start = hexes.size();
      add_cap(b, quad, caps);
      geometry::pillow_region(b.out.mesh, cap_start, hexes.size(), b.out.on_boundary);
    }
    geometry::pillow_region(b.out.mesh, pair_start, hexes.size(), b.out.on_boundary);
  }
  b.out.cap_hexes = hexes.size();
  for (std::uint32_t q = 0; q < surface.quads.size(); ++q) b.add_core(q);
  return std::move(b.out);
}

}  // namespace loom::fill
