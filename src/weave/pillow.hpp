#pragma once
// Pillowing: the two non-local operations the degeneracy rules call.
//
// insert_pillow(S) puts a new sheet (a pillow sheet, with no loop on the
// boundary) around a set S of hexes: every face of S's boundary dS gets a new
// hex between it and a shrunken copy of S, as in Mitchell & Tautges,
// "Pillowing doublets" (1995), and in the 1996 progress report's resolution of
// through-cells. The elements of S's closure that lie on dS are copied once
// per local component of S around them, so dS may be pinched (a through-3-cell)
// or meet an edge more than twice (a through-2-cell).
//
// split_pinched_node(x) separates a node whose hexes form several groups that
// share only that node (what a pillowed through-3-cell leaves on the outside):
// one node per group, each at the position of the boundary node it stands for.
#include <span>
#include <string>

#include "src/stc/stc.hpp"

namespace loom::weave {

using stc::Id;
using stc::no_element;

struct PillowCounts {
  std::size_t hexes = 0;  ///< pillow hexes inserted (one per face of dS)
  std::size_t chords = 0; ///< chords of the new sheet
};

/// Inserts a pillow sheet around `shrink_set` (distinct, alive hexes). Throws
/// std::runtime_error, before changing anything, if a face of dS is not
/// between S and its complement exactly once, or if a sector of S around an
/// edge of dS does not end in two faces of dS.
PillowCounts insert_pillow(stc::Stc& stc, std::span<const Id> shrink_set);

/// The shrink set that resolves the doublet of h1 and h2 (two hexes sharing
/// two or more faces): h1 and the hexes across its faces that hold three
/// nodes of the shared faces (their faces there share two edges with h2's);
/// h2's side instead when one of h1's such faces is a boundary quad.
std::vector<Id> doublet_shrink_set(const stc::Stc& stc, Id h1, Id h2);

/// The hexes having `node` as a corner (each once, in id order).
std::vector<Id> hexes_at_node(const stc::Stc& stc, Id node);

/// Splits `node` into one node per group of its hexes (hexes connected
/// through faces at the node); edges at the node used by several groups are
/// copied. A group with a boundary face takes that face's original surface
/// node position and boundary 1; others keep the position, boundary 0.
/// Returns the number of nodes added.
std::size_t split_pinched_node(stc::Stc& stc, Id node);

}  // namespace loom::weave
