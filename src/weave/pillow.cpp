#include "src/weave/pillow.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <fmt/format.h>

#include "src/weave/pillow_detail.hpp"

namespace loom::weave {

using namespace detail;

PillowCounts insert_pillow(Stc& stc, std::span<const Id> shrink_set) {
  Graph& g = stc.graph();
  const stc::StcSchema& ids = stc.ids();
  std::unordered_set<Id> in_s(shrink_set.begin(), shrink_set.end());
  auto in_set = [&](Id h) { return in_s.count(h) != 0; };

  // dS: faces with S on exactly one side, and the S hex behind each.
  std::vector<std::pair<Id, Id>> shell;  // (face, its hex in S)
  std::unordered_set<Id> shell_faces;
  std::vector<Id> nodes, edges;
  for (Id h : shrink_set)
    for (unsigned i = 0; i < 6; ++i) {
      Id f = stc.hex_face(h, i);
      Id other = stc.across(f, h);
      if (other == h) throw std::runtime_error(fmt::format("pillow: hex {} meets itself across face {}", h, f));
      if (other != no_element && in_s.count(other)) continue;
      if (!shell_faces.insert(f).second)
        throw std::runtime_error(fmt::format("pillow: face {} bounds the shrink set twice", f));
      shell.emplace_back(f, h);
      for (unsigned k = 0; k < 4; ++k) {
        nodes.push_back(stc.face_node(f, k));
        edges.push_back(stc.face_edge(f, k));
      }
    }
  if (shell.empty()) throw std::runtime_error("pillow: the shrink set has no boundary");
  for (auto* v : {&nodes, &edges}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }

  // Local components of S around every node and edge of dS, checked before
  // anything changes: each sector of S around an edge must end in two faces of dS.
  std::unordered_map<Id, std::map<Id, std::size_t>> node_parts, edge_parts;
  for (Id x : nodes) node_parts[x] = components_at(stc, owners_via(g, x, ids.face_node), in_set);
  for (Id e : edges) {
    auto parts = components_at(stc, owners_via(g, e, ids.face_edge), in_set);
    std::map<std::size_t, int> ends;
    for (auto& [f, h] : shell)
      if (stc.slot_in_face(f, e) < 4) ++ends[parts.at(h)];
    for (auto [part, count] : ends)
      if (count != 2)
        throw std::runtime_error(
            fmt::format("pillow: a sector of the shrink set around edge {} ends in {} boundary faces, not 2", e, count));
    edge_parts[e] = std::move(parts);
  }

  // Inner copies: one node and one edge per (element, local component).
  std::unordered_map<std::uint64_t, Id> inner_node, inner_edge, vertical;
  Id sheet = g.add(ids.sheet);
  for (Id x : nodes) {
    std::map<std::size_t, std::pair<Vec3, int>> centre;
    for (auto [h, part] : node_parts[x]) {
      auto& [sum, n] = centre[part];
      sum = sum + hex_centroid(stc, h);
      ++n;
    }
    Vec3 at = point_of(stc, x);
    for (auto& [part, c] : centre) {
      Id copy = g.add(ids.node);
      Vec3 towards = (1.0 / c.second) * c.first;
      stc.place(copy, at + 0.3 * (towards - at));
      inner_node[pair_key(x, static_cast<Id>(part))] = copy;
      Id v = g.add(ids.edge);
      g.link(v, ids.edge_node, 0, x);
      g.link(v, ids.edge_node, 1, copy);
      g.link(v, ids.edge_sheet, 0, sheet);
      vertical[pair_key(x, static_cast<Id>(part))] = v;
    }
  }
  auto inner_of_node = [&](Id x, Id h) { return inner_node.at(pair_key(x, static_cast<Id>(node_parts.at(x).at(h)))); };
  for (Id e : edges)
    for (auto [h, part] : edge_parts[e]) {
      auto key = pair_key(e, static_cast<Id>(part));
      if (inner_edge.count(key)) continue;
      Id copy = g.add(ids.edge);
      g.link(copy, ids.edge_node, 0, inner_of_node(stc.edge_node(e, 0), h));
      g.link(copy, ids.edge_node, 1, inner_of_node(stc.edge_node(e, 1), h));
      g.link(copy, ids.edge_sheet, 0, stc.edge_sheet(e));
      inner_edge[key] = copy;
    }
  auto inner_of_edge = [&](Id e, Id h) { return inner_edge.at(pair_key(e, static_cast<Id>(edge_parts.at(e).at(h)))); };
  auto is_shell_node = [&](Id x) { return node_parts.count(x) != 0; };
  auto is_shell_edge = [&](Id e) { return edge_parts.count(e) != 0; };

  // S moves onto the inner copies: faces inside S, and edges inside S.
  std::vector<std::pair<Id, Id>> inside_faces;  // (face, one of its S hexes)
  std::unordered_set<Id> seen;
  for (Id h : shrink_set)
    for (unsigned i = 0; i < 6; ++i) {
      Id f = stc.hex_face(h, i);
      if (!shell_faces.count(f) && seen.insert(f).second) inside_faces.emplace_back(f, h);
    }
  // An edge inside S follows the copies of its ends that the faces using it
  // see; when its hexes lie in two local components at an end (an edge the
  // weave pinched), each pair of ends gets its own copy of the edge.
  std::unordered_map<Id, std::pair<Id, Id>> ends_before;
  for (auto [f, h] : inside_faces)
    for (unsigned k = 0; k < 4; ++k)
      if (Id e = stc.face_edge(f, k); !is_shell_edge(e)) ends_before.try_emplace(e, stc.edge_node(e, 0), stc.edge_node(e, 1));
  std::map<std::tuple<Id, Id, Id>, Id> inside_edge;  // (edge, end 0, end 1) -> the edge to use
  // An edge that faces outside S use too (which a degenerate weave allows
  // without it being on dS) is never moved: S's faces get copies.
  std::unordered_set<Id> inside(seen.begin(), seen.end()), reused;
  for (auto& [e, ends] : ends_before)
    for (engine::SlotId sl : g.incoming(e))
      if (g.slot_port(sl) == ids.face_edge && !inside.count(g.slot_owner(sl))) reused.insert(e);
  auto inner_end = [&](Id x, Id h) { return is_shell_node(x) ? inner_of_node(x, h) : x; };
  for (auto [f, h] : inside_faces)
    for (unsigned k = 0; k < 4; ++k) {
      Id e = stc.face_edge(f, k);
      if (is_shell_edge(e)) {
        g.link(f, ids.face_edge, k, inner_of_edge(e, h));
        continue;
      }
      auto [x0, x1] = ends_before.at(e);
      Id end0 = inner_end(x0, h), end1 = inner_end(x1, h);
      auto [it, fresh] = inside_edge.try_emplace({e, end0, end1}, no_element);
      if (fresh) {
        it->second = reused.insert(e).second ? e : g.add(ids.edge);
        g.link(it->second, ids.edge_node, 0, end0);
        g.link(it->second, ids.edge_node, 1, end1);
        g.link(it->second, ids.edge_sheet, 0, stc.edge_sheet(e));
      }
      g.link(f, ids.face_edge, k, it->second);
    }
  for (auto [f, h] : inside_faces)
    for (unsigned k = 0; k < 4; ++k)
      if (Id x = stc.face_node(f, k); is_shell_node(x)) g.link(f, ids.face_node, k, inner_of_node(x, h));

  // One pillow hex per face of dS, between the face and its inner copy.
  std::unordered_map<std::uint64_t, Id> side_face;  // (edge, component) -> face
  Groups chords;
  std::unordered_map<Id, std::size_t> chord_index;
  auto side = [&](Id e, Id a, Id b, Id s, Id pillow) {
    auto key = pair_key(e, static_cast<Id>(edge_parts.at(e).at(s)));
    auto [it, fresh] = side_face.try_emplace(key, no_element);
    if (fresh) {
      Id q = it->second = g.add(ids.face);
      Id va = vertical.at(pair_key(a, static_cast<Id>(node_parts.at(a).at(s))));
      Id vb = vertical.at(pair_key(b, static_cast<Id>(node_parts.at(b).at(s))));
      Id node_cycle[4] = {a, b, inner_of_node(b, s), inner_of_node(a, s)};
      Id edge_cycle[4] = {e, vb, inner_of_edge(e, s), va};
      for (unsigned k = 0; k < 4; ++k) {
        g.link(q, ids.face_node, k, node_cycle[k]);
        g.link(q, ids.face_edge, k, edge_cycle[k]);
      }
      // Seen from this pillow hex, a -> b runs along dS oriented away from S,
      // so the cycle a b b' a' faces into the pillow hex: it is cell[1].
      g.link(q, ids.face_cell, 1, pillow);
      chord_index[q] = chords.add();
    } else {
      Id q = it->second;
      if (stc.face_node(q, 0) != b || stc.face_cell(q, 0) != no_element)
        throw std::runtime_error(fmt::format("pillow: the boundary of the shrink set is not oriented at edge {}", e));
      g.link(q, ids.face_cell, 0, pillow);
    }
    return it->second;
  };
  PillowCounts counts;
  for (auto [f, s] : shell) {
    Id pillow = g.add(ids.hex);
    ++counts.hexes;
    Id copy = g.add(ids.face);
    for (unsigned k = 0; k < 4; ++k) {
      g.link(copy, ids.face_node, k, inner_of_node(stc.face_node(f, k), s));
      g.link(copy, ids.face_edge, k, inner_of_edge(stc.face_edge(f, k), s));
    }
    g.link(copy, ids.face_chord, 0, stc.face_chord(f));
    g.set(copy, ids.face_layer, g.get(f, ids.face_layer));
    const bool forward = stc.face_cell(f, 0) == s;  // f's cycle faces away from S
    g.link(copy, ids.face_cell, forward ? 0 : 1, s);
    g.link(copy, ids.face_cell, forward ? 1 : 0, pillow);
    g.link(s, ids.hex_face, stc.slot_in_hex(s, f), copy);
    g.link(f, ids.face_cell, forward ? 0 : 1, pillow);
    // f's cycle oriented away from S: o[i] -> o[i+1] along edge oe[i].
    Id o[4], oe[4];
    for (unsigned i = 0; i < 4; ++i) {
      o[i] = stc.face_node(f, forward ? i : (4 - i) % 4);
      oe[i] = stc.face_edge(f, forward ? i : 3 - i);
    }
    Id q[4];
    for (unsigned i = 0; i < 4; ++i) q[i] = side(oe[i], o[i], o[(i + 1) % 4], s, pillow);
    Id faces[6] = {copy, f, q[0], q[2], q[3], q[1]};
    for (unsigned i = 0; i < 6; ++i) g.link(pillow, ids.hex_face, i, faces[i]);
    chords.unite(chord_index.at(q[0]), chord_index.at(q[2]));
    chords.unite(chord_index.at(q[1]), chord_index.at(q[3]));
  }
  for (auto& [key, q] : side_face)
    if (stc.face_cell(q, 0) == no_element)
      throw std::logic_error(fmt::format("pillow: side face {} has one pillow hex", q));

  // The chords of the pillow sheet: side faces opposite in a pillow hex.
  std::unordered_map<std::size_t, Id> chord_of_group;
  std::vector<Id> sides;
  for (auto& [key, q] : side_face) sides.push_back(q);
  std::sort(sides.begin(), sides.end());
  for (Id q : sides) {
    auto [it, fresh] = chord_of_group.try_emplace(chords.find(chord_index.at(q)), no_element);
    if (fresh) {
      it->second = g.add(ids.chord);
      g.link(it->second, ids.chord_sheet, 0, stc.edge_sheet(stc.face_edge(q, 0)));
      g.link(it->second, ids.chord_sheet, 1, sheet);
      ++counts.chords;
    }
    g.link(q, ids.face_chord, 0, it->second);
  }
  return counts;
}

}  // namespace loom::weave
