#include "src/weave/database_closure.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include <fmt/format.h>

#include "src/closure/cavity.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/pillow_detail.hpp"

namespace loom::weave {

using detail::owners_via;
using stc::Id;
using stc::no_element;
using stc::Stc;

namespace {

/// The STC's hex face slots (stc.hpp) as indices into quadmap::outward_faces.
constexpr int kOutwardOfSlot[6] = {0, 1, 2, 4, 5, 3};

/// Face `slot` of a hex, its corners in the order that faces into the hex
/// (for hexes oriented as the database places them).
Quad inward_face(const Hex& h, int slot) {
  const Quad q = quadmap::outward_faces(h)[kOutwardOfSlot[slot]];
  return {q[0], q[3], q[2], q[1]};
}
/// Per axis of a hex, the four edges joining faces 2*axis and 2*axis + 1.
constexpr int kAxisEdges[3][4][2] = {{{0, 4}, {1, 5}, {2, 6}, {3, 7}},
                                     {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
                                     {{0, 1}, {3, 2}, {4, 5}, {7, 6}}};

/// The whiskers of the front component of `face`, or nothing when it is not
/// a closed surface of at most `most` faces.
std::optional<std::vector<Id>> front_component(const Stc& stc, Id face, std::size_t most) {
  const auto& ids = stc.ids();
  if (!stc.is_whisker(face) || stc.face_cell(face, 0) != no_element) return std::nullopt;
  std::vector<Id> faces{face};
  std::unordered_set<Id> seen{face};
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (unsigned k = 0; k < 4; ++k) {
      std::vector<Id> on_edge = owners_via(stc.graph(), stc.face_edge(faces[i], k), ids.face_edge);
      std::erase_if(on_edge, [&](Id f) { return !stc.is_whisker(f); });
      if (on_edge.size() != 2) return std::nullopt;
      for (Id f : on_edge) {
        if (stc.face_cell(f, 0) != no_element) return std::nullopt;
        if (seen.insert(f).second) faces.push_back(f);
      }
      if (faces.size() > most) return std::nullopt;
    }
  return faces;
}

/// A front component as a cavity (closure/cavity.hpp) over dense vertex ids.
struct Placement {
  std::vector<Id> faces;    ///< the component's whiskers, one per front quad
  std::vector<Id> node_of;  ///< dense id -> STC node
  closure::Cavity cavity;
};

std::optional<Placement> placement_of(const Stc& stc, std::vector<Id> faces) {
  const auto& ids = stc.ids();
  Placement p;
  std::unordered_map<Id, std::uint32_t> dense;
  auto id = [&](Id node) {
    auto [it, fresh] = dense.try_emplace(node, static_cast<std::uint32_t>(p.node_of.size()));
    if (fresh) p.node_of.push_back(node);
    return it->second;
  };
  for (Id f : faces) {
    Quad q;
    for (unsigned k = 0; k < 4; ++k) q[k] = id(stc.face_node(f, k));
    p.cavity.front.quads.push_back(q);
  }
  const std::size_t front_nodes = p.node_of.size();
  std::vector<Id> hexes;
  for (std::size_t v = 0; v < front_nodes; ++v)
    for (Id f : owners_via(stc.graph(), p.node_of[v], ids.face_node))
      for (unsigned side = 0; side < 2; ++side)
        if (Id h = stc.face_cell(f, side); h != no_element) hexes.push_back(h);
  std::sort(hexes.begin(), hexes.end());
  hexes.erase(std::unique(hexes.begin(), hexes.end()), hexes.end());
  for (Id h : hexes) {
    Hex corners;
    for (unsigned k = 0; k < 8; ++k) {
      const Id n = stc::corner_node(stc, h, k);
      if (n == no_element) return std::nullopt;  // a degenerate hex beside the component
      corners[k] = id(n);
    }
    p.cavity.hexes.push_back(corners);
  }
  for (Id f : faces) {
    const Id behind = stc.face_cell(f, 1);
    p.cavity.owner.push_back(
        behind == no_element ? -1
                             : static_cast<std::int32_t>(std::lower_bound(hexes.begin(), hexes.end(), behind) - hexes.begin()));
  }
  p.cavity.front.vertex_bound = static_cast<std::uint32_t>(p.node_of.size());
  if (!closure::why_not_closable(p.cavity).empty()) return std::nullopt;
  p.faces = std::move(faces);
  return p;
}

/// The database's mesh placed in the cavity: one expansion of the search,
/// which looks the front up and tries every automorphism.
std::optional<std::vector<Hex>> database_mesh(const Placement& p, const closure::Database& db) {
  closure::ClosureOptions options;
  options.limits.max_expansions = 1;
  options.max_growth = 0;
  closure::ClosureResult r = closure::close_cavity(p.cavity, &db, options);
  if (!r.closed) return std::nullopt;
  return std::move(r.hexes);
}

std::optional<std::pair<Placement, std::vector<Hex>>> find_template(const Stc& stc, Id face,
                                                                    const closure::Database& db) {
  auto faces = front_component(stc, face, kMostTemplateQuads);
  if (!faces) return std::nullopt;
  auto p = placement_of(stc, std::move(*faces));
  if (!p) return std::nullopt;
  auto hexes = database_mesh(*p, db);
  if (!hexes) return std::nullopt;
  return std::make_pair(std::move(*p), std::move(*hexes));
}

/// Builds the hexes into the STC.
class Inserter {
public:
  explicit Inserter(Stc& stc) : stc_(stc), g_(stc.graph()), ids_(stc.ids()) {}

  std::size_t insert(const Placement& p, std::vector<Hex> hexes) {
    int layer = 0;
    for (Id f : p.faces) {
      faces_.emplace(key_of(f), f);
      layer = std::max(layer, g_.get(f, ids_.face_layer) + 1);
    }
    if (needs_mirroring(p, hexes))
      for (Hex& h : hexes) h = mirror_hex(h);
    std::vector<Hex> corners;
    for (const Hex& h : hexes) {
      Hex c;
      for (unsigned k = 0; k < 8; ++k) c[k] = node(p, h[k]);
      corners.push_back(c);
    }
    std::vector<Id> made;
    for (const auto& c : corners) made.push_back(add_hex(c, layer));
    join_sheets(made, corners);
    join_chords(made);
    place_new_nodes(corners);
    return made.size();
  }

private:
  std::array<Id, 4> key_of(const std::array<Id, 4>& nodes) const {
    std::array<Id, 4> k = nodes;
    std::sort(k.begin(), k.end());
    return k;
  }
  std::array<Id, 4> key_of(Id face) const {
    std::array<Id, 4> k;
    for (unsigned i = 0; i < 4; ++i) k[i] = stc_.face_node(face, i);
    return key_of(k);
  }

  /// Whether the hexes face the other way round from the STC's convention: a
  /// whisker's cycle faces away from the hex that goes on its open side.
  bool needs_mirroring(const Placement& p, const std::vector<Hex>& hexes) const {
    std::map<std::array<std::uint32_t, 4>, std::size_t> front;
    for (std::size_t q = 0; q < p.cavity.front.size(); ++q) {
      auto k = p.cavity.front.quads[q];
      std::sort(k.begin(), k.end());
      front.emplace(k, q);
    }
    for (const Hex& h : hexes)
      for (int slot = 0; slot < 6; ++slot) {
        const Quad inward = inward_face(h, slot);
        Quad k = inward;
        std::sort(k.begin(), k.end());
        auto it = front.find(k);
        if (it == front.end()) continue;
        const Quad& q = p.cavity.front.quads[it->second];
        const auto at = static_cast<std::size_t>(std::find(q.begin(), q.end(), inward[0]) - q.begin());
        return q[(at + 1) % 4] == inward[1];  // the whisker runs as the hex's inward cycle
      }
    throw std::logic_error("close_from_database: no hex of the mesh lies on the front");
  }

  Id node(const Placement& p, std::uint32_t v) {
    if (v < p.node_of.size()) return p.node_of[v];
    auto [it, fresh] = new_nodes_.try_emplace(v, no_element);
    if (fresh) it->second = g_.add(ids_.node);
    return it->second;
  }

  Id edge_between(Id a, Id b) {
    for (Id e : owners_via(g_, a, ids_.edge_node))
      if (stc_.edge_node(e, 0) == b || stc_.edge_node(e, 1) == b) return e;
    const Id e = g_.add(ids_.edge);
    g_.link(e, ids_.edge_node, 0, a);
    g_.link(e, ids_.edge_node, 1, b);
    return e;
  }

  Id add_hex(const Hex& c, int layer) {
    const Id h = g_.add(ids_.hex);
    g_.set(h, ids_.hex_source, stc::kHexFromDatabase);
    for (unsigned i = 0; i < 6; ++i) {
      const Quad cycle = inward_face(c, static_cast<int>(i));
      auto [it, fresh] = faces_.try_emplace(key_of(cycle), no_element);
      if (!fresh) {
        if (stc_.face_cell(it->second, 0) != no_element)
          throw std::logic_error(fmt::format("close_from_database: face {} has no open side", it->second));
        g_.link(it->second, ids_.face_cell, 0, h);
      } else {
        const Id f = it->second = g_.add(ids_.face);
        for (unsigned k = 0; k < 4; ++k) {
          g_.link(f, ids_.face_node, k, cycle[k]);
          g_.link(f, ids_.face_edge, k, edge_between(cycle[k], cycle[(k + 1) % 4]));
        }
        g_.link(f, ids_.face_cell, 1, h);
        g_.set(f, ids_.face_layer, layer);
      }
      g_.link(h, ids_.hex_face, i, it->second);
    }
    return h;
  }

  /// Identifies `from` with `into` (two sheets or two chords found to be one).
  void merge(Id from, Id into) {
    g_.redirect_incoming(from, into);
    if (g_.get(from, from_self(from)) != 0) g_.set(into, from_self(from), 1);
    g_.remove(from);
  }
  engine::AttrId from_self(Id x) const {
    return g_.kind(x) == ids_.sheet ? ids_.sheet_self : ids_.chord_self;
  }

  /// Parallel edges of a hex lie on one sheet: new edges take their
  /// neighbours' sheet, sheets that meet in a hex are merged, and edges with
  /// no sheet anywhere near get a new one.
  void join_sheets(const std::vector<Id>& made, const std::vector<Hex>& corners) {
    std::vector<std::array<std::array<Id, 4>, 3>> axis_edges(made.size());
    for (std::size_t h = 0; h < made.size(); ++h)
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k)
          axis_edges[h][a][k] = edge_between(corners[h][kAxisEdges[a][k][0]], corners[h][kAxisEdges[a][k][1]]);
    for (bool open = true; open;) {
      open = false;
      bool changed = true;
      while (changed) {
        changed = false;
        for (const auto& axes : axis_edges)
          for (const auto& edges : axes) {
            Id sheet = no_element;
            for (Id e : edges) {
              const Id s = stc_.edge_sheet(e);
              if (s == no_element) continue;
              if (sheet == no_element) sheet = s;
              else if (s != sheet) merge(s, sheet), changed = true;
            }
            if (sheet == no_element) {
              open = true;
              continue;
            }
            for (Id e : edges)
              if (stc_.edge_sheet(e) == no_element) g_.link(e, ids_.edge_sheet, 0, sheet), changed = true;
          }
      }
      if (open) new_sheet_for_one(axis_edges);
    }
    for (Id h : made)
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = a + 1; b < 3; ++b)
          if (stc_.hex_sheet(h, a) == stc_.hex_sheet(h, b)) g_.set(stc_.hex_sheet(h, a), ids_.sheet_self, 1);
  }

  /// A new sheet for the first axis whose edges have none; the next round
  /// spreads it.
  void new_sheet_for_one(const std::vector<std::array<std::array<Id, 4>, 3>>& axis_edges) {
    for (const auto& axes : axis_edges)
      for (const auto& edges : axes)
        if (stc_.edge_sheet(edges[0]) == no_element) {
          const Id s = g_.add(ids_.sheet);
          for (Id e : edges) g_.link(e, ids_.edge_sheet, 0, s);
          return;
        }
  }

  /// Opposite faces of a hex lie on one chord, on the sheets of the face's edges.
  void join_chords(const std::vector<Id>& made) {
    for (bool changed = true; changed;) {
      changed = false;
      for (Id h : made)
        for (unsigned a = 0; a < 3; ++a) {
          const Id f = stc_.hex_face(h, 2 * a), o = stc_.hex_face(h, 2 * a + 1);
          const Id cf = stc_.face_chord(f), co = stc_.face_chord(o);
          if (cf != no_element && co != no_element && cf != co) merge(co, cf), changed = true;
          else if (cf != no_element && co == no_element) g_.link(o, ids_.face_chord, 0, cf), changed = true;
          else if (co != no_element && cf == no_element) g_.link(f, ids_.face_chord, 0, co), changed = true;
        }
      if (changed) continue;
      for (Id h : made)
        for (unsigned a = 0; a < 3 && !changed; ++a) {
          const Id f = stc_.hex_face(h, 2 * a);
          if (stc_.face_chord(f) != no_element) continue;
          const Id c = g_.add(ids_.chord);
          g_.link(c, ids_.chord_sheet, 0, stc_.edge_sheet(stc_.face_edge(f, 0)));
          g_.link(c, ids_.chord_sheet, 1, stc_.edge_sheet(stc_.face_edge(f, 1)));
          g_.link(f, ids_.face_chord, 0, c);
          changed = true;
        }
    }
    for (Id h : made)
      for (unsigned a = 0; a < 3; ++a) {
        const Id c = stc_.face_chord(stc_.hex_face(h, 2 * a));
        for (unsigned b = a + 1; b < 3; ++b)
          if (stc_.face_chord(stc_.hex_face(h, 2 * b)) == c) g_.set(c, ids_.chord_self, 1);
        if (stc_.chord_sheet(c, 0) == stc_.chord_sheet(c, 1)) g_.set(c, ids_.chord_self, 1);
      }
  }

  /// New nodes at the mean of their placed neighbours, spreading inwards;
  /// placement decides the final positions.
  void place_new_nodes(const std::vector<Hex>& corners) {
    std::map<Id, std::vector<Id>> next;
    for (const auto& c : corners)
      for (const auto& axis : kAxisEdges)
        for (const auto& e : axis) next[c[e[0]]].push_back(c[e[1]]), next[c[e[1]]].push_back(c[e[0]]);
    for (bool progress = true; progress;) {
      progress = false;
      for (const auto& [v, n] : new_nodes_) {
        if (stc_.position(n)) continue;
        Vec3 sum{0, 0, 0};
        int placed = 0;
        for (Id w : next[n])
          if (const Vec3* at = stc_.position(w)) sum = sum + *at, ++placed;
        if (placed == 0) continue;
        stc_.place(n, (1.0 / placed) * sum);
        progress = true;
      }
    }
  }

  Stc& stc_;
  engine::Graph& g_;
  const stc::StcSchema& ids_;
  std::map<std::array<Id, 4>, Id> faces_;
  std::map<std::uint32_t, Id> new_nodes_;
};

}  // namespace

bool closes_from_database(const Stc& stc, Id face, const closure::Database& db) {
  return find_template(stc, face, db).has_value();
}

std::size_t close_from_database(Stc& stc, Id face, const closure::Database& db) {
  auto found = find_template(stc, face, db);
  if (!found)
    throw std::runtime_error(fmt::format(
        "close_from_database: the front component of face {} is not in the database (test it with closes_from_database)",
        face));
  return Inserter(stc).insert(found->first, std::move(found->second));
}

}  // namespace loom::weave
