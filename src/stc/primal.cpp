#include "src/stc/primal.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace loom::stc {

Id corner_node(const Stc& stc, Id hex, unsigned k) {
  const auto& [a, b, c] = corner_faces[k];
  Id fa = stc.hex_face(hex, a), fb = stc.hex_face(hex, b), fc = stc.hex_face(hex, c);
  auto has = [&](Id f, Id n) {
    for (unsigned i = 0; i < 4; ++i)
      if (stc.face_node(f, i) == n) return true;
    return false;
  };
  Id found = no_element;
  for (unsigned i = 0; i < 4; ++i) {
    Id n = stc.face_node(fa, i);
    if (n == found || !has(fb, n) || !has(fc, n)) continue;
    if (found != no_element) return no_element;
    found = n;
  }
  return found;
}

HexMesh to_hex_mesh(const Stc& stc, std::vector<bool>* on_boundary) {
  const engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  for (Id f : g.members(ids.face))
    if (stc.is_whisker(f)) throw std::runtime_error(fmt::format("primal construction: face {} is still a whisker", f));

  HexMesh mesh;
  if (on_boundary) on_boundary->clear();
  std::vector<std::uint32_t> index(g.id_bound(), UINT32_MAX);
  for (Id n : g.members(ids.node)) {
    std::int32_t p = g.get(n, ids.node_point);
    if (p < 0 || static_cast<std::size_t>(p) >= stc.points().size())
      throw std::runtime_error(fmt::format("primal construction: node {} has no position", n));
    index[n] = static_cast<std::uint32_t>(mesh.points.size());
    mesh.points.push_back(stc.points()[static_cast<std::size_t>(p)]);
    if (on_boundary) on_boundary->push_back(g.get(n, ids.node_boundary) != 0);
  }
  for (Id h : g.members(ids.hex)) {
    Hex hex{};
    for (unsigned k = 0; k < 8; ++k) {
      Id n = corner_node(stc, h, k);
      if (n == no_element)
        throw std::runtime_error(fmt::format("primal construction: hex {} is degenerate at corner {}", h, k));
      hex[k] = index[n];
    }
    mesh.hexes.push_back(hex);
  }
  return mesh;
}

HexMesh woven_hexes(const Stc& stc) {
  const engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  HexMesh mesh;
  std::vector<std::uint32_t> index(g.id_bound(), UINT32_MAX);
  for (Id h : g.members(ids.hex)) {
    Hex hex{};
    bool whole = true;
    for (unsigned k = 0; k < 8 && whole; ++k) {
      Id n = corner_node(stc, h, k);
      if (n == no_element) {
        whole = false;
        break;
      }
      if (index[n] == UINT32_MAX) {
        index[n] = static_cast<std::uint32_t>(mesh.points.size());
        std::int32_t p = g.get(n, ids.node_point);
        mesh.points.push_back(p >= 0 ? stc.points().at(static_cast<std::size_t>(p)) : Vec3{0, 0, 0});
      }
      hex[k] = index[n];
    }
    if (whole) mesh.hexes.push_back(hex);
  }
  return mesh;
}

HexMesh woven_over_surface(const Stc& stc, std::size_t surface_points, std::vector<Id>* hexes) {
  const engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  HexMesh mesh;
  mesh.points.assign(stc.points().begin(), stc.points().begin() + static_cast<std::ptrdiff_t>(surface_points));
  std::vector<std::uint32_t> index(g.id_bound(), UINT32_MAX);
  auto vertex_of = [&](Id n) -> std::uint32_t {
    const std::int32_t boundary = g.get(n, ids.node_boundary);
    const std::int32_t p = g.get(n, ids.node_point);
    if (boundary > 1) return UINT32_MAX;
    if (boundary == 1) return p >= 0 && static_cast<std::size_t>(p) < surface_points ? static_cast<std::uint32_t>(p) : UINT32_MAX;
    if (index[n] == UINT32_MAX) {
      index[n] = static_cast<std::uint32_t>(mesh.points.size());
      mesh.points.push_back(p >= 0 ? stc.points().at(static_cast<std::size_t>(p)) : Vec3{0, 0, 0});
    }
    return index[n];
  };
  if (hexes) hexes->clear();
  for (Id h : g.members(ids.hex)) {
    Hex hex{};
    bool whole = true;
    for (unsigned k = 0; k < 8 && whole; ++k) {
      const Id n = corner_node(stc, h, k);
      whole = n != no_element && (hex[k] = vertex_of(n)) != UINT32_MAX;
    }
    if (!whole) continue;
    mesh.hexes.push_back(hex);
    if (hexes) hexes->push_back(h);
  }
  return mesh;
}

}  // namespace loom::stc
