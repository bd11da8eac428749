// The STC invariants, written once. They hold in every state of a weave
// (degenerate hexes such as knives included) and in every complete STC.
#include <algorithm>

#include <fmt/format.h>

#include "src/stc/stc.hpp"

namespace loom::stc {

namespace {
bool same_pair(Id a, Id b, Id c, Id d) { return (a == c && b == d) || (a == d && b == c); }
}  // namespace

std::string Stc::check_invariants() const {
  if (auto s = graph_.check_structure(); !s.empty()) return s;
  const engine::Graph& g = graph_;

  for (Id e : g.members(ids_->edge)) {
    // 1. An edge has two nodes and lies on one sheet.
    if (edge_node(e, 0) == no_element || edge_node(e, 1) == no_element) return fmt::format("edge {} lacks a node", e);
    if (edge_sheet(e) == no_element) return fmt::format("edge {} lies on no sheet", e);
  }
  for (Id c : g.members(ids_->chord))
    // 2. A chord lies on two sheets (possibly the same one twice).
    if (chord_sheet(c, 0) == no_element || chord_sheet(c, 1) == no_element)
      return fmt::format("chord {} lacks a sheet", c);

  for (Id f : g.members(ids_->face)) {
    // 3. A face is a closed cycle: edge[i] joins node[i] and node[i+1].
    for (unsigned i = 0; i < 4; ++i) {
      Id e = face_edge(f, i);
      if (e == no_element || face_node(f, i) == no_element) return fmt::format("face {} has an empty slot {}", f, i);
      if (!same_pair(edge_node(e, 0), edge_node(e, 1), face_node(f, i), face_node(f, i + 1)))
        return fmt::format("face {}: edge[{}] = {} does not join node[{}] and node[{}]", f, i, e, i, i + 1);
    }
    // 4. Opposite edges of a face lie on one sheet; the face's chord lies on
    //    the sheets of its two pairs of opposite edges.
    Id s0 = edge_sheet(face_edge(f, 0)), s1 = edge_sheet(face_edge(f, 1));
    if (edge_sheet(face_edge(f, 2)) != s0 || edge_sheet(face_edge(f, 3)) != s1)
      return fmt::format("face {}: opposite edges lie on different sheets", f);
    Id c = face_chord(f);
    if (c == no_element) return fmt::format("face {} lies on no chord", f);
    if (!same_pair(chord_sheet(c, 0), chord_sheet(c, 1), s0, s1))
      return fmt::format("face {}: chord {} does not lie on the face's sheets {} and {}", f, c, s0, s1);
    // 5. Cells and faces point at each other as often on both sides.
    if (is_boundary(f) && face_cell(f, 1) != no_element)
      return fmt::format("boundary face {} has a hex on its outer side", f);
    for (unsigned side = 0; side < 2; ++side) {
      Id h = face_cell(f, side);
      if (h == no_element) continue;
      auto in_cell = std::count_if(g.incoming(f).begin(), g.incoming(f).end(),
                                   [&](engine::SlotId s) { return g.slot_owner(s) == h; });
      auto in_face = (face_cell(f, 0) == h) + (face_cell(f, 1) == h);
      if (in_cell != in_face)
        return fmt::format("face {} names hex {} {} time(s) but the hex names the face {} time(s)", f, h, in_face,
                           in_cell);
    }
  }

  for (Id h : g.members(ids_->hex)) {
    for (unsigned i = 0; i < 6; ++i) {
      Id f = hex_face(h, i);
      if (f == no_element) return fmt::format("hex {} has no face {}", h, i);
      if (face_cell(f, 0) != h && face_cell(f, 1) != h)
        return fmt::format("hex {} names face {} which does not name it", h, f);
    }
    // 6. A hex's opposite faces lie on one chord (the chord passes through it).
    for (unsigned k = 0; k < 3; ++k)
      if (face_chord(hex_face(h, 2 * k)) != face_chord(hex_face(h, 2 * k + 1)))
        return fmt::format("hex {}: faces {} and {} are opposite but on different chords", h, 2 * k, 2 * k + 1);
  }
  return {};
}

}  // namespace loom::stc
