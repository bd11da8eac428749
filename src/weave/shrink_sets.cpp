// The shrink sets the pillow rules use: see pillow.hpp.
#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "src/weave/pillow.hpp"
#include "src/weave/pillow_detail.hpp"

namespace loom::weave {

using namespace detail;

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

}  // namespace loom::weave
