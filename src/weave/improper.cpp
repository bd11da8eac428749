#include "src/weave/improper.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <unordered_set>

#include "src/check/hex_topology.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/pillow.hpp"

namespace loom::weave {

std::optional<Hex> complete_hex_corners(const stc::Stc& stc, stc::Id hex) {
  for (unsigned i = 0; i < 6; ++i) {
    stc::Id f = stc.hex_face(hex, i);
    if (f == no_element || stc.is_whisker(f)) return std::nullopt;
  }
  Hex corners;
  for (unsigned k = 0; k < 8; ++k) {
    stc::Id n = stc::corner_node(stc, hex, k);
    if (n == no_element) return std::nullopt;
    corners[k] = static_cast<std::uint32_t>(n);
  }
  return corners;
}

bool stc_hexes_meet_properly(const stc::Stc& stc, stc::Id a, const Hex& at_a, stc::Id b, const Hex& at_b) {
  if (!hexes_meet_properly(at_a, at_b)) return false;
  int shared = 0;
  for (auto n : at_a) shared += std::find(at_b.begin(), at_b.end(), n) != at_b.end();
  if (shared != 4) return true;
  // Four nodes that are a face of both must be one face, not two faces on
  // the same nodes (which criterion 2 would see as a face of three or four hexes).
  for (unsigned i = 0; i < 6; ++i)
    if (stc.across(stc.hex_face(a, i), a) == b) return true;
  return false;
}

std::optional<Hex> HexCornerCache::operator()(stc::Id hex) {
  if (revision_ != stc_.graph().revision()) {
    revision_ = stc_.graph().revision();
    corners_.clear();
  }
  auto it = corners_.find(hex);
  if (it == corners_.end()) it = corners_.emplace(hex, complete_hex_corners(stc_, hex)).first;
  return it->second;
}

std::optional<std::pair<stc::Id, stc::Id>> improper_pair_at(const stc::Stc& stc, stc::Id node, HexCornerCache& corners) {
  auto hexes = hexes_at_node(stc, node);
  for (std::size_t i = 0; i < hexes.size(); ++i) {
    const auto a = corners(hexes[i]);
    if (!a) continue;
    for (std::size_t j = i + 1; j < hexes.size(); ++j) {
      const auto b = corners(hexes[j]);
      if (b && !stc_hexes_meet_properly(stc, hexes[i], *a, hexes[j], *b)) return std::pair{hexes[i], hexes[j]};
    }
  }
  return std::nullopt;
}

std::size_t improper_meetings_around(const stc::Stc& stc, std::span<const stc::Id> hexes) {
  HexCornerCache corners(stc);
  std::unordered_set<stc::Id> in_set(hexes.begin(), hexes.end());
  std::size_t count = 0;
  for (stc::Id a : hexes) {
    const auto at_a = corners(a);
    if (!at_a) continue;
    std::vector<stc::Id> met;
    for (auto n : *at_a)
      for (stc::Id b : hexes_at_node(stc, n))
        if (b != a && !(in_set.count(b) && b < a)) met.push_back(b);
    std::sort(met.begin(), met.end());
    met.erase(std::unique(met.begin(), met.end()), met.end());
    for (stc::Id b : met)
      if (const auto at_b = corners(b); at_b && !stc_hexes_meet_properly(stc, a, *at_a, b, *at_b)) ++count;
  }
  return count;
}

namespace {

/// {h}, {h, n} and {h, n, m} for neighbours n, m of h (across its faces),
/// for h = h1 then h2, each set once.
std::vector<std::vector<stc::Id>> candidate_sets(const stc::Stc& stc, stc::Id h1, stc::Id h2) {
  std::vector<std::vector<stc::Id>> sets;
  auto add = [&](std::vector<stc::Id> s) {
    std::sort(s.begin(), s.end());
    if (std::find(sets.begin(), sets.end(), s) == sets.end()) sets.push_back(std::move(s));
  };
  for (stc::Id h : {h1, h2}) {
    add({h});
    std::vector<stc::Id> nb;
    for (unsigned i = 0; i < 6; ++i)
      if (stc::Id n = stc.across(stc.hex_face(h, i), h); n != no_element && n != h) {
        add({h, n});
        nb.push_back(n);
      }
    for (std::size_t i = 0; i < nb.size(); ++i)
      for (std::size_t j = i + 1; j < nb.size(); ++j)
        if (nb[i] != nb[j]) add({h, nb[i], nb[j]});
  }
  return sets;
}

/// Improper meetings near `set` after pillowing it, or nullopt when it cannot
/// be pillowed or h1 and h2 still meet improperly; the STC is left as it was.
std::optional<std::size_t> try_pillow(stc::Stc& stc, std::span<const stc::Id> set, stc::Id h1, stc::Id h2) {
  auto& g = stc.graph();
  const auto points = stc.points().size();
  const stc::Id first_new = g.id_bound();
  const auto mark = g.checkpoint();
  std::optional<std::size_t> left;
  try {
    insert_pillow(stc, set);
    std::vector<stc::Id> near(set.begin(), set.end());
    for (stc::Id e = first_new; e < g.id_bound(); ++e)
      if (g.alive(e) && g.kind(e) == stc.ids().hex) near.push_back(e);
    HexCornerCache corners(stc);
    const auto a = corners(h1);
    const auto b = corners(h2);
    if (a && b && stc_hexes_meet_properly(stc, h1, *a, h2, *b)) left = improper_meetings_around(stc, near);
  } catch (const std::runtime_error&) {
    // Not a pillowable set (see insert_pillow): not a candidate.
  }
  g.rollback(mark);
  g.release(mark);
  stc.points().resize(points);
  return left;
}

}  // namespace

std::optional<std::vector<stc::Id>> best_improper_pillow(stc::Stc& stc, stc::Id h1, stc::Id h2) {
  std::vector<stc::Id> best;
  std::ptrdiff_t best_change = std::numeric_limits<std::ptrdiff_t>::max();
  for (const auto& set : candidate_sets(stc, h1, h2)) {
    const auto before = static_cast<std::ptrdiff_t>(improper_meetings_around(stc, set));
    auto after = try_pillow(stc, set, h1, h2);
    if (!after) continue;
    const auto change = static_cast<std::ptrdiff_t>(*after) - before;
    if (change < best_change) best_change = change, best = set;
  }
  if (best.empty() || best_change >= 0) return std::nullopt;
  return best;
}

std::size_t pillow_improper_pair(stc::Stc& stc, stc::Id h1, stc::Id h2) {
  const auto best = best_improper_pillow(stc, h1, h2);
  return best ? insert_pillow(stc, *best).hexes : 0;
}

}  // namespace loom::weave
