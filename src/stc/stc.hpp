#pragma once
// Stc: the Spatial Twist Continuum as a typed incidence graph.
//
// Element kinds and ports (the schema every rule file is written against):
//   hex   (STC vertex)  face[6]  -> face   ordered: 0/1, 2/3, 4/5 are opposite
//   face  (STC edge)    edge[4]  -> edge   cyclic; edge[i] joins node[i], node[i+1]
//                       node[4]  -> node   cyclic
//                       cell[2]  -> hex    cell[0]: the hex the face's node cycle
//                                          faces away from; cell[1]: the other side
//                       chord[1] -> chord
//   edge  (STC 2-cell)  node[2]  -> node
//                       sheet[1] -> sheet
//   node  (STC 3-cell)  (none)
//   chord               sheet[2] -> sheet  the two sheets it lies on (equal when
//                                          the chord lies twice on one sheet)
//   sheet               (none)
// Attributes: face.boundary (index of the boundary quad it is, or -1),
// face.layer (0 on the boundary; a face made by a weave is one layer deeper
// than the faces it was made from), node.point (index into points(), or -1
// while unplaced), node.boundary (1 on the boundary surface; the number of
// surface nodes it stands for once seam_through has merged some), hex.source (index
// in the hex mesh it was built from, -1 when a rule made it, or
// kHexFromDatabase), sheet.self (1 if
// self-intersecting), chord.self (1 if it passes a hex twice or lies twice on
// one sheet).
//
// Hex face order, for a hex built from VTK nodes 0..7: face 0 = 0123, 1 = 4567,
// 2 = 0154, 3 = 3267, 4 = 0374, 5 = 1265. Node k of the hex is the node common
// to faces corner_faces[k] (see primal.hpp).
//
// A face with an empty cell slot on a boundary side is a boundary face; an
// empty slot on the inner side is a whisker: the chord still dangles there.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph.hpp"
#include "src/mesh/vec3.hpp"

namespace loom::stc {

using engine::Id;
using engine::no_element;

/// hex.source of a hex put in from the closure database, not woven
/// (weave/database_closure.hpp).
inline constexpr std::int32_t kHexFromDatabase = -2;

/// Ids of the STC schema's kinds, ports and attributes.
struct StcSchema {
  engine::KindId hex, face, edge, node, chord, sheet;
  engine::PortId hex_face, face_edge, face_node, face_cell, face_chord, edge_node, edge_sheet, chord_sheet;
  engine::AttrId face_boundary, face_layer, node_point, node_boundary, hex_source, sheet_self, chord_self;
  std::shared_ptr<const engine::Schema> schema;
  /// The one schema shared by every Stc.
  static const StcSchema& get();
};

/// Whether Stc::debug_check() checks: always in Debug builds (no NDEBUG),
/// otherwise when the environment variable LOOM_CHECK_INVARIANTS is set and
/// not "0" (ctest sets it). Read once per process.
bool invariant_checks_on();

class Stc {
public:
  Stc();

  engine::Graph& graph() { return graph_; }
  const engine::Graph& graph() const { return graph_; }
  const StcSchema& ids() const { return *ids_; }

  /// Coordinates of mesh nodes, indexed by node.point.
  std::vector<Vec3>& points() { return points_; }
  const std::vector<Vec3>& points() const { return points_; }
  /// The position of a node, or nullptr while it has none (node.point -1).
  const Vec3* position(Id node) const {
    const std::int32_t p = graph_.get(node, ids_->node_point);
    return p < 0 ? nullptr : &points_[static_cast<std::size_t>(p)];
  }
  /// Gives `node` a new point at `at`.
  void place(Id node, const Vec3& at) {
    graph_.set(node, ids_->node_point, static_cast<std::int32_t>(points_.size()));
    points_.push_back(at);
  }
  /// For each boundary quad (face.boundary), the point of each of its four
  /// nodes as built, in the face's node order: what a node split after a
  /// through-cell needs to know which surface node a boundary face stands on.
  std::vector<std::array<std::int32_t, 4>>& boundary_points() { return boundary_points_; }
  const std::vector<std::array<std::int32_t, 4>>& boundary_points() const { return boundary_points_; }

  // --- navigation (all O(1)) ---------------------------------------------
  Id hex_face(Id hex, unsigned i) const { return graph_.at(hex, ids_->hex_face, i); }
  Id face_edge(Id face, unsigned i) const { return graph_.at(face, ids_->face_edge, i & 3u); }
  Id face_node(Id face, unsigned i) const { return graph_.at(face, ids_->face_node, i & 3u); }
  Id face_cell(Id face, unsigned side) const { return graph_.at(face, ids_->face_cell, side); }
  Id face_chord(Id face) const { return graph_.at(face, ids_->face_chord); }
  Id edge_node(Id edge, unsigned i) const { return graph_.at(edge, ids_->edge_node, i); }
  Id edge_sheet(Id edge) const { return graph_.at(edge, ids_->edge_sheet); }
  Id chord_sheet(Id chord, unsigned i) const { return graph_.at(chord, ids_->chord_sheet, i); }
  /// The face opposite slot i of a hex (i ^ 1).
  Id opposite_face(Id hex, unsigned i) const { return hex_face(hex, i ^ 1u); }
  /// The hex on the other side of `face` from `hex` (no_element if none).
  Id across(Id face, Id hex) const;
  /// The slot of `face` in `hex`, or 6 if absent.
  unsigned slot_in_hex(Id hex, Id face) const;
  /// The position of `edge` in `face`'s cycle, or 4 if absent.
  unsigned slot_in_face(Id face, Id edge) const;
  /// Within `hex`, the face other than `face` that contains `edge`: the next
  /// face around the edge inside that hex. no_element if none.
  Id face_across_edge(Id hex, Id face, Id edge) const;
  /// The sheet that separates faces 2*axis and 2*axis+1 of `hex` (the sheet of
  /// the four edges joining them); no_element if the hex is degenerate there.
  Id hex_sheet(Id hex, unsigned axis) const;
  int boundary_index(Id face) const { return graph_.get(face, ids_->face_boundary); }
  bool is_boundary(Id face) const { return boundary_index(face) >= 0; }

  // --- counts --------------------------------------------------------------
  std::size_t hexes() const { return graph_.size(ids_->hex); }
  std::size_t faces() const { return graph_.size(ids_->face); }
  std::size_t edges() const { return graph_.size(ids_->edge); }
  std::size_t nodes() const { return graph_.size(ids_->node); }
  std::size_t sheets() const { return graph_.size(ids_->sheet); }
  std::size_t chords() const { return graph_.size(ids_->chord); }
  /// A whisker: a face with an open side that must still get a hex (a boundary
  /// face without its hex, or an inner face with one hex).
  bool is_whisker(Id face) const;
  std::size_t whiskers() const;

  // --- invariants ------------------------------------------------------------
  /// Checks the STC invariants (see invariants.cpp for the list); returns the
  /// first violation, or an empty string.
  std::string check_invariants() const;
  /// When invariant_checks_on(), throws std::logic_error on a violation;
  /// otherwise does nothing. Called after every mutation.
  void debug_check() const;

private:
  const StcSchema* ids_;
  engine::Graph graph_;
  std::vector<Vec3> points_;
  std::vector<std::array<std::int32_t, 4>> boundary_points_;
};

}  // namespace loom::stc
