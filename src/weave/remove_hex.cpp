#include "src/weave/remove_hex.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace loom::weave {

using stc::Id;
using stc::no_element;

namespace {

/// Reverses the face's node cycle and swaps its cells, so that its open side
/// is cell[0] again (edge[i] joins node[i] and node[i+1] in the new order).
void turn_round(stc::Stc& stc, Id face) {
  engine::Graph& g = stc.graph();
  const auto& ids = stc.ids();
  std::array<Id, 4> nodes{}, edges{};
  for (unsigned i = 0; i < 4; ++i) nodes[i] = stc.face_node(face, i), edges[i] = stc.face_edge(face, i);
  for (unsigned i = 0; i < 4; ++i) {
    g.link(face, ids.face_node, i, nodes[(4 - i) % 4]);
    g.link(face, ids.face_edge, i, edges[3 - i]);
  }
  const Id glued = stc.face_cell(face, 0);
  g.link(face, ids.face_cell, 0, no_element);
  g.link(face, ids.face_cell, 1, glued);
}

void remove_unused(engine::Graph& g, std::vector<Id> candidates) {
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (Id e : candidates)
    if (g.alive(e) && g.in_degree(e) == 0) g.remove(e);
}

}  // namespace

void remove_hex(stc::Stc& stc, Id hex) {
  engine::Graph& g = stc.graph();
  const auto& ids = stc.ids();
  std::array<Id, 6> faces{};
  for (unsigned i = 0; i < 6; ++i) {
    faces[i] = stc.hex_face(hex, i);
    if (stc.face_cell(faces[i], 0) == hex && stc.face_cell(faces[i], 1) == hex)
      throw std::runtime_error(fmt::format("remove_hex: hex {} lies on both sides of its face {}", hex, faces[i]));
  }
  std::vector<Id> edges, nodes, chords, sheets;
  for (Id f : faces) {
    if (!g.alive(f)) continue;  // a face the hex holds twice, already gone
    if (stc.face_cell(f, 0) == hex) {
      g.link(f, ids.face_cell, 0, no_element);
    } else if (stc.face_cell(f, 0) != no_element) {
      g.link(f, ids.face_cell, 1, no_element);
      turn_round(stc, f);
    } else {
      for (unsigned i = 0; i < 4; ++i) {
        const Id e = stc.face_edge(f, i);
        edges.push_back(e), nodes.push_back(stc.face_node(f, i)), sheets.push_back(stc.edge_sheet(e));
      }
      chords.push_back(stc.face_chord(f));
      g.remove(f);
    }
  }
  g.remove(hex);
  // Edges first: they hold nodes and sheets; chords hold sheets.
  for (Id e : edges)
    if (g.alive(e) && g.in_degree(e) == 0)
      for (unsigned i = 0; i < 2; ++i) nodes.push_back(stc.edge_node(e, i));
  remove_unused(g, edges);
  remove_unused(g, nodes);
  for (Id c : chords)
    if (g.alive(c) && g.in_degree(c) == 0)
      for (unsigned i = 0; i < 2; ++i) sheets.push_back(stc.chord_sheet(c, i));
  remove_unused(g, chords);
  remove_unused(g, sheets);
}

}  // namespace loom::weave
