#include "src/stc/build.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "src/util/error.hpp"

namespace loom::stc {

namespace {

class UnionFind {
public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<std::uint32_t> parent_;
};

struct KeyHash {
  std::size_t operator()(std::uint64_t k) const { return std::hash<std::uint64_t>{}(k * 0x9E3779B97F4A7C15ull); }
  std::size_t operator()(const std::array<std::uint32_t, 4>& k) const {
    std::uint64_t h = 0;
    for (auto v : k) h = (h ^ v) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// Creates nodes, edges and faces of a cell complex, each once.
class ComplexBuilder {
public:
  ComplexBuilder(Stc& stc, std::size_t points)
      : g_(stc.graph()), ids_(stc.ids()), node_of_point_(points, no_element) {}

  Id node(std::uint32_t p) {
    Id& n = node_of_point_[p];
    if (n == no_element) {
      n = g_.add(ids_.node);
      g_.set(n, ids_.node_point, static_cast<std::int32_t>(p));
    }
    return n;
  }

  /// Creates the nodes of all used points first, so node order is point order.
  void reserve_nodes_in_point_order(const std::vector<bool>& used) {
    for (std::uint32_t p = 0; p < used.size(); ++p)
      if (used[p]) node(p);
  }

  Id edge(std::uint32_t a, std::uint32_t b) {
    std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    auto [it, fresh] = edges_.try_emplace(key, no_element);
    if (fresh) {
      it->second = g_.add(ids_.edge);
      g_.link(it->second, ids_.edge_node, 0, node(a));
      g_.link(it->second, ids_.edge_node, 1, node(b));
    }
    return it->second;
  }

  /// The face with node cycle `c`; `same` tells whether its stored cycle runs
  /// the same way as `c` (a face is stored with the cycle it was first seen with).
  Id face(const std::array<std::uint32_t, 4>& c, bool& same) {
    bool forward = false;
    auto key = canonical(c, forward);
    auto [it, fresh] = faces_.try_emplace(key, StoredFace{no_element, forward});
    if (fresh) {
      Id f = it->second.id = g_.add(ids_.face);
      for (unsigned i = 0; i < 4; ++i) {
        g_.link(f, ids_.face_node, i, node(c[i]));
        g_.link(f, ids_.face_edge, i, edge(c[i], c[(i + 1) % 4]));
      }
    }
    same = it->second.forward == forward;
    return it->second.id;
  }

private:
  struct StoredFace {
    Id id;
    bool forward;  ///< direction of the stored cycle relative to the canonical key
  };
  // Rotated to start at the smallest index, walked towards the smaller neighbour.
  static std::array<std::uint32_t, 4> canonical(const std::array<std::uint32_t, 4>& c, bool& forward) {
    unsigned m = static_cast<unsigned>(std::min_element(c.begin(), c.end()) - c.begin());
    forward = c[(m + 1) % 4] < c[(m + 3) % 4];
    std::array<std::uint32_t, 4> k{};
    for (unsigned i = 0; i < 4; ++i) k[i] = forward ? c[(m + i) % 4] : c[(m + 4 - i) % 4];
    return k;
  }

  engine::Graph& g_;
  const StcSchema& ids_;
  std::vector<Id> node_of_point_;
  std::unordered_map<std::uint64_t, Id, KeyHash> edges_;
  std::unordered_map<std::array<std::uint32_t, 4>, StoredFace, KeyHash> faces_;
};

/// Sheets (classes of opposite edges) and chords (classes of opposite faces,
/// through hexes), created in order of their first edge and first face.
void group_sheets_and_chords(Stc& stc) {
  engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  UnionFind edges(g.id_bound()), faces(g.id_bound());
  for (Id f : g.members(ids.face)) {
    edges.unite(stc.face_edge(f, 0), stc.face_edge(f, 2));
    edges.unite(stc.face_edge(f, 1), stc.face_edge(f, 3));
  }
  for (Id h : g.members(ids.hex))
    for (unsigned k = 0; k < 3; ++k) faces.unite(stc.hex_face(h, 2 * k), stc.hex_face(h, 2 * k + 1));

  std::unordered_map<std::uint32_t, Id> sheet_of_root, chord_of_root;
  for (Id e : g.members(ids.edge)) {
    auto [it, fresh] = sheet_of_root.try_emplace(edges.find(e), no_element);
    if (fresh) it->second = g.add(ids.sheet);
    g.link(e, ids.edge_sheet, 0, it->second);
  }
  for (Id f : g.members(ids.face)) {
    auto [it, fresh] = chord_of_root.try_emplace(faces.find(f), no_element);
    Id s0 = stc.edge_sheet(stc.face_edge(f, 0)), s1 = stc.edge_sheet(stc.face_edge(f, 1));
    if (fresh) {
      it->second = g.add(ids.chord);
      g.link(it->second, ids.chord_sheet, 0, s0);
      g.link(it->second, ids.chord_sheet, 1, s1);
    }
    g.link(f, ids.face_chord, 0, it->second);
    if (s0 == s1) {
      g.set(s0, ids.sheet_self, 1);
      g.set(it->second, ids.chord_self, 1);
    }
  }
  for (Id h : g.members(ids.hex)) {
    Id c0 = stc.face_chord(stc.hex_face(h, 0)), c1 = stc.face_chord(stc.hex_face(h, 2)),
       c2 = stc.face_chord(stc.hex_face(h, 4));
    for (Id c : {c0, c1, c2})
      if ((c == c0) + (c == c1) + (c == c2) > 1) g.set(c, ids.chord_self, 1);
  }
}

// Outward node cycles of the six faces of a positively oriented VTK hex.
constexpr std::array<std::array<int, 4>, 6> hex_face_cycles{{
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}}};

/// Marks the nodes of boundary face `f` and records their points (in order of
/// face.boundary, which callers number 0, 1, 2, ...).
void record_boundary_points(Stc& stc, Id f) {
  engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  std::array<std::int32_t, 4> points{};
  for (unsigned i = 0; i < 4; ++i) {
    g.set(stc.face_node(f, i), ids.node_boundary, 1);
    points[i] = g.get(stc.face_node(f, i), ids.node_point);
  }
  stc.boundary_points().push_back(points);
}

}  // namespace

Stc build_from_hex_mesh(const HexMesh& mesh) {
  Stc stc;
  engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  stc.points() = mesh.points;
  std::vector<bool> used(mesh.points.size(), false);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const Hex& hex = mesh.hexes[h];
    for (auto p : hex) {
      if (p >= mesh.points.size())
        fail_input(fmt::format("hex {}", h), fmt::format("node index {} is out of range", p), "fix the mesh file");
      used[p] = true;
    }
    auto sorted = hex;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      fail_input(fmt::format("hex {}", h), "repeats a node (degenerate hex)", "run 'loom check' on the mesh");
  }
  ComplexBuilder complex(stc, mesh.points.size());
  complex.reserve_nodes_in_point_order(used);

  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    Id hex = g.add(ids.hex);
    g.set(hex, ids.hex_source, static_cast<std::int32_t>(h));
    for (unsigned i = 0; i < 6; ++i) {
      std::array<std::uint32_t, 4> cycle{};
      for (unsigned k = 0; k < 4; ++k) cycle[k] = mesh.hexes[h][hex_face_cycles[i][k]];
      bool same = false;
      Id f = complex.face(cycle, same);
      unsigned side = same ? 0 : 1;
      if (stc.face_cell(f, side) != no_element) side ^= 1;
      if (stc.face_cell(f, side) != no_element)
        fail_input(fmt::format("hex {}", h), fmt::format("its face {} is shared by more than two hexes", i),
                   "run 'loom check' on the mesh");
      g.link(f, ids.face_cell, side, hex);
      g.link(hex, ids.hex_face, i, f);
    }
  }
  std::int32_t boundary = 0;
  for (Id f : g.members(ids.face))
    if (stc.face_cell(f, 1) == no_element || stc.face_cell(f, 0) == no_element) {
      if (stc.face_cell(f, 0) == no_element) {  // keep the hex on the inner side, slot 0
        g.link(f, ids.face_cell, 0, stc.face_cell(f, 1));
        g.link(f, ids.face_cell, 1, no_element);
      }
      g.set(f, ids.face_boundary, boundary++);
      record_boundary_points(stc, f);
    }
  group_sheets_and_chords(stc);
  stc.debug_check();
  return stc;
}

Stc build_from_surface(const QuadSurface& surface) {
  Stc stc;
  engine::Graph& g = stc.graph();
  const StcSchema& ids = stc.ids();
  stc.points() = surface.points;
  std::vector<bool> used(surface.points.size(), false);
  for (const Quad& q : surface.quads)
    for (auto p : q) used.at(p) = true;
  ComplexBuilder complex(stc, surface.points.size());
  complex.reserve_nodes_in_point_order(used);
  for (std::size_t q = 0; q < surface.quads.size(); ++q) {
    bool same = false;
    Id f = complex.face(surface.quads[q], same);
    g.set(f, ids.face_boundary, static_cast<std::int32_t>(q));
    record_boundary_points(stc, f);
  }
  group_sheets_and_chords(stc);
  stc.debug_check();
  return stc;
}

}  // namespace loom::stc
