#include "src/closure/symmetric_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "src/closure/cavity.hpp"
#include "src/closure/hex_meeting.hpp"
#include "src/quadmap/automorphisms.hpp"
#include "src/quadmap/canonical.hpp"
#include "src/quadmap/hex_glue.hpp"

namespace loom::closure {

using quadmap::Permutation;
using quadmap::QuadMap;

namespace {

/// A quad read from its least corner: equal for the same quad read from any corner.
Quad from_least(const Quad& q) {
  const auto least = static_cast<std::size_t>(std::min_element(q.begin(), q.end()) - q.begin());
  return {q[least], q[(least + 1) % 4], q[(least + 2) % 4], q[(least + 3) % 4]};
}

Quad image(const Quad& q, const Permutation& p) { return {p[q[0]], p[q[1]], p[q[2]], p[q[3]]}; }

bool is_automorphism(const QuadMap& m, const Permutation& p) {
  std::vector<Quad> quads;
  for (const Quad& q : m.quads) quads.push_back(from_least(q));
  std::sort(quads.begin(), quads.end());
  return std::all_of(m.quads.begin(), m.quads.end(), [&](const Quad& q) {
    return std::binary_search(quads.begin(), quads.end(), from_least(image(q, p)));
  });
}

/// Glues `hex` onto the front quads `onto` (read in any rotation), the front
/// gaining `added`; false, leaving `c` as it was, unless every quad is there
/// and the hex meets the front and the hexes as a valid mesh allows.
bool glue_onto(Cavity& c, const Hex& hex, const std::vector<Quad>& onto, const std::vector<Quad>& added) {
  std::vector<std::uint32_t> covered;
  for (const Quad& q : onto) {
    const Quad key = from_least(q);
    const auto it = std::find_if(c.front.quads.begin(), c.front.quads.end(),
                                 [&](const Quad& f) { return from_least(f) == key; });
    if (it == c.front.quads.end()) return false;
    covered.push_back(static_cast<std::uint32_t>(it - c.front.quads.begin()));
  }
  if (!touches_front_properly(hex, c.front, QuadsAtVertex(c.front), covered)) return false;
  std::vector<const Quad*> onto_quads;
  for (const Quad& q : onto) onto_quads.push_back(&q);
  for (const Hex& other : c.hexes)
    if (!meets_as_glued(hex, other, onto_quads)) return false;
  QuadMap front;
  front.vertex_bound = c.front.vertex_bound;
  std::vector<std::int32_t> owner;
  for (std::uint32_t q = 0; q < c.front.size(); ++q)
    if (std::find(covered.begin(), covered.end(), q) == covered.end()) {
      front.quads.push_back(c.front.quads[q]);
      owner.push_back(c.owner[q]);
    }
  for (const Quad& a : added) {
    front.quads.push_back(a);
    owner.push_back(static_cast<std::int32_t>(c.hexes.size()));
  }
  for (std::uint32_t v : hex) front.vertex_bound = std::max(front.vertex_bound, v + 1);
  if (!front.quads.empty() && !quadmap::why_not_proper(front).empty()) return false;
  c.front = std::move(front);
  c.owner = std::move(owner);
  c.hexes.push_back(hex);
  return true;
}

class PairSpace {
public:
  struct State {
    Cavity cavity;         ///< its hexes: the pairs placed
    Permutation symmetry;  ///< of the front, over every vertex the pairs made too
    quadmap::Code code;    ///< the front's, up to mirror images
    /// The hexes of the inner search that closed the front (a goal: all of
    /// them; otherwise they only rank the state).
    std::vector<Hex> rest;
    std::vector<HexSource> rest_source;
    bool inner_closed = false;
    bool closed = false;
  };
  using Key = quadmap::Code;
  using KeyHash = quadmap::CodeHash;

  PairSpace(const Database* db, const SymmetricOptions& options, std::size_t max_front)
      : db_(db), options_(options), max_front_(max_front) {}

  State start(const QuadMap& surface, Permutation symmetry) const {
    State s;
    s.cavity = surface_cavity(surface);
    s.symmetry = std::move(symmetry);
    s.code = quadmap::canonical_unoriented(surface).code;
    return s;
  }

  Key key(const State& s) const { return s.code; }
  double cost(const State& s) const { return static_cast<double>(s.cavity.hexes.size() + (s.closed ? s.rest.size() : 0)); }
  /// The inner search's hexes where it closed the front; after every such
  /// front, those it did not close, smallest front first.
  double estimate(const State& s) const {
    if (s.closed) return 0;
    return s.inner_closed ? static_cast<double>(s.rest.size()) : kNotClosed + s.cavity.front.size() / 4.0;
  }
  /// A hex covers at most six front quads.
  double lower_bound(const State& s) const { return s.closed ? 0.0 : std::ceil(s.cavity.front.size() / 6.0); }
  bool goal(const State& s) const { return s.closed; }

  template <class Emit>
  void expand(const State& s, Emit&& emit) {
    const QuadMap& front = s.cavity.front;
    const auto twin = quadmap::twins(front);
    const auto degree = quadmap::degrees(front);
    quadmap::GluedHex glued;
    for (std::uint32_t q = 0; q < front.size(); ++q)
      for (std::uint8_t sides = 0; sides < 16; ++sides) {
        if (!quadmap::plan_gluing(front, twin, degree, {q, sides}, glued)) continue;
        State next;
        if (!glue_pair(s, glued, next) || next.cavity.front.size() > max_front_) continue;
        if (next.cavity.front.quads.empty()) {
          next.closed = true;
          emit(std::move(next));
          continue;
        }
        next.code = quadmap::canonical_unoriented(next.cavity.front).code;
        if (!reached_.insert(next.code).second) continue;  // reached before, with no more hexes
        ClosureResult inner = close_cavity(next.cavity, db_, options_.each);
        inner_.expanded += inner.stats.expanded;
        inner_.generated += inner.stats.generated;
        inner_.peak_open = std::max(inner_.peak_open, inner.stats.peak_open);
        if (inner.closed) {
          next.inner_closed = true;
          next.rest = std::move(inner.hexes);
          next.rest_source = std::move(inner.source);
          State done = next;
          done.closed = true;
          emit(std::move(done));
        }
        emit(std::move(next));
      }
  }

  /// The inner searches' expansions, states and most open states, summed.
  const engine::SearchStats& inner() const { return inner_; }

private:
  static constexpr double kNotClosed = 1000;

  /// The gluing planned on s's front and its image under s's symmetry.
  bool glue_pair(const State& s, const quadmap::GluedHex& glued, State& out) const {
    const QuadMap& front = s.cavity.front;
    const std::uint32_t bound = front.vertex_bound;
    std::uint32_t made = 0;  // vertices the gluing makes, numbered from bound on
    for (std::uint32_t v : glued.hex)
      if (v >= bound) made = std::max(made, v - bound + 1);
    // The image's new vertices follow the gluing's; the symmetry swaps the two.
    Permutation swap = s.symmetry;
    swap.resize(bound + 2 * made);
    for (std::uint32_t i = 0; i < made; ++i) {
      swap[bound + i] = bound + made + i;
      swap[bound + made + i] = bound + i;
    }
    out.cavity = s.cavity;
    Hex hex = glued.hex;
    std::vector<Quad> onto, added;
    for (int i = 0; i < glued.k; ++i) onto.push_back(front.quads[glued.covered[static_cast<std::size_t>(i)]]);
    for (int i = 0; i < 6 - glued.k; ++i) added.push_back(glued.added[static_cast<std::size_t>(i)]);
    for (int copy = 0; copy < 2; ++copy) {
      if (!glue_onto(out.cavity, hex, onto, added)) return false;
      for (std::uint32_t& v : hex) v = swap[v];
      for (Quad& q : onto) q = image(q, swap);
      for (Quad& q : added) q = image(q, swap);
    }
    out.cavity.front.vertex_bound = bound + 2 * made;
    out.symmetry = std::move(swap);
    return out.cavity.front.quads.empty() || is_automorphism(out.cavity.front, out.symmetry);
  }

  const Database* db_;
  const SymmetricOptions& options_;
  std::size_t max_front_;
  std::unordered_set<quadmap::Code, quadmap::CodeHash> reached_;
  engine::SearchStats inner_;
};

}  // namespace

ClosureResult close_symmetric(const QuadMap& surface, const Database* db, const SymmetricOptions& options) {
  const std::vector<Permutation> group = quadmap::automorphisms(surface);
  std::vector<Permutation> involutions;
  for (const Permutation& p : group)
    if (quadmap::order_of(p) == 2) involutions.push_back(p);
  ClosureResult best;
  best.vertex_bound = surface.vertex_bound;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  const std::size_t max_front = surface.size() + static_cast<std::size_t>(std::max(0, options.max_growth));
  for (const Permutation& symmetry : quadmap::up_to_conjugacy(involutions, group)) {
    PairSpace space(db, options, max_front);
    auto outcome = engine::beam_search(space, space.start(surface, symmetry), options.beam);
    best.stats.expanded += outcome.stats.expanded + space.inner().expanded;
    best.stats.generated += outcome.stats.generated + space.inner().generated;
    best.stats.goals += outcome.stats.goals;
    best.stats.seconds += outcome.stats.seconds;
    best.stats.peak_open = std::max({best.stats.peak_open, outcome.stats.peak_open, space.inner().peak_open});
    if (!outcome.goal) continue;
    const auto& goal = *outcome.goal;
    const std::size_t hexes = goal.cavity.hexes.size() + goal.rest.size();
    if (hexes >= fewest) continue;
    fewest = hexes;
    best.closed = true;
    best.hexes = goal.cavity.hexes;
    best.source.assign(best.hexes.size(), HexSource::searched);
    best.hexes.insert(best.hexes.end(), goal.rest.begin(), goal.rest.end());
    best.source.insert(best.source.end(), goal.rest_source.begin(), goal.rest_source.end());
    best.vertex_bound = surface.vertex_bound;
    for (const Hex& h : best.hexes)
      for (std::uint32_t v : h) best.vertex_bound = std::max(best.vertex_bound, v + 1);
  }
  return best;
}

}  // namespace loom::closure
