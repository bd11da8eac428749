#pragma once
// Helpers shared by the pillow operations (pillow.cpp, node_split.cpp,
// shrink_sets.cpp); not part of the public surface.
#include <algorithm>
#include <map>
#include <vector>

#include "src/stc/stc.hpp"

namespace loom::weave::detail {

using engine::Graph;
using stc::Id;
using stc::no_element;
using stc::Stc;

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

inline std::uint64_t pair_key(Id a, Id b) { return (std::uint64_t{a} << 32) | b; }

/// The faces pointing at `target` through `port` (each once).
inline std::vector<Id> owners_via(const Graph& g, Id target, engine::PortId port) {
  std::vector<Id> out;
  for (engine::SlotId s : g.incoming(target))
    if (g.slot_port(s) == port) out.push_back(g.slot_owner(s));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

inline Vec3 point_of(const Stc& stc, Id node) {
  const Vec3* p = stc.position(node);
  return p ? *p : Vec3{0, 0, 0};
}

inline Vec3 hex_centroid(const Stc& stc, Id hex) {
  Vec3 sum{0, 0, 0};
  for (unsigned i = 0; i < 6; ++i)
    for (unsigned k = 0; k < 4; ++k) sum = sum + point_of(stc, stc.face_node(stc.hex_face(hex, i), k));
  return (1.0 / 24.0) * sum;
}

/// The local components of S around one element x (a node or an edge): the
/// hexes of S (those `in_s` accepts) at x, grouped by the faces at x that
/// have S on both sides.
/// Returns hex -> component index (dense, per element).
template <class InSet>
std::map<Id, std::size_t> components_at(const Stc& stc, const std::vector<Id>& faces_at_x, InSet in_s) {
  std::map<Id, std::size_t> index;
  Groups groups;
  auto idx = [&](Id h) {
    auto [it, fresh] = index.try_emplace(h, 0);
    if (fresh) it->second = groups.add();
    return it->second;
  };
  for (Id f : faces_at_x) {
    Id a = stc.face_cell(f, 0), b = stc.face_cell(f, 1);
    bool sa = a != no_element && in_s(a), sb = b != no_element && in_s(b);
    if (sa) idx(a);
    if (sb) idx(b);
    if (sa && sb) groups.unite(idx(a), idx(b));
  }
  std::map<std::size_t, std::size_t> dense;
  std::map<Id, std::size_t> out;
  for (auto& [h, i] : index) out[h] = dense.try_emplace(groups.find(i), dense.size()).first->second;
  return out;
}


}  // namespace loom::weave::detail
