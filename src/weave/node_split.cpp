// Splitting a pinched node: see split_pinched_node in pillow.hpp.
#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "src/weave/pillow.hpp"
#include "src/weave/pillow_detail.hpp"

namespace loom::weave {

using namespace detail;

std::size_t split_pinched_node(Stc& stc, Id node) {
  Graph& g = stc.graph();
  const stc::StcSchema& ids = stc.ids();
  std::vector<Id> faces = owners_via(g, node, ids.face_node);
  // The groups: every hex at the node, joined through the faces at it.
  auto group = components_at(stc, faces, [](Id) { return true; });
  std::vector<std::size_t> group_of_face;
  std::size_t parts = 0;
  for (Id f : faces) {
    Id h = stc.face_cell(f, 0) != no_element ? stc.face_cell(f, 0) : stc.face_cell(f, 1);
    if (h == no_element) throw std::runtime_error(fmt::format("split: face {} at node {} has no hex", f, node));
    group_of_face.push_back(group.at(h));
    parts = std::max(parts, group.at(h) + 1);
  }
  if (parts < 2) {
    bool boundary = std::any_of(faces.begin(), faces.end(), [&](Id f) { return stc.is_boundary(f); });
    g.set(node, ids.node_boundary, boundary ? 1 : 0);
    return 0;
  }

  std::vector<Id> part_node(parts, node);
  for (std::size_t p = 1; p < parts; ++p) part_node[p] = g.add(ids.node);
  // Position and boundary flag of each part, from a boundary face it holds.
  for (std::size_t p = 0; p < parts; ++p) {
    std::int32_t point = g.get(node, ids.node_point), boundary = 0;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (group_of_face[i] != p || !stc.is_boundary(faces[i])) continue;
      for (unsigned k = 0; k < 4; ++k)
        if (stc.face_node(faces[i], k) == node)
          point = stc.boundary_points().at(static_cast<std::size_t>(stc.boundary_index(faces[i])))[k];
      boundary = 1;
      break;
    }
    g.set(part_node[p], ids.node_point, point);
    g.set(part_node[p], ids.node_boundary, boundary);
  }
  // Edges at the node: used by one part, they follow it; by several, each
  // part but the first gets a copy.
  std::map<std::pair<Id, std::size_t>, Id> edge_for;
  std::map<Id, std::size_t> first_part;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (unsigned k = 0; k < 4; ++k) {
      Id e = stc.face_edge(faces[i], k);
      if (stc.edge_node(e, 0) != node && stc.edge_node(e, 1) != node) continue;
      first_part.try_emplace(e, group_of_face[i]);
    }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    Id f = faces[i];
    std::size_t p = group_of_face[i];
    for (unsigned k = 0; k < 4; ++k) {
      Id e = stc.face_edge(f, k);
      if (stc.edge_node(e, 0) != node && stc.edge_node(e, 1) != node) continue;
      auto [it, fresh] = edge_for.try_emplace({e, p}, e);
      if (fresh && first_part.at(e) != p) {
        Id copy = g.add(ids.edge);
        g.link(copy, ids.edge_node, 0, stc.edge_node(e, 0));
        g.link(copy, ids.edge_node, 1, stc.edge_node(e, 1));
        g.link(copy, ids.edge_sheet, 0, stc.edge_sheet(e));
        it->second = copy;
      }
    }
  }
  for (auto& [key, e] : edge_for)
    for (unsigned k = 0; k < 2; ++k)
      if (stc.edge_node(e, k) == node) g.link(e, ids.edge_node, k, part_node[key.second]);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    std::size_t p = group_of_face[i];
    for (unsigned k = 0; k < 4; ++k) {
      Id f = faces[i];
      if (Id e = stc.face_edge(f, k); edge_for.count({e, p})) g.link(f, ids.face_edge, k, edge_for.at({e, p}));
      if (stc.face_node(f, k) == node) g.link(f, ids.face_node, k, part_node[p]);
    }
  }
  return parts - 1;
}

}  // namespace loom::weave
