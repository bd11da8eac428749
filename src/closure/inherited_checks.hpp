#pragma once
// What the expansion of a child front inherits from its parent's: the
// gluings that could be planned at each quad, and what the checks of the
// gluings planned said. A child front differs from its parent only in quads
// and hexes at the corners of the hex glued between them, so whatever was
// read only elsewhere holds as before; the search then plans and checks
// anew only near that hex.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "src/closure/cavity.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/quadmap/hex_glue.hpp"

namespace loom::closure {

/// Which gluings plan_gluing() was asked at each quad of a front and which
/// it planned, by the set of covered sides: bit `sides` asked, bit
/// 16 + `sides` planned. A plan reads the bottom quad, the quads across its
/// sides and the degrees of their corners; none of these changes at a child
/// quad with neither a corner nor an edge neighbour at the hex glued between.
class PlanMasks {
public:
  explicit PlanMasks(std::size_t quads = 0) : masks_(quads, 0) {}

  std::size_t bytes() const { return masks_.capacity() * sizeof(std::uint32_t); }
  bool known(std::uint32_t quad, unsigned sides) const { return masks_[quad] >> sides & 1; }
  bool planned(std::uint32_t quad, unsigned sides) const { return masks_[quad] >> (16 + sides) & 1; }
  void record(std::uint32_t quad, unsigned sides, bool planned) {
    masks_[quad] |= (1u << sides) | (planned ? 1u << (16 + sides) : 0u);
  }

  /// What holds at the child front `child` of the front these masks are of,
  /// made by the gluing `made_by` planned there (nothing, when these masks
  /// are of no expansion).
  PlanMasks for_child(const quadmap::QuadMap& child, const std::vector<quadmap::Dart>& child_twin,
                      const QuadsAtVertex& child_at, const quadmap::GluedHex& made_by) const {
    PlanMasks out(child.size());
    if (masks_.empty()) return out;  // a front rebuilt, not expanded: nothing learnt
    std::array<std::uint32_t, 5> covered = made_by.covered;
    std::sort(covered.begin(), covered.begin() + made_by.k);
    const auto covered_end = covered.cbegin() + made_by.k;
    // after_gluing() keeps the uncovered quads in order, then adds the hex's.
    std::uint32_t from = 0;
    const std::size_t kept = child.size() - static_cast<std::size_t>(6 - made_by.k);
    for (std::uint32_t q = 0; q < kept; ++q, ++from) {
      while (std::find(covered.cbegin(), covered_end, from) != covered_end) ++from;
      out.masks_[q] = masks_[from];
    }
    for (std::uint32_t v : made_by.hex)
      child_at.each(v, [&](std::uint32_t q) {
        out.masks_[q] = 0;
        for (quadmap::Dart d = 4 * q; d < 4 * q + 4; ++d)
          if (child_twin[d] != quadmap::no_dart) out.masks_[child_twin[d] / 4] = 0;
      });
    return out;
  }

private:
  std::vector<std::uint32_t> masks_;
};

/// What the checks of the gluings planned at a front said. A gluing is known
/// by the front quads it covers, and its checks (a proper front afterwards,
/// proper contact with the front, proper meeting with the hexes before it)
/// read only the front quads and the hexes at its hex's corners that are
/// already on the front; its new corners meet nothing in either front. So a
/// child's gluing none of whose corners is a corner of the hex glued between
/// gets the parent's verdict.
class GluingVerdicts {
public:
  enum class Verdict : std::uint8_t { unknown, fits, does_not_fit };

  std::size_t bytes() const { return (fit_.capacity() + unfit_.capacity()) * sizeof(std::uint64_t); }
  /// `covered_hash`: the exclusive or of the covered quads' hashes.
  void record(std::uint64_t covered_hash, bool fits) { (fits ? fit_ : unfit_).push_back(covered_hash); }
  /// Once every verdict is recorded.
  void seal() {
    std::sort(fit_.begin(), fit_.end());
    std::sort(unfit_.begin(), unfit_.end());
  }

  /// What these verdicts say of a gluing with hex `hex` at a child front made by `made_by`.
  Verdict for_child(std::uint64_t covered_hash, const Hex& hex, const Hex& made_by) const {
    for (std::uint32_t v : hex)
      if (std::find(made_by.begin(), made_by.end(), v) != made_by.end()) return Verdict::unknown;
    if (std::binary_search(fit_.begin(), fit_.end(), covered_hash)) return Verdict::fits;
    if (std::binary_search(unfit_.begin(), unfit_.end(), covered_hash)) return Verdict::does_not_fit;
    return Verdict::unknown;
  }

private:
  std::vector<std::uint64_t> fit_, unfit_;
};

}  // namespace loom::closure
