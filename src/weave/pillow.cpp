#include "src/weave/pillow.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include <fmt/format.h>

namespace loom::weave {

using engine::Graph;
using stc::Stc;

namespace {

/// Union-find over small dense indices.
struct Groups {
  std::vector<std::size_t> parent;
  std::size_t add() {
    parent.push_back(parent.size());
    return parent.size() - 1;
  }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

std::uint64_t pair_key(Id a, Id b) { return (std::uint64_t{a} << 32) | b; }

/// The faces pointing at `target` through `port` (each once).
std::vector<Id> owners_via(const Graph& g, Id target, engine::PortId port) {
  std::vector<Id> out;
  for (engine::SlotId s : g.incoming(target))
    if (g.slot_port(s) == port) out.push_back(g.slot_owner(s));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Vec3 point_of(const Stc& stc, Id node) {
  std::int32_t p = stc.graph().get(node, stc.ids().node_point);
  return p >= 0 ? stc.points()[static_cast<std::size_t>(p)] : Vec3{0, 0, 0};
}

Vec3 hex_centroid(const Stc& stc, Id hex) {
  Vec3 sum{0, 0, 0};
  for (unsigned i = 0; i < 6; ++i)
    for (unsigned k = 0; k < 4; ++k) sum = sum + point_of(stc, stc.face_node(stc.hex_face(hex, i), k));
  return (1.0 / 24.0) * sum;
}

/// The local components of S around one element x (a node or an edge): the
/// hexes of S at x, grouped by the faces at x that have S on both sides.
/// Returns hex -> component index (dense, per element).
std::map<Id, std::size_t> components_at(const Stc& stc, const std::vector<Id>& faces_at_x,
                                        const std::unordered_set<Id>& in_s) {
  std::map<Id, std::size_t> index;
  Groups groups;
  auto idx = [&](Id h) {
    auto [it, fresh] = index.try_emplace(h, 0);
    if (fresh) it->second = groups.add();
    return it->second;
  };
  for (Id f : faces_at_x) {
    Id a = stc.face_cell(f, 0), b = stc.face_cell(f, 1);
    bool sa = a != no_element && in_s.count(a), sb = b != no_element && in_s.count(b);
    if (sa) idx(a);
    if (sb) idx(b);
    if (sa && sb) groups.unite(idx(a), idx(b));
  }
  std::map<std::size_t, std::size_t> dense;
  std::map<Id, std::size_t> out;
  for (auto& [h, i] : index) out[h] = dense.try_emplace(groups.find(i), dense.size()).first->second;
  return out;
}

}  // namespace

std::vector<Id> doublet_shrink_set(const Stc& stc, Id h1, Id h2) {
  std::vector<Id> shared, set{h1};
  for (unsigned i = 0; i < 6; ++i)
    if (stc.across(stc.hex_face(h1, i), h1) == h2) shared.push_back(stc.hex_face(h1, i));
  auto nodes_of = [&](Id f) {
    std::vector<Id> n;
    for (unsigned k = 0; k < 4; ++k) n.push_back(stc.face_node(f, k));
    return n;
  };
  std::vector<Id> shared_nodes;
  for (Id f : shared)
    for (Id n : nodes_of(f)) shared_nodes.push_back(n);
  for (unsigned i = 0; i < 6; ++i) {
    Id f = stc.hex_face(h1, i);
    if (std::find(shared.begin(), shared.end(), f) != shared.end()) continue;
    // Faces of h1 meeting the shared faces in an edge only are left out:
    // a face holding more than two shared nodes is one that meets two of them.
    auto n = nodes_of(f);
    auto touching = std::count_if(n.begin(), n.end(), [&](Id x) {
      return std::find(shared_nodes.begin(), shared_nodes.end(), x) != shared_nodes.end();
    });
    Id other = stc.across(f, h1);
    if (touching > 2 && other != no_element && other != h2 &&
        std::find(set.begin(), set.end(), other) == set.end())
      set.push_back(other);
  }
  return set;
}

std::vector<Id> hexes_at_node(const Stc& stc, Id node) {
  std::vector<Id> out;
  for (Id f : owners_via(stc.graph(), node, stc.ids().face_node))
    for (unsigned side = 0; side < 2; ++side)
      if (Id h = stc.face_cell(f, side); h != no_element) out.push_back(h);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

PillowCounts insert_pillow(Stc& stc, std::span<const Id> shrink_set) {
  Graph& g = stc.graph();
  const stc::StcSchema& ids = stc.ids();
  std::unordered_set<Id> in_s(shrink_set.begin(), shrink_set.end());

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
  for (Id x : nodes) node_parts[x] = components_at(stc, owners_via(g, x, ids.face_node), in_s);
  for (Id e : edges) {
    auto parts = components_at(stc, owners_via(g, e, ids.face_edge), in_s);
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
      g.set(copy, ids.node_point, static_cast<std::int32_t>(stc.points().size()));
      stc.points().push_back(at + 0.3 * (towards - at));
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
  std::vector<std::pair<Id, Id>> inside_edges;
  for (auto [f, h] : inside_faces)
    for (unsigned k = 0; k < 4; ++k)
      if (Id e = stc.face_edge(f, k); !is_shell_edge(e) && seen.insert(e).second) inside_edges.emplace_back(e, h);
  for (auto [e, h] : inside_edges)
    for (unsigned k = 0; k < 2; ++k)
      if (Id x = stc.edge_node(e, k); is_shell_node(x)) g.link(e, ids.edge_node, k, inner_of_node(x, h));
  for (auto [f, h] : inside_faces)
    for (unsigned k = 0; k < 4; ++k) {
      if (Id x = stc.face_node(f, k); is_shell_node(x)) g.link(f, ids.face_node, k, inner_of_node(x, h));
      if (Id e = stc.face_edge(f, k); is_shell_edge(e)) g.link(f, ids.face_edge, k, inner_of_edge(e, h));
    }

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

std::size_t split_pinched_node(Stc& stc, Id node) {
  Graph& g = stc.graph();
  const stc::StcSchema& ids = stc.ids();
  std::vector<Id> faces = owners_via(g, node, ids.face_node);
  std::map<Id, std::size_t> index;
  Groups groups;
  auto idx = [&](Id h) {
    auto [it, fresh] = index.try_emplace(h, 0);
    if (fresh) it->second = groups.add();
    return it->second;
  };
  for (Id f : faces) {
    Id a = stc.face_cell(f, 0), b = stc.face_cell(f, 1);
    if (a != no_element) idx(a);
    if (b != no_element) idx(b);
    if (a != no_element && b != no_element) groups.unite(idx(a), idx(b));
  }
  // Group of each face at the node, in the order the groups first appear.
  std::map<std::size_t, std::size_t> dense;
  std::vector<std::size_t> group_of_face;
  for (Id f : faces) {
    Id h = stc.face_cell(f, 0) != no_element ? stc.face_cell(f, 0) : stc.face_cell(f, 1);
    if (h == no_element) throw std::runtime_error(fmt::format("split: face {} at node {} has no hex", f, node));
    group_of_face.push_back(dense.try_emplace(groups.find(index.at(h)), dense.size()).first->second);
  }
  const std::size_t parts = dense.size();
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
