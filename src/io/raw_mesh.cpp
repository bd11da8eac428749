#include "src/io/raw_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/util/error.hpp"

namespace loom {

namespace {

void check_finite_points(const RawMesh& raw, const std::string& where) {
  for (std::size_t i = 0; i < raw.points.size(); ++i) {
    const Vec3& p = raw.points[i];
    if (std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); })) continue;
    bool has_nan = std::any_of(p.begin(), p.end(), [](double x) { return std::isnan(x); });
    fail_input(where,
               fmt::format("node {} has a{} coordinate", i + raw.node_numbering_base, has_nan ? " NaN" : "n infinite"),
               "every coordinate must be a finite number; fix or remove that node");
  }
}

template <std::size_t N>
std::array<std::uint32_t, N> checked_nodes(const RawCell& cell, const RawMesh& raw, const std::string& label,
                                           const std::string& where) {
  std::array<std::uint32_t, N> nodes{};
  for (std::size_t k = 0; k < N; ++k) {
    std::int64_t index = cell.nodes[k];
    if (index < 0 || static_cast<std::uint64_t>(index) >= raw.points.size())
      fail_input(where,
                 fmt::format("{} refers to node {}, but nodes are numbered {} to {}", label,
                             index + raw.node_numbering_base, raw.node_numbering_base,
                             static_cast<std::int64_t>(raw.points.size()) - 1 + raw.node_numbering_base),
                 "fix the node index or add the missing node");
    nodes[k] = static_cast<std::uint32_t>(index);
  }
  return nodes;
}

void check_point_count(const RawMesh& raw, const std::string& where) {
  if (raw.points.size() > std::numeric_limits<std::uint32_t>::max())
    fail_input(where, fmt::format("{} nodes is more than Loom can index", raw.points.size()), "split the mesh");
}

}  // namespace

std::string describe(const CellOrigin& origin) { return fmt::format("{} {}", origin.unit, origin.number); }

QuadSurface to_quad_surface(RawMesh&& raw, const std::string& where) {
  check_point_count(raw, where);
  QuadSurface surface;
  for (const RawCell& cell : raw.cells) {
    switch (cell.kind) {
      case CellKind::vertex:
      case CellKind::line:
        continue;
      case CellKind::triangle:
      case CellKind::quad:
      case CellKind::polygon:
        if (cell.nodes.size() != 4)
          fail_input(where,
                     fmt::format("face {} ({}) has {} nodes, not 4", surface.quads.size(), describe(cell.origin),
                                 cell.nodes.size()),
                     "only quad faces can bound a hex mesh; remesh the surface with quads only");
        surface.quads.push_back(checked_nodes<4>(
            cell, raw, fmt::format("face {} ({})", surface.quads.size(), describe(cell.origin)), where));
        continue;
      case CellKind::hexahedron:
      case CellKind::other_volume:
        fail_input(where,
                   fmt::format("{} is a volume cell ({}), not a surface face", describe(cell.origin), cell.type_name),
                   "give a quad surface mesh; to use a hex mesh, extract its boundary first");
      case CellKind::unsupported:
        fail_input(where, fmt::format("{} has unsupported cell type {}", describe(cell.origin), cell.type_name),
                   "only quads (and ignored vertices and lines) may appear in a surface file");
    }
  }
  check_finite_points(raw, where);
  surface.points = std::move(raw.points);
  return surface;
}

HexMesh to_hex_mesh(RawMesh&& raw, const std::string& where) {
  check_point_count(raw, where);
  HexMesh mesh;
  for (const RawCell& cell : raw.cells) {
    switch (cell.kind) {
      case CellKind::vertex:
      case CellKind::line:
      case CellKind::triangle:
      case CellKind::quad:
      case CellKind::polygon:
        continue;
      case CellKind::hexahedron:
        if (cell.nodes.size() != 8)
          fail_input(where,
                     fmt::format("hexahedron at {} has {} nodes, not 8", describe(cell.origin), cell.nodes.size()),
                     "only linear 8-node hexahedra are supported");
        mesh.hexes.push_back(checked_nodes<8>(
            cell, raw, fmt::format("hexahedron {} ({})", mesh.hexes.size(), describe(cell.origin)), where));
        continue;
      case CellKind::other_volume:
        fail_input(where, fmt::format("{} is a {}, not a hexahedron", describe(cell.origin), cell.type_name),
                   "an all-hex mesh may contain only 8-node hexahedra");
      case CellKind::unsupported:
        fail_input(where, fmt::format("{} has unsupported cell type {}", describe(cell.origin), cell.type_name),
                   "an all-hex mesh may contain only 8-node hexahedra");
    }
  }
  check_finite_points(raw, where);
  mesh.points = std::move(raw.points);
  return mesh;
}

}  // namespace loom
