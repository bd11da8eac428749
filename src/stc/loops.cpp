#include "src/stc/loops.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_set>

#include <fmt/format.h>

namespace loom::stc {

std::size_t Loop::self_crossings() const {
  std::vector<Id> sorted = faces;
  std::sort(sorted.begin(), sorted.end());
  std::size_t n = 0;
  for (std::size_t i = 1; i < sorted.size(); ++i) n += sorted[i] == sorted[i - 1];
  return n;
}

std::vector<Id> boundary_faces_of_edge(const Stc& stc, Id edge) {
  const engine::Graph& g = stc.graph();
  std::vector<Id> out;
  for (engine::SlotId s : g.incoming(edge)) {
    Id f = g.slot_owner(s);
    if (g.kind(f) == stc.ids().face && stc.is_boundary(f) && std::find(out.begin(), out.end(), f) == out.end())
      out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Loop> trace_loops(const Stc& stc) {
  const engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  std::vector<std::vector<Id>> boundary_edges_of_sheet(g.id_bound());
  for (Id e : g.members(ids.edge))
    if (!boundary_faces_of_edge(stc, e).empty()) boundary_edges_of_sheet[stc.edge_sheet(e)].push_back(e);

  std::vector<Loop> loops;
  std::unordered_set<Id> visited;
  for (Id sheet : g.members(ids.sheet)) {
    for (Id start : boundary_edges_of_sheet[sheet]) {
      if (visited.count(start)) continue;
      Loop loop;
      loop.sheet = sheet;
      Id edge = start, from = no_element;
      do {
        visited.insert(edge);
        auto faces = boundary_faces_of_edge(stc, edge);
        if (faces.size() != 2)
          throw std::runtime_error(fmt::format("loop tracing: boundary edge {} has {} boundary faces", edge, faces.size()));
        Id face = faces[0] == from ? faces[1] : faces[0];
        loop.edges.push_back(edge);
        loop.faces.push_back(face);
        from = face;
        edge = stc.face_edge(face, stc.slot_in_face(face, edge) + 2);
      } while (edge != start);
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

}  // namespace loom::stc
