#include "src/closure/shelling_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "src/closure/front_key.hpp"
#include "src/closure/front_store.hpp"
#include "src/closure/hex_meeting.hpp"
#include "src/closure/inherited_checks.hpp"
#include "src/closure/irregularity.hpp"
#include "src/quadmap/canonical.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/util/bits.hpp"
#include "src/util/stopwatch.hpp"

namespace loom::closure {

using quadmap::QuadMap;

namespace {

class ShellSpace {
public:
  /// What the search keeps open: how to rebuild the front, not the front.
  struct State {
    std::uint64_t key = 0;
    std::int32_t parent = -1;  ///< the expanded state it comes from (-1: the start)
    quadmap::Gluing gluing{};  ///< the gluing made there
    std::int32_t last = -1;    ///< arena index of the newest hex placed
    int hexes = 0;
    float irregularity = 0;  ///< of the hexes placed so far (shelling_search.hpp)
    std::uint32_t front_quads = 0;
    bool closed = false;
  };
  /// Fronts up to canonical_limit quads are also merged up to isomorphism,
  /// when expanded, and looked up in the database.
  using Key = std::uint64_t;
  struct KeyHash {
    std::size_t operator()(std::uint64_t k) const noexcept { return static_cast<std::size_t>(k); }
  };

  struct Placed {
    Hex hex;
    std::int32_t parent;
    HexSource source;
  };

  /// A state rebuilt: its front, whose hex is behind each front quad (cavity
  /// hex h -> h; placed hex a -> cavity size + a), and the placed hexes with
  /// a corner on the front (the only ones a new hex can touch).
  struct Front {
    QuadMap front;
    std::vector<std::int32_t> owner;
    std::vector<std::int32_t> near;
    std::vector<quadmap::Dart> twin;
    std::vector<int> degree;
    quadmap::GluedHex made_by;  ///< the gluing that made it from its parent's front (none at the start)
    PlanMasks plans;            ///< of the gluings tried when it was expanded
    GluingVerdicts verdicts;

    std::size_t bytes() const {
      return sizeof(Front) + front.quads.capacity() * sizeof(Quad) +
             (owner.capacity() + near.capacity() + twin.capacity() + degree.capacity()) * 4 + plans.bytes() +
             verdicts.bytes();
    }
  };

  ShellSpace(const Cavity& cavity, const Database* db, std::size_t max_front, double irregularity_weight,
             std::size_t front_bytes)
      : cavity_(cavity), context_(cavity.hexes), db_(db), max_front_(max_front), fronts_(front_bytes),
        weight_(irregularity_weight) {}

  State start() const {
    State s;
    for (const Quad& q : cavity_.front.quads) s.key ^= quad_hash(q);
    s.front_quads = static_cast<std::uint32_t>(cavity_.front.size());
    s.closed = cavity_.front.quads.empty();
    return s;
  }

  Key key(const State& s) const { return s.closed ? 0 : s.key; }
  double cost(const State& s) const { return s.hexes + weight_ * s.irregularity; }
  double estimate(const State& s) const { return s.closed ? 0.0 : s.front_quads / 4.0; }
  /// Every front quad needs a hex, and a hex covers at most six.
  double lower_bound(const State& s) const { return s.closed ? 0.0 : std::ceil(s.front_quads / 6.0); }
  bool goal(const State& s) const { return s.closed; }

  template <class Emit>
  void expand(const State& s, Emit&& emit) {
    Stopwatch clock;
    fronts_.keep_to_budget();
    const Made made{s.parent, s.gluing, s.last};
    const Front* parent = s.parent >= 0 ? &front_of(s.parent) : nullptr;
    const auto index = fronts_.add(made, rebuild(parent, made));
    Front& f = front_of(index);
    profile_.rebuild += clock.lap();
    if (f.front.size() <= canonical_limit) {
      const auto canon = quadmap::canonical_unoriented(f.front, f.twin);
      profile_.canonical += clock.lap();
      auto [it, fresh] = expanded_codes_.try_emplace(quadmap::CodeHash{}(canon.code), cost(s));
      if (!fresh && it->second <= cost(s)) return;  // an isomorphic front was expanded no dearer
      it->second = cost(s);
      close_from_database(s, f, canon, emit);
    }
    close_cube(s, f, emit);
    profile_.database += clock.lap();
    const QuadsAtVertex at(f.front);
    const NearAtVertex near_at(f.near, arena_);
    std::unordered_set<std::uint64_t> tried;
    quadmap::GluedHex glued;
    std::vector<std::uint32_t> covered;
    // On a large front, gluings that grow it (k = 1, 2) are tried only when
    // no other applies: there are hundreds of them, they are rarely the way,
    // and generating them all would be most of the work.
    const int least_k = f.front.size() > kLargeFront ? 3 : 1;
    std::size_t emitted = 0;
    const PlanMasks known_plans =
        parent ? parent->plans.for_child(f.front, f.twin, at, f.made_by) : PlanMasks(f.front.size());
    PlanMasks plans(f.front.size());
    GluingVerdicts verdicts;
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1 && (least_k == 1 || emitted > 0)) break;
      const int pass_least_k = pass == 0 ? least_k : 1;
      for (std::uint32_t q = 0; q < f.front.size(); ++q)
        for (std::uint8_t sides = 0; sides < 16; ++sides) {
          if (bits_set(sides) + 1 < pass_least_k) continue;
          if (known_plans.known(q, sides) && !known_plans.planned(q, sides)) {
            plans.record(q, sides, false);
            continue;
          }
          const bool planned = quadmap::plan_gluing(f.front, f.twin, f.degree, {q, sides}, glued);
          plans.record(q, sides, planned);
          if (!planned) continue;
          if (pass == 1 && glued.k >= least_k) continue;  // tried in the first pass
          const std::uint32_t quads = s.front_quads + 6 - 2 * static_cast<std::uint32_t>(glued.k);
          if (quads > max_front_) continue;
          covered.assign(glued.covered.begin(), glued.covered.begin() + glued.k);
          std::uint64_t key = s.key;
          for (std::uint32_t c : covered) key ^= quad_hash(f.front.quads[c]);
          if (!tried.insert(key).second) continue;  // the same hex from another bottom
          const auto known = parent ? parent->verdicts.for_child(key ^ s.key, glued.hex, f.made_by.hex)
                                    : GluingVerdicts::Verdict::unknown;
          const bool ok = known != GluingVerdicts::Verdict::unknown
                              ? known == GluingVerdicts::Verdict::fits
                              : glued_front_is_proper(f.front, at, glued) &&
                                    touches_front_properly(glued.hex, f.front, at, covered) &&
                                    fits(glued.hex, f, near_at, covered);
          verdicts.record(key ^ s.key, ok);
          if (!ok) continue;
          for (int a = 0; a < 6 - glued.k; ++a) key ^= quad_hash(glued.added[static_cast<std::size_t>(a)]);
          State next;
          next.key = key;
          next.parent = index;
          next.gluing = {q, sides};
          next.last = place(glued.hex, s.last, HexSource::searched);
          next.hexes = s.hexes + 1;
          next.irregularity = s.irregularity + gluing_cost(glued, f, at, near_at, covered);
          next.front_quads = quads;
          emit(std::move(next));
          ++emitted;
        }
    }
    verdicts.seal();
    f.plans = std::move(plans);
    f.verdicts = std::move(verdicts);
    fronts_.recount(index);
    profile_.gluing += clock.lap();
  }

  const SearchProfile& profile() const { return profile_; }

  /// How an expanded state's front was made.
  struct Made {
    std::int32_t parent;
    quadmap::Gluing gluing;
    std::int32_t last;
  };

  /// The front of an expanded state, rebuilt if it was dropped.
  Front& front_of(std::int32_t index) {
    return fronts_.at(index, [this](const Front* parent, const Made& m) { return rebuild(parent, m); });
  }

  /// The front of a state: the start, or one a gluing from `parent`, an
  /// expanded state's front, reaches.
  Front rebuild(const Front* parent, const Made& s) const {
    if (!parent) {
      Front f;
      f.front = cavity_.front;
      f.owner = cavity_.owner;
      f.twin = quadmap::twins(f.front);
      f.degree = quadmap::degrees(f.front);
      return f;
    }
    const Front& p = *parent;
    Front f;
    quadmap::GluedHex& glued = f.made_by;
    quadmap::plan_gluing(p.front, p.twin, p.degree, s.gluing, glued);
    f.front = quadmap::after_gluing(p.front, glued);
    f.twin = quadmap::twins_after_gluing(p.front, p.twin, glued);
    f.degree = quadmap::degrees_after_gluing(p.front, p.degree, glued);
    const auto covered_end = glued.covered.cbegin() + glued.k;
    for (std::uint32_t o = 0; o < p.front.size(); ++o)
      if (std::find(glued.covered.cbegin(), covered_end, o) == covered_end) f.owner.push_back(p.owner[o]);
    f.owner.resize(f.front.size(), id_of_placed(s.last));
    for (std::int32_t a : p.near)
      if (std::any_of(arena_[static_cast<std::size_t>(a)].hex.begin(), arena_[static_cast<std::size_t>(a)].hex.end(),
                      [&](std::uint32_t v) { return f.degree[v] > 0; }))
        f.near.push_back(a);
    f.near.push_back(s.last);
    return f;
  }

  /// The front a state generated (not necessarily expanded) has.
  Front front_after(const State& s) {
    return rebuild(s.parent >= 0 ? &front_of(s.parent) : nullptr, {s.parent, s.gluing, s.last});
  }

  /// Arena indices of the hexes placed on the way to `s`, first placed first.
  std::vector<std::int32_t> path(const State& s) const {
    std::vector<std::int32_t> out;
    for (std::int32_t a = s.last; a >= 0; a = arena_[static_cast<std::size_t>(a)].parent) out.push_back(a);
    std::reverse(out.begin(), out.end());
    return out;
  }
  const Placed& placed(std::int32_t a) const { return arena_[static_cast<std::size_t>(a)]; }

private:
  static constexpr std::size_t canonical_limit = 40;
  static constexpr std::size_t kLargeFront = 64;

  std::int32_t id_of_placed(std::int32_t arena_index) const {
    return static_cast<std::int32_t>(cavity_.hexes.size()) + arena_index;
  }

  std::int32_t place(const Hex& hex, std::int32_t parent, HexSource source) {
    arena_.push_back({hex, parent, source});
    return static_cast<std::int32_t>(arena_.size() - 1);
  }

  /// The near hexes (arena indices) at each vertex, for one expansion.
  struct NearAtVertex : ByCorner<std::int32_t> {
    NearAtVertex(const std::vector<std::int32_t>& near, const std::vector<Placed>& arena)
        : ByCorner(
              near.size(), [&](std::size_t i) -> const Hex& { return arena[static_cast<std::size_t>(near[i])].hex; },
              [&](std::size_t i) { return near[i]; }) {}
  };

  /// Hexes round an edge before a gluing: the cavity's and the placed ones
  /// near the front hold every hex at a front vertex.
  HexesRound hexes_round(const NearAtVertex& near) const {
    return [this, &near](std::uint32_t u, std::uint32_t v) {
      int n = 0;
      for (std::int32_t h : context_.at(u)) n += hex_has_edge(cavity_.hexes[static_cast<std::size_t>(h)], u, v);
      near.each(u, [&](std::int32_t a) { n += hex_has_edge(arena_[static_cast<std::size_t>(a)].hex, u, v); });
      return n;
    };
  }
  float gluing_cost(const quadmap::GluedHex& glued, const Front& f, const QuadsAtVertex& at, const NearAtVertex& near,
                    const std::vector<std::uint32_t>& covered) const {
    if (weight_ == 0) return 0;
    return static_cast<float>(gluing_irregularity(glued, f.front, f.owner, at, covered, hexes_round(near)));
  }
  float closing_cost(const std::vector<Hex>& hexes, const Front& f) const {
    if (weight_ == 0) return 0;
    const NearAtVertex near(f.near, arena_);
    return static_cast<float>(closing_irregularity(hexes, f.front, f.owner, hexes_round(near)));
  }

  /// Whether `hex`, glued onto the front quads `onto` (indices into
  /// f.front), meets every hex before it as a valid mesh allows. Only hexes
  /// sharing a corner with it can fail: the cavity's (context_) and the
  /// placed ones near the front (`near`).
  bool fits(const Hex& hex, const Front& f, const NearAtVertex& near, const std::vector<std::uint32_t>& onto) const {
    onto_.clear();
    for (std::uint32_t q : onto) onto_.push_back(&f.front.quads[q]);
    checked_.clear();
    bool ok = true;
    for (std::uint32_t v : hex) {
      for (std::int32_t h : context_.at(v)) {
        if (std::find(checked_.begin(), checked_.end(), h) != checked_.end()) continue;
        checked_.push_back(h);
        if (!meets_as_glued(hex, cavity_.hexes[static_cast<std::size_t>(h)], onto_)) return false;
      }
      near.each(v, [&](std::int32_t a) {
        const std::int32_t id = id_of_placed(a);
        if (!ok || std::find(checked_.begin(), checked_.end(), id) != checked_.end()) return;
        checked_.push_back(id);
        ok = meets_as_glued(hex, arena_[static_cast<std::size_t>(a)].hex, onto_);
      });
      if (!ok) return false;
    }
    return true;
  }

  template <class Emit>
  void close_cube(const State& s, const Front& f, Emit& emit) {
    Hex hex;
    if (!quadmap::fill_cube(f.front, f.twin, hex)) return;
    std::vector<std::uint32_t> all(f.front.size());
    for (std::uint32_t q = 0; q < all.size(); ++q) all[q] = q;
    if (!fits(hex, f, NearAtVertex(f.near, arena_), all)) return;
    State done;
    done.closed = true;
    done.hexes = s.hexes + 1;
    done.irregularity = s.irregularity + closing_cost({hex}, f);
    done.last = place(hex, s.last, HexSource::searched);
    emit(std::move(done));
  }

  /// The database's mesh for the front, placed by each automorphism in turn
  /// until one fits the hexes around it.
  template <class Emit>
  void close_from_database(const State& s, const Front& f, const quadmap::Canonical& canon, Emit& emit) {
    const Database::Entry* entry = db_ ? db_->find(canon.code) : nullptr;
    if (!entry) return;
    const QuadMap read = canon.mirrored ? quadmap::mirrored(f.front) : f.front;
    const auto twin = canon.mirrored ? quadmap::mirrored_twins(f.twin) : f.twin;
    for (quadmap::Dart start : canon.starts) {
      const std::vector<Hex> hexes = db_->mesh_on(*entry, read, twin, start, canon.mirrored);
      std::int32_t last = s.last;
      const std::size_t mark = arena_.size();
      bool ok = true;
      // Each of the mesh's hexes goes onto the whole front: every front quad is covered.
      std::vector<std::uint32_t> all(f.front.size());
      for (std::uint32_t q = 0; q < all.size(); ++q) all[q] = q;
      const NearAtVertex near_at(f.near, arena_);
      for (const Hex& h : hexes) {
        if (!fits(h, f, near_at, all)) {
          ok = false;
          break;
        }
        last = place(h, last, HexSource::database);
      }
      if (!ok) {
        arena_.resize(mark);
        continue;
      }
      State done;
      done.closed = true;
      done.hexes = s.hexes + static_cast<int>(hexes.size());
      done.irregularity = s.irregularity + closing_cost(hexes, f);
      done.last = last;
      emit(std::move(done));
      return;
    }
  }

  const Cavity& cavity_;
  HexesAtVertex context_;
  const Database* db_;
  std::size_t max_front_;
  std::vector<Placed> arena_;
  FrontStore<Front, Made> fronts_;
  double weight_;
  std::unordered_map<std::uint64_t, double> expanded_codes_;  ///< canonical code hash -> least cost expanded at
  mutable std::vector<std::int32_t> checked_;
  mutable std::vector<const Quad*> onto_;
  SearchProfile profile_;
};

}  // namespace

ClosureResult close_cavity(const Cavity& cavity, const Database* db, const ClosureOptions& options) {
  ShellSpace space(cavity, db, cavity.front.size() + static_cast<std::size_t>(std::max(0, options.max_growth)),
                   options.irregularity_weight, options.front_bytes);
  auto outcome = engine::best_first_search(space, space.start(), options.limits);
  ClosureResult r;
  r.stats = outcome.stats;
  r.profile = space.profile();
  const ShellSpace::State* end = outcome.goal ? &*outcome.goal : outcome.closest ? &*outcome.closest : nullptr;
  r.closed = outcome.goal.has_value();
  std::uint32_t bound = cavity.front.vertex_bound;
  const auto context = static_cast<std::int32_t>(cavity.hexes.size());
  std::vector<std::int32_t> position_of;  // arena index -> place in r.hexes
  if (end)
    for (std::int32_t a : space.path(*end)) {
      const auto& p = space.placed(a);
      if (position_of.size() <= static_cast<std::size_t>(a)) position_of.resize(static_cast<std::size_t>(a) + 1, -1);
      position_of[static_cast<std::size_t>(a)] = static_cast<std::int32_t>(r.hexes.size());
      r.hexes.push_back(p.hex);
      r.source.push_back(p.source);
      for (std::uint32_t v : p.hex) bound = std::max(bound, v + 1);
    }
  r.vertex_bound = bound;
  if (!r.closed && end) {
    const ShellSpace::Front f = space.front_after(*end);
    r.left.front = f.front;
    r.left.front.vertex_bound = bound;
    for (std::int32_t o : f.owner)
      r.left.owner.push_back(o < context ? o : context + position_of[static_cast<std::size_t>(o - context)]);
    r.left.hexes = cavity.hexes;
    r.left.hexes.insert(r.left.hexes.end(), r.hexes.begin(), r.hexes.end());
  }
  return r;
}

}  // namespace loom::closure
