#pragma once
// A combinatorial quadrangulation of the sphere that stays simple (no repeated
// node in a quad, no two edges between the same nodes) with every node of
// degree >= 3, changed by local moves: hex flips (a hex glued onto k connected
// quads replaces them with its 6-k other faces, literature.md §4.3) for k = 1,
// 2, 3 and diagonal slides. Used by gen::randquad to walk at random through
// such quadrangulations. A refused move changes nothing.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::gen {

class SphereQuadrangulation {
 public:
  /// The pseudo-double wheel with `faces` quads (even, >= 6): a cycle of
  /// `faces` nodes and two hubs, one joined to the even cycle nodes and one
  /// to the odd ones. Every cycle node has degree 3, each hub faces/2; for 6
  /// quads it is the cube. Quads are counter-clockwise seen from outside.
  explicit SphereQuadrangulation(int faces);

  /// Hex flip with k = 1: the quad is replaced by a smaller copy of itself and
  /// four quads joining the two (4 new nodes of degree 3, +4 quads). Always
  /// allowed. Side (a, b) of the old quad stays in index `quad`, so
  /// hex_flip_2(quad, 0) is allowed right after it.
  void hex_flip_1(std::size_t quad);

  /// Hex flip with k = 2: `quad` and its neighbour across edge `side` (corners
  /// side, side+1) are replaced by the four other faces of the hex glued onto
  /// them (2 new nodes of degree 3, +2 quads). The shared edge disappears, so
  /// it is refused if an end of it would drop below degree 3.
  bool hex_flip_2(std::size_t quad, int side);

  /// Diagonal slide: quad `quad` and its neighbour across its edge `side`
  /// (corners side, side+1) form a hexagon; the shared edge is replaced by one
  /// of the hexagon's two other long diagonals (`which` 0 or 1). Refused (false,
  /// nothing changed) if an end of the old edge would drop below degree 3 or
  /// the new diagonal is already an edge.
  bool diagonal_slide(std::size_t quad, int side, int which);

  /// Hex flip with k = 3 (literature.md §4.3): if corner `corner` of `quad` has
  /// degree 3, its three quads are replaced by the three opposite faces of a hex
  /// glued onto them (the node moves to the hex's far corner). Refused if a
  /// neighbour of the node would drop below degree 3 or the three quads'
  /// far corners are not distinct.
  bool hex_flip_3(std::size_t quad, int corner);

  const std::vector<Quad>& quads() const { return quads_; }
  std::size_t node_count() const { return degree_.size(); }

 private:
  static std::uint64_t key(std::uint32_t from, std::uint32_t to) { return std::uint64_t(from) << 32 | to; }
  bool has_edge(std::uint32_t a, std::uint32_t b) const { return quad_left_of_.contains(key(a, b)); }
  /// The quad that runs from `from` to `to`.
  std::uint32_t quad_along(std::uint32_t from, std::uint32_t to) const { return quad_left_of_.at(key(from, to)); }
  void set_quad(std::uint32_t index, const Quad& quad);
  std::uint32_t add_quad(const Quad& quad);
  std::uint32_t add_node(int degree);
  /// The hexagon of `quad` and its neighbour across edge `side`, counter-
  /// clockwise, starting with the ends u, v of the shared edge at h[0] and h[3];
  /// also the neighbour's index.
  std::array<std::uint32_t, 6> hexagon(std::size_t quad, int side, std::uint32_t& neighbour) const;
  void unlink_quad(std::uint32_t index);

  std::vector<Quad> quads_;
  std::vector<int> degree_;
  std::unordered_map<std::uint64_t, std::uint32_t> quad_left_of_;  ///< directed edge -> the quad running along it
};

}  // namespace loom::gen
