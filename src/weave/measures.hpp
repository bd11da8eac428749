#pragma once
// The geometric measures rules may use in any expression (`if`, `where`,
// `order`; docs/rules.md#measures): integers computed from the positions of
// the nodes a match binds, so that a rule can ask where the front is before
// it changes it. The arguments are nodes, or faces where named f and g; a
// node without a position is an error naming it.
//
//   corner_sj(v, a, b, c)             thousandths  scaled Jacobian of the hex corner at v
//                                                  with edges to a, b, c (right-handed > 0)
//   hex_sj(v, a, b, c, ab, bc, ca)    thousandths  scaled Jacobian (least corner) of the hex
//                                                  with corner v, its edges to a, b, c, face
//                                                  corners ab, bc, ca and its far corner at
//                                                  a + b + c - 2v (where place_hex_corner puts it)
//   angle(a, v, b)                    degrees      the angle at v between v-a and v-b
//   dihedral(a, b, c, d)              degrees      the angle of the unmeshed region at the front
//                                                  edge a-b, between the front face that runs
//                                                  a -> b -> c and the one that runs b -> a -> d
//                                                  (90 at a box's edge, 180 flat, 270 reflex)
//   gap(u, a, b)                      thousandths  |a - b| over the mean of |a - u| and |b - u|
//                                                  (0 when a and b coincide)
//   facing(f, g)                      degrees      the angle between f's normal and the reverse of
//                                                  g's (normals point away from the unmeshed region,
//                                                  as a front face's node cycle runs): 0 when two
//                                                  front faces squarely face each other
//   distance(f, g)                    thousandths  between the faces' centroids, over their mean
//                                                  edge length (1000: one hex layer apart)
// Values are rounded to the nearest integer, so equal positions give equal
// values on every machine that computes IEEE doubles alike.
#include "engine/rewriter.hpp"
#include "src/stc/stc.hpp"

namespace loom::weave {

/// Registers the measures above on `actions`, reading positions from `stc`.
void add_geometric_measures(engine::Actions& actions, const stc::Stc& stc);

/// The hexes of `stc` whose eight corners are placed and whose scaled
/// Jacobian there is <= 0: the weave's `inverted`, a strategy's cost
/// (docs/strategies.md). It visits every hex.
std::int64_t inverted_hexes(const stc::Stc& stc);

/// How far the interior edges of `stc` are from valence 4: |hexes round it -
/// 4| summed over the edges every face round which is closed on both sides,
/// plus the hexes over 4 round each edge still on the front (they can only
/// gain more). Boundary edges are left out. The weave's `irregular`, a
/// strategy's cost; it visits every edge.
std::int64_t irregular_edges(const stc::Stc& stc);

}  // namespace loom::weave
