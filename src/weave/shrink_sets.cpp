// The shrink sets the pillow rules use: see pillow.hpp.
#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "src/weave/pillow.hpp"
#include "src/weave/pillow_detail.hpp"

namespace loom::weave {

using namespace detail;

namespace {

/// h and the hexes across its faces that touch more than two nodes of the
/// faces it shares with `other`; `complete` is false when such a face is a
/// boundary face (nothing across it to take in).
std::vector<Id> doublet_side(const Stc& stc, Id h, Id other, bool& complete) {
  std::vector<Id> shared, shared_nodes, set{h};
  for (unsigned i = 0; i < 6; ++i)
    if (stc.across(stc.hex_face(h, i), h) == other) shared.push_back(stc.hex_face(h, i));
  for (Id f : shared)
    for (unsigned k = 0; k < 4; ++k) shared_nodes.push_back(stc.face_node(f, k));
  complete = true;
  for (unsigned i = 0; i < 6; ++i) {
    Id f = stc.hex_face(h, i);
    if (std::find(shared.begin(), shared.end(), f) != shared.end()) continue;
    int touching = 0;
    for (unsigned k = 0; k < 4; ++k)
      touching += std::find(shared_nodes.begin(), shared_nodes.end(), stc.face_node(f, k)) != shared_nodes.end();
    // A face meeting the shared ones in an edge is fine; one holding three of
    // their nodes shares two edges with `other`'s faces there.
    if (touching <= 2) continue;
    Id across = stc.across(f, h);
    if (across == no_element) complete = false;
    else if (across != other && std::find(set.begin(), set.end(), across) == set.end()) set.push_back(across);
  }
  return set;
}

}  // namespace

std::vector<Id> doublet_shrink_set(const Stc& stc, Id h1, Id h2) {
  // The pillow must also pass between the faces at the doublet's ends that
  // share two edges, so the hexes beyond h1's end faces go in the set; where
  // such a face is a boundary quad there is nothing beyond it, and the other
  // hex's side is taken instead.
  bool complete1 = false, complete2 = false;
  auto first = doublet_side(stc, h1, h2, complete1);
  if (complete1) return first;
  auto second = doublet_side(stc, h2, h1, complete2);
  return complete2 ? second : first;
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

}  // namespace loom::weave
