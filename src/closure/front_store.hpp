#pragma once
// The fronts of the states a search expanded, kept for the expansions of
// their children, within a memory budget. Each front is a copy of a whole
// cavity boundary, and a search of a large cavity expands a hundred thousand:
// kept all, they took the flange's closure past 18 GB. Beyond the budget the
// oldest fronts are dropped (the search goes on mostly from recent ones), and
// one asked for again is rebuilt from the nearest kept ancestor by replaying
// the gluings that made it, without what its expansion had learnt
// (inherited_checks.hpp), which a child then works out anew. Results do not
// depend on the budget.
//
// Front: movable, with std::size_t bytes() const.
// Made: how a front was made, with std::int32_t parent (the index of the
// front it was glued from, -1 for the start).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

namespace loom::closure {

template <class Front, class Made>
class FrontStore {
public:
  explicit FrontStore(std::size_t budget_bytes) : budget_(budget_bytes) {}

  std::int32_t size() const { return static_cast<std::int32_t>(made_.size()); }

  std::int32_t add(const Made& made, Front front) {
    made_.push_back(made);
    fronts_.emplace_back();
    keep(size() - 1, std::move(front));
    return size() - 1;
  }

  /// The front at `index`; `rebuild(const Front* parent, const Made&)` makes
  /// a dropped one again (parent null for the start).
  template <class Rebuild>
  Front& at(std::int32_t index, Rebuild&& rebuild) {
    std::vector<std::int32_t> missing;
    for (std::int32_t i = index; i >= 0 && !fronts_[static_cast<std::size_t>(i)].front;
         i = made_[static_cast<std::size_t>(i)].parent)
      missing.push_back(i);
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      const Made& m = made_[static_cast<std::size_t>(*it)];
      const Front* parent = m.parent >= 0 ? fronts_[static_cast<std::size_t>(m.parent)].front.get() : nullptr;
      keep(*it, rebuild(parent, m));
    }
    return *fronts_[static_cast<std::size_t>(index)].front;
  }

  /// Counts the front at `index` again, after it grew.
  void recount(std::int32_t index) {
    Kept& k = fronts_[static_cast<std::size_t>(index)];
    if (!k.front) return;
    bytes_ -= k.bytes;
    k.bytes = k.front->bytes();
    bytes_ += k.bytes;
  }

  /// Drops the oldest fronts while the kept ones exceed the budget. Call it
  /// only while no reference into the store is held.
  void keep_to_budget() {
    while (bytes_ > budget_ && kept_.size() > 1) {
      const auto [oldest, ticket] = kept_.front();
      kept_.pop_front();
      Kept& k = fronts_[static_cast<std::size_t>(oldest)];
      if (!k.front || k.ticket != ticket) continue;  // dropped already, or kept again since
      bytes_ -= k.bytes;
      k.front.reset();
    }
  }

private:
  void keep(std::int32_t index, Front front) {
    Kept& k = fronts_[static_cast<std::size_t>(index)];
    k.front = std::make_unique<Front>(std::move(front));
    k.bytes = k.front->bytes();
    bytes_ += k.bytes;
    k.ticket = ++tickets_;
    kept_.emplace_back(index, k.ticket);
  }

  std::size_t budget_, bytes_ = 0;
  std::vector<Made> made_;
  struct Kept {
    std::unique_ptr<Front> front;  ///< null when dropped
    std::size_t bytes = 0;         ///< as counted into bytes_
    std::uint64_t ticket = 0;      ///< of its latest entry in kept_
  };
  std::vector<Kept> fronts_;
  std::deque<std::pair<std::int32_t, std::uint64_t>> kept_;  ///< (index, ticket) in the order kept, oldest first
  std::uint64_t tickets_ = 0;
};

}  // namespace loom::closure
