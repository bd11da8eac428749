#include "src/pipeline/mesh_surface.hpp"

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>
#include <stdexcept>

#include "src/fill/fill.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/pipeline/candidate.hpp"
#include "src/pipeline/mesh_handles.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/util/error.hpp"

namespace loom::pipeline {

using closure::HexSource;

namespace {

/// Beside a valid mesh of at most 72 hexes before its boundary layer (what
/// Verhetsel et al. 2019 reach for every quadrangulation of at most 20
/// quads), the search from the surface gets a short budget: it only has to
/// find a smaller one. Above that (quadrangulation 16 90: 117 woven; search
/// 77 hexes with 500 expansions, 55 with 50,000) it gets the full one.
constexpr std::size_t kBesideValidExpansions = 500;
constexpr std::size_t kPublishedSmallBound = 72;
constexpr std::size_t kPublishedSmallQuads = 20;

/// Hexes of the result before its boundary layer, which placement adds to
/// some meshes and not others: meshes are compared by this count.
std::size_t hexes_before_layer(const MeshingResult& r) { return r.mesh->hexes.size() - r.boundary_layer.hexes_added; }

bool within_published_bound(const MeshingResult& r) {
  return r.combinatorially_valid() && hexes_before_layer(r) <= kPublishedSmallBound;
}

/// Whether a small surface's mesh needs the searches that look for a smaller
/// one: over the published bound and, when quality decides, not valid by
/// criterion 7 either (a smaller mesh would have to beat it placed).
bool wants_smaller(const MeshingResult& r, Prefer prefer) {
  if (within_published_bound(r)) return false;
  return prefer == Prefer::fewest_hexes || !r.combinatorially_valid() || r.smoothing.below_zero_after > 0;
}

/// Where each STC hex came from: woven, or put in whole by a template rule (the database).
std::vector<HexSource> sources_of(const stc::Stc& stc, const std::vector<stc::Id>& hexes) {
  std::vector<HexSource> out;
  out.reserve(hexes.size());
  for (stc::Id h : hexes)
    out.push_back(stc.graph().get(h, stc.ids().hex_source) == stc::kHexFromDatabase ? HexSource::database
                                                                                     : HexSource::woven);
  return out;
}

void weave_once(MeshingResult& r, const QuadSurface& surface, std::vector<engine::Rule> rules,
                const weave::WeaveOptions& options, const std::function<void(const char*)>& on_stage) {
  if (on_stage) on_stage("weaving");
  r.stc = stc::build_from_surface(surface);
  r.weave = weave::weave(r.stc, std::move(rules), options);
  r.mesh.reset();
  r.check.reset();
  r.source.clear();
  r.failure.clear();
  r.made_by.clear();
  r.smoothing = {};
  r.boundary_layer = {};
  if (!r.weave.closed) return;
  if (on_stage) on_stage("placing nodes");
  try {
    Candidate c;
    c.mesh = stc::to_hex_mesh(r.stc, &c.fixed);
    // to_hex_mesh keeps the STC's hex order.
    c.source = sources_of(r.stc, r.stc.graph().members(r.stc.ids().hex));
    place(c, surface, r);
    adopt(r, std::move(c), "woven");
  } catch (const std::runtime_error& e) {
    r.failure = e.what();
  }
}

/// What the stages after the weave read, loaded when first needed.
class Resources {
public:
  explicit Resources(const MeshingOptions& o) : o_(o) {}
  const closure::Database* database() {
    if (!db_ && !o_.database.empty()) db_ = closure::Database::load(o_.database);
    return db_ ? &*db_ : nullptr;
  }
  const std::vector<fill::Cap>& caps() {
    if (!caps_ && !o_.fill_caps.empty()) caps_ = fill::load_caps(o_.fill_caps);
    static const std::vector<fill::Cap> none;
    return caps_ ? *caps_ : none;
  }

private:
  const MeshingOptions& o_;
  std::optional<closure::Database> db_;
  std::optional<std::vector<fill::Cap>> caps_;
};

/// A candidate from a closed mesh: placed and checked.
Candidate placed_candidate(ClosedMesh&& closed, const QuadSurface& surface, MeshingResult& r) {
  Candidate c;
  c.mesh = std::move(closed.mesh);
  c.source = std::move(closed.source);
  c.fixed = std::move(closed.on_boundary);
  place(c, surface, r);
  return c;
}

void close_cavities_of(MeshingResult& r, const QuadSurface& surface, const HexMesh& woven,
                       const std::vector<HexSource>& woven_source, Resources& res, const MeshingOptions& options) {
  if (options.on_stage) options.on_stage("closing cavities");
  try {
    const bool fill = options.closure == Closure::full;
    ClosedMesh closed = close_cavities(surface, woven, res.database(), fill ? res.caps() : std::vector<fill::Cap>{},
                                       options.search, woven_source);
    r.closure = closed.report;
    if (!closed.complete) {
      r.closure_failure = "the search left cavities and the fill is off";
      return;
    }
    if (options.on_stage) options.on_stage("placing nodes");
    Candidate c = placed_candidate(std::move(closed), surface, r);
    if (!c.valid()) {
      r.closure_failure = c.why_invalid();
      return;
    }
    adopt(r, std::move(c), "closed");
  } catch (const InputError& e) {
    r.closure_failure = e.what();
  }
}

/// A mesh a search from the surface closed, kept if it beats the mesh there
/// is as `prefer` says. By hexes, a candidate with no fewer is not even placed.
void adopt_if_better(MeshingResult& r, ClosedMesh&& closed, const QuadSurface& surface, Prefer prefer) {
  if (!closed.complete) return;
  const std::size_t hexes = closed.mesh.hexes.size();
  const bool fewer = !r.combinatorially_valid() || hexes < hexes_before_layer(r);
  if (prefer == Prefer::fewest_hexes && !fewer) return;
  const ClosureReport report = closed.report;
  Candidate c = placed_candidate(std::move(closed), surface, r);
  if (!c.valid()) return;
  if (prefer == Prefer::quality && r.combinatorially_valid() && !improves(c.smoothing, r.smoothing) &&
      (improves(r.smoothing, c.smoothing) || !fewer))
    return;
  adopt(r, std::move(c), "searched");
  r.closure = report;
}

/// The search alone from the surface (the fill of what it leaves too, with
/// `fill`); kept if it beats the mesh there is.
void search_from_surface(MeshingResult& r, const QuadSurface& surface, Resources& res, const MeshingOptions& options,
                         const closure::ClosureOptions& search, bool fill) {
  if (options.on_stage) options.on_stage("searching from the surface");
  try {
    adopt_if_better(r,
                    close_cavities(surface, HexMesh{surface.points, {}}, res.database(),
                                   fill ? res.caps() : std::vector<fill::Cap>{}, search),
                    surface, options.prefer);
  } catch (const InputError& e) {
    if (r.closure_failure.empty()) r.closure_failure = e.what();
  }
}

/// The search in symmetric pairs; kept if it beats the mesh there is.
void search_symmetric_pairs(MeshingResult& r, const QuadSurface& surface, Resources& res,
                            const MeshingOptions& options) {
  if (options.on_stage) options.on_stage("searching symmetric pairs");
  try {
    const closure::ClosureResult closed =
        closure::close_symmetric(quadmap::from_surface(surface), res.database(), options.symmetric);
    if (closed.closed) adopt_if_better(r, mesh_of_closure(surface, closed), surface, options.prefer);
  } catch (const InputError& e) {
    if (r.closure_failure.empty()) r.closure_failure = e.what();
  }
}

void fill_whole_surface(MeshingResult& r, const QuadSurface& surface, Resources& res) {
  if (res.caps().empty()) {
    r.fill_failure = "it has no caps: the rules directory has no fill/ (the shipped rules/fill has them)";
    return;
  }
  try {
    fill::FilledMesh f = fill::fill_constructively(surface, res.caps());
    Candidate c;
    c.mesh = std::move(f.mesh);
    c.fixed = std::move(f.on_boundary);
    c.source.assign(c.mesh.hexes.size(), HexSource::filled);
    // Its caps are pillowed, so no hex has two faces on the boundary and a
    // boundary layer (place's second resort) could unlock nothing.
    {
      const PlacementTally tally(r);
      c.smoothing = weave::smooth_interior(c.mesh, c.fixed);
      c.check = check_hex_mesh(c.mesh, &surface);
    }
    adopt(r, std::move(c), "filled");
  } catch (const InputError& e) {
    r.fill_failure = e.what();
  }
}

}  // namespace

/// A surface of at most 20 quads still over 72 hexes after the direct search
/// gets one wide search. Quadrangulation 14 54 (two poles of degree 7): 79
/// hexes at growth 8, where every state within that bound is expanded in
/// 780,000 expansions; at growth 16 with 1,000,000, 73 with room for 4,000,000
/// open states, 67 with 20,000,000 (255 s, 3.6 GB). Counted in expansions, so
/// its seconds guard is only against a runaway.
closure::ClosureOptions wide_search_defaults() {
  closure::ClosureOptions wide;
  wide.max_growth = 16;
  wide.limits.max_expansions = 1'000'000;
  wide.limits.max_open = 20'000'000;
  wide.limits.max_seconds = 3'600;
  return wide;
}

MeshingOptions default_meshing_options(const std::filesystem::path& rules_dir) {
  MeshingOptions o;
  o.attempts = 16;
  o.closure = Closure::full;
  if (std::filesystem::exists(closure::database_file(rules_dir))) o.database = closure::database_file(rules_dir);
  if (std::filesystem::is_directory(rules_dir / "fill")) o.fill_caps = rules_dir / "fill";
  return o;
}

MeshingResult mesh_surface(const QuadSurface& surface, std::vector<engine::Rule> rules, const MeshingOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MeshingResult r;
  r.prefer = options.prefer;
  Resources res(options);
  weave::WeaveOptions attempt = options.weave;
  if (!attempt.database) attempt.database = [&res] { return res.database(); };
  const std::uint64_t first_seed = options.weave.strategy.random() ? options.weave.strategy.seed : 0;
  std::optional<HexMesh> best_woven;  // of the attempt that left the fewest whiskers
  std::vector<HexSource> best_woven_source;
  std::size_t best_left = SIZE_MAX, best_attempt = 0;
  // Cavities, the search and the fill are built for balls: a solid with
  // handles that the weave does not mesh is cut into one. Its own weave gets
  // one attempt, the ball all of them: 16 attempts closed no torus N x M of
  // N = 3..24, M = 4..16, nor the 5 x 3 plate with two holes.
  std::vector<bool> used(surface.points.size(), false);
  for (const Quad& q : surface.quads)
    for (std::uint32_t v : q) used[v] = true;
  // V - E + F with E = 2F on a closed quad surface.
  const long long euler = std::count(used.begin(), used.end(), true) - static_cast<long long>(surface.quads.size());
  const bool cut_if_open = options.closure != Closure::none && euler != 2;
  const std::size_t attempts = cut_if_open ? 1 : options.attempts;
  for (r.attempts = 1;; ++r.attempts) {
    r.strategy = attempt.strategy;
    weave_once(r, surface, rules, attempt, options.on_stage);
    if (r.combinatorially_valid()) break;
    if (options.closure != Closure::none && r.weave.whiskers_left < best_left) {
      best_left = r.weave.whiskers_left;
      best_attempt = r.attempts;
      std::vector<stc::Id> hexes;
      best_woven = stc::woven_over_surface(r.stc, surface.points.size(), &hexes);
      best_woven_source = sources_of(r.stc, hexes);
    }
    if (r.attempts >= attempts) break;
    attempt.strategy = options.weave.strategy.with_random_picks();
    attempt.strategy.seed = first_seed + r.attempts;
    if (options.before_attempt) options.before_attempt(r.attempts + 1, attempt.strategy, r.weave);
  }
  if (cut_if_open && !r.combinatorially_valid())
    mesh_through_cuts(r, surface, rules, options);
  else if (options.closure != Closure::none) {
    if (!r.combinatorially_valid()) close_cavities_of(r, surface, *best_woven, best_woven_source, res, options);
    const bool small = surface.quads.size() <= kDirectSearchQuads;
    auto budget = [&options](std::size_t expansions) {
      closure::ClosureOptions search = options.search;
      search.limits.max_expansions = expansions;
      return search;
    };
    // Beside a valid mesh within the published bound (by quality, with no hex
    // <= 0 either), only a short search: it has to find a smaller one, so it
    // counts hexes alone.
    if (small) {
      const bool settled = within_published_bound(r) &&
                           (options.prefer == Prefer::fewest_hexes || r.smoothing.below_zero_after == 0);
      closure::ClosureOptions fewest = budget(settled ? kBesideValidExpansions : kSmallFrontExpansions);
      fewest.irregularity_weight = 0;
      search_from_surface(r, surface, res, options, fewest, false);
      // Still over the bound (by quality, with a hex <= 0 too): first the
      // search in symmetric pairs (16 439: 78 hexes to 68 in a minute), then
      // the wide search. They can only
      // improve a mesh the run already has: when one runs out of memory
      // (--max-memory), it gives way and that mesh stays.
      if (surface.quads.size() <= kPublishedSmallQuads && wants_smaller(r, options.prefer)) try {
          search_symmetric_pairs(r, surface, res, options);
          if (wants_smaller(r, options.prefer)) search_from_surface(r, surface, res, options, options.wide_search, false);
        } catch (const std::bad_alloc&) {
          if (!r.combinatorially_valid()) throw;
          r.wide_search_stopped = "out of memory";
        }
    }
    // The woven hexes kept can leave cavities harder than the surface: when
    // the closure had to fill, the search alone from the surface is tried too.
    else if (r.made_by == "closed" && r.closure.filled > 0)
      search_from_surface(r, surface, res, options,
                          budget(std::clamp<std::size_t>(kExpansionsPerQuad * surface.quads.size(),
                                                         kSmallFrontExpansions, kMostExpansions)),
                          options.closure == Closure::full);
    if (!r.combinatorially_valid() && options.closure == Closure::full) {
      if (options.on_stage) options.on_stage("filling the surface");
      fill_whole_surface(r, surface, res);
    }
  }
  const bool holds_woven = std::count(r.source.begin(), r.source.end(), HexSource::woven) > 0;
  if (r.cut_disks == 0)
    r.woven_attempt = !holds_woven ? 0 : r.made_by == "woven" ? r.attempts : r.made_by == "closed" ? best_attempt : 0;
  if (r.mesh) r.inversions = geometry::diagnose_inversions(*r.mesh);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace loom::pipeline
