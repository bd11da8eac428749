#pragma once
// Hexes that meet improperly in a closed weave, and the pillow that parts them.
//
// Two hexes meet properly when they share nothing, one node, one edge or one
// face of both, and a face they share is one STC face (criteria 2 and 3 in
// validity.md). Weaves of hard surfaces (Schneiders' pyramid, small random
// quadrangulations) close with hexes whose faces a b c d and a b c e share two
// consecutive edges, or that meet in two nodes no edge joins. A pillow sheet
// round one of the two hexes, or round it and one or two neighbours, splits
// the shared nodes between the two sides; which set to pillow is decided by
// trying them and keeping the one that leaves the fewest improper meetings.
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>

#include "src/mesh/hex_mesh.hpp"
#include "src/stc/stc.hpp"

namespace loom::weave {

/// The corners of `hex` in VTK order; nullopt while it is not complete (a
/// face missing, a whisker face, or a degenerate corner).
std::optional<Hex> complete_hex_corners(const stc::Stc& stc, stc::Id hex);

/// complete_hex_corners of the hexes asked about, each computed once while the
/// STC stays as it is (the cache empties itself when the graph's revision moves).
class HexCornerCache {
public:
  explicit HexCornerCache(const stc::Stc& stc) : stc_(stc) {}
  std::optional<Hex> operator()(stc::Id hex);

private:
  const stc::Stc& stc_;
  std::uint64_t revision_ = 0;
  std::unordered_map<stc::Id, std::optional<Hex>> corners_;
};

/// Whether complete hexes a and b meet properly (see above).
bool stc_hexes_meet_properly(const stc::Stc& stc, stc::Id a, const Hex& at_a, stc::Id b, const Hex& at_b);

/// Two complete hexes at `node` that meet improperly (the first such pair in
/// id order), or nullopt.
std::optional<std::pair<stc::Id, stc::Id>> improper_pair_at(const stc::Stc& stc, stc::Id node, HexCornerCache& corners);

/// Improper meetings (pairs of hexes) that involve at least one of `hexes`.
std::size_t improper_meetings_around(const stc::Stc& stc, std::span<const stc::Id> hexes);

/// The set to pillow, among {h}, {h, n} and {h, n, m} for h = h1, h2 and
/// neighbours n, m of h, after which h1 and h2 meet properly and the fewest
/// improper meetings are left (the first such set on a tie), provided that
/// is fewer than before; nullopt when none is. Tries each and undoes it.
std::optional<std::vector<stc::Id>> best_improper_pillow(stc::Stc& stc, stc::Id h1, stc::Id h2);

/// Pillows the set, among {h}, {h, n} and {h, n, m} for h = h1, h2 and
/// neighbours n, m of h, after which h1 and h2 meet properly and the fewest
/// improper meetings are left (the first such set on a tie), provided that
/// is fewer than before. Returns the number of pillow hexes inserted; 0, and
/// nothing changed, when no candidate lowers the count (so a weave can be
/// pillowed at most as many times as it has improper meetings).
std::size_t pillow_improper_pair(stc::Stc& stc, stc::Id h1, stc::Id h2);

}  // namespace loom::weave
