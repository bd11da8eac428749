// Criterion 6: the mesh's boundary faces are exactly the given surface's quads.
// Surface nodes are matched to mesh boundary nodes by exact coordinates; quads
// are compared as cycles of nodes (any starting corner, either direction, since
// orientation is criterion 7's business).
#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "src/check/criteria.hpp"

namespace loom::criteria {

namespace {

using NodeCycle = std::array<std::uint32_t, 4>;

/// The smallest of the 8 rotations and reflections of a quad's node cycle.
NodeCycle canonical_cycle(const NodeCycle& q) {
  NodeCycle best = q;
  for (int start = 0; start < 4; ++start)
    for (int dir : {1, 3}) {
      NodeCycle c;
      for (int i = 0; i < 4; ++i) c[i] = q[(start + dir * i) % 4];
      best = std::min(best, c);
    }
  return best;
}

bool finite(const Vec3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

std::string at(const Vec3& p) { return fmt::format("({}, {}, {})", p[0], p[1], p[2]); }

NodeCycle side_nodes(const HexMesh& mesh, std::uint32_t side) {
  return face_nodes(mesh.hexes[side / 6], static_cast<int>(side % 6));
}

/// Why a position holds no boundary node of the mesh (only on the failure path).
std::string what_is_at(const HexMesh& mesh, const Vec3& p) {
  std::vector<char> used(mesh.points.size(), 0);
  for (const Hex& hex : mesh.hexes)
    for (std::uint32_t v : hex) used[v] = 1;
  bool unused_node_there = false;
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    if (mesh.points[v] != p) continue;
    if (used[v]) return fmt::format("mesh node {}, an interior node, not a boundary node", v);
    unused_node_there = true;
  }
  return unused_node_there ? "not a node of any hex" : "not a node of the mesh";
}

struct Located {
  Vec3 position;
  std::uint32_t node;
  bool operator<(const Located& o) const { return std::tie(position, node) < std::tie(o.position, o.node); }
};

/// The mesh's boundary nodes sorted by position; a problem if two coincide or
/// one is not finite.
std::optional<std::string> locate_boundary_nodes(const HexMesh& mesh, const std::vector<std::uint32_t>& sides,
                                                 std::vector<Located>& located) {
  std::vector<char> on_boundary(mesh.points.size(), 0);
  for (std::uint32_t side : sides)
    for (std::uint32_t v : side_nodes(mesh, side)) on_boundary[v] = 1;
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    if (!on_boundary[v]) continue;
    if (!finite(mesh.points[v])) return fmt::format("boundary node {} of the mesh is at {}", v, at(mesh.points[v]));
    located.push_back({mesh.points[v], v});
  }
  std::sort(located.begin(), located.end());
  for (std::size_t i = 0; i + 1 < located.size(); ++i)
    if (located[i].position == located[i + 1].position)
      return fmt::format("boundary nodes {} and {} of the mesh are both at {}", located[i].node, located[i + 1].node,
                         at(located[i].position));
  return std::nullopt;
}

/// Maps each surface node used by a quad to the mesh boundary node at its
/// position, one to one; a problem if that fails.
std::optional<std::string> match_surface_nodes(const HexMesh& mesh, const QuadSurface& surface,
                                               const std::vector<Located>& located,
                                               std::vector<std::uint32_t>& mesh_node) {
  mesh_node.assign(surface.points.size(), kNoSide);
  std::vector<std::uint32_t> surface_node_at(mesh.points.size(), kNoSide);
  for (const Quad& q : surface.quads)
    for (std::uint32_t s : q) {
      if (s >= surface.points.size())
        return fmt::format("a surface quad refers to node {}, but the surface has {} nodes", s, surface.points.size());
      if (mesh_node[s] != kNoSide) continue;
      const Vec3& p = surface.points[s];
      if (!finite(p)) return fmt::format("surface node {} is at {}", s, at(p));
      auto it = std::lower_bound(located.begin(), located.end(), Located{p, 0});
      if (it == located.end() || it->position != p)
        return fmt::format("surface node {} at {} is {}", s, at(p), what_is_at(mesh, p));
      if (surface_node_at[it->node] != kNoSide)
        return fmt::format("surface nodes {} and {} are both at {}", surface_node_at[it->node], s, at(p));
      mesh_node[s] = it->node;
      surface_node_at[it->node] = s;
    }
  return std::nullopt;
}

}  // namespace

CriterionResult boundary_matches(const HexMesh& mesh, const HexTopology& topo, const QuadSurface& surface) {
  std::vector<std::uint32_t> sides;  // 6 * hex + local face of each boundary face, in hex order
  for (std::uint32_t f = 0; f < topo.face_count; ++f)
    if (topo.is_boundary_face(f)) sides.push_back(topo.face_sides[f][0]);
  std::sort(sides.begin(), sides.end());

  std::vector<Located> located;
  if (auto problem = locate_boundary_nodes(mesh, sides, located)) return failed(6, *problem);
  std::vector<std::uint32_t> mesh_node;
  if (auto problem = match_surface_nodes(mesh, surface, located, mesh_node)) return failed(6, *problem);

  // Compare the two sets of quads as sorted lists of (canonical cycle, origin).
  using Keyed = std::pair<NodeCycle, std::uint32_t>;
  std::vector<Keyed> from_surface, from_mesh;
  for (std::uint32_t i = 0; i < surface.quads.size(); ++i) {
    const Quad& q = surface.quads[i];
    from_surface.push_back({canonical_cycle({mesh_node[q[0]], mesh_node[q[1]], mesh_node[q[2]], mesh_node[q[3]]}), i});
  }
  for (std::uint32_t side : sides) from_mesh.push_back({canonical_cycle(side_nodes(mesh, side)), side});
  std::sort(from_surface.begin(), from_surface.end());
  std::sort(from_mesh.begin(), from_mesh.end());

  std::uint32_t first_surface_only = kNoSide, first_mesh_only = kNoSide;
  std::size_t surface_only = 0, mesh_only = 0, i = 0, j = 0;
  while (i < from_surface.size() || j < from_mesh.size()) {
    if (j == from_mesh.size() || (i < from_surface.size() && from_surface[i].first < from_mesh[j].first)) {
      ++surface_only;
      first_surface_only = std::min(first_surface_only, from_surface[i++].second);
    } else if (i == from_surface.size() || from_mesh[j].first < from_surface[i].first) {
      ++mesh_only;
      first_mesh_only = std::min(first_mesh_only, from_mesh[j++].second);
    } else {
      ++i;
      ++j;
    }
  }
  if (surface_only == 0 && mesh_only == 0) return passed(6);

  std::vector<std::string> parts;
  if (surface_only > 0)
    parts.push_back(fmt::format("surface quad {} ({}) is not a boundary face of the mesh{}", first_surface_only,
                                fmt::join(surface.quads[first_surface_only], "-"),
                                surface_only > 1 ? fmt::format(" ({} such quads)", surface_only) : ""));
  if (mesh_only > 0)
    parts.push_back(fmt::format("the mesh's boundary face {} of hex {} is not a surface quad{}",
                                fmt::join(side_nodes(mesh, first_mesh_only), "-"), first_mesh_only / 6,
                                mesh_only > 1 ? fmt::format(" ({} such faces)", mesh_only) : ""));
  return failed(6, fmt::format("{}", fmt::join(parts, "; ")));
}

}  // namespace loom::criteria
