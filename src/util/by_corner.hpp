#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace loom {

/// Items (quads, hexes, darts) listed under each of their corners. Built by
/// counting, not sorting: a search makes some at every expansion. It holds a
/// slot per corner id up to the largest, so it is meant for dense ids.
template <class Id>
class ByCorner {
public:
  /// Item i has the corners corners_of(i) and is listed as id_of(i).
  template <class CornersOf, class IdOf>
  ByCorner(std::size_t items, CornersOf&& corners_of, IdOf&& id_of) {
    std::uint32_t bound = 0;
    std::size_t entries = 0;
    for (std::size_t i = 0; i < items; ++i)
      for (std::uint32_t v : corners_of(i)) bound = std::max(bound, v + 1), ++entries;
    first_.assign(bound + 1, 0);
    for (std::size_t i = 0; i < items; ++i)
      for (std::uint32_t v : corners_of(i)) ++first_[v + 1];
    for (std::uint32_t v = 0; v < bound; ++v) first_[v + 1] += first_[v];
    ids_.resize(entries);
    std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t i = 0; i < items; ++i)
      for (std::uint32_t v : corners_of(i)) ids_[next[v]++] = id_of(i);
  }
  /// Calls f(id) for each item with `v` as a corner, in the order of the items.
  template <class F>
  void each(std::uint32_t v, F&& f) const {
    if (v + 1 >= first_.size()) return;
    for (std::uint32_t i = first_[v]; i < first_[v + 1]; ++i) f(ids_[i]);
  }

private:
  std::vector<std::uint32_t> first_;  ///< per vertex, where its items begin in ids_ (one past the end too)
  std::vector<Id> ids_;
};

}  // namespace loom
