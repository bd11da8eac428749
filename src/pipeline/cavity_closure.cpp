#include "src/pipeline/cavity_closure.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <stdexcept>

#include "src/closure/cavities.hpp"
#include "src/fill/fill.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/util/error.hpp"

namespace loom::pipeline {

using closure::HexSource;

namespace {

/// A hex or a face by its corners alone, as a key.
Hex sorted(Hex h) {
  std::sort(h.begin(), h.end());
  return h;
}
Hex sorted_face(const Quad& q) {
  Hex k{q[0], q[1], q[2], q[3], 0, 0, 0, 0};
  std::sort(k.begin(), k.begin() + 4);
  return k;
}

/// The budget of a search on a front; `again`: a search on what another left.
std::size_t budget_for(std::size_t front_quads, std::size_t least, bool again) {
  if (again && front_quads <= kSmallFrontQuads) return std::max(least, kSmallFrontExpansions);
  return std::max(least, std::min(kExpansionsPerQuad * front_quads, kMostExpansions));
}

struct Builder {
  ClosedMesh out;
  std::vector<bool> placed;  ///< per point: has a position

  std::uint32_t bound() const { return static_cast<std::uint32_t>(out.mesh.points.size()); }
  void reserve_points(std::uint32_t n) {
    if (n > out.mesh.points.size()) {
      out.mesh.points.resize(n, Vec3{0, 0, 0});
      placed.resize(n, false);
    }
  }
  void add(const Hex& h, HexSource s) {
    for (std::uint32_t v : h) reserve_points(v + 1);
    out.mesh.hexes.push_back(h);
    out.source.push_back(s);
  }

  /// The hexes already in the mesh with a corner on `cavity`'s front that
  /// `cavity` does not list yet (hexes another cavity's closure added).
  void add_neighbours_to(closure::Cavity& cavity, std::size_t first_added) const {
    std::vector<std::uint32_t> vertices;
    for (const Quad& q : cavity.front.quads) vertices.insert(vertices.end(), q.begin(), q.end());
    std::sort(vertices.begin(), vertices.end());
    for (std::size_t h = first_added; h < out.mesh.hexes.size(); ++h) {
      const Hex& hex = out.mesh.hexes[h];
      if (std::any_of(hex.begin(), hex.end(),
                      [&](std::uint32_t v) { return std::binary_search(vertices.begin(), vertices.end(), v); }))
        cavity.hexes.push_back(hex);
    }
  }

  /// Fills the front of `left` constructively; its new nodes get the fill's first positions.
  void fill(const closure::Cavity& left, const std::vector<fill::Cap>& caps) {
    std::map<std::uint32_t, std::uint32_t> local;
    std::vector<std::uint32_t> global;
    QuadSurface s;
    for (const Quad& q : left.front.quads) {
      Quad l;
      for (int i = 0; i < 4; ++i) {
        auto [it, fresh] = local.emplace(q[i], static_cast<std::uint32_t>(global.size()));
        if (fresh) {
          global.push_back(q[i]);
          s.points.push_back(out.mesh.points[q[i]]);
        }
        l[i] = it->second;
      }
      s.quads.push_back(l);
    }
    fill::FilledMesh f = fill::fill_constructively(s, caps);
    const std::size_t first = out.mesh.hexes.size();
    for (std::size_t p = global.size(); p < f.mesh.points.size(); ++p) {
      global.push_back(bound());
      reserve_points(bound() + 1);
      out.mesh.points.back() = f.mesh.points[p];
      placed.back() = true;
    }
    for (const Hex& h : f.mesh.hexes) {
      Hex g;
      for (int i = 0; i < 8; ++i) g[i] = global[h[i]];
      add(g, HexSource::filled);
    }
    out.report.filled += f.mesh.hexes.size();
    std::vector<bool> fixed(bound(), false);
    const auto layer = geometry::pillow_region(out.mesh, first, out.mesh.hexes.size(), fixed);
    out.source.resize(out.mesh.hexes.size(), HexSource::pillow);
    placed.resize(bound(), true);
    out.report.pillowed += layer.hexes_added;
  }

  /// Positions for the nodes the search and the database made: the mean of
  /// their placed hex-edge neighbours, spreading inwards. Placement (the
  /// harmonic start) decides the final ones; this only avoids a degenerate start.
  void estimate_positions() {
    std::vector<std::vector<std::uint32_t>> next(bound());
    static constexpr int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                         {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const Hex& h : out.mesh.hexes)
      for (const auto& e : edges) {
        next[h[e[0]]].push_back(h[e[1]]);
        next[h[e[1]]].push_back(h[e[0]]);
      }
    for (bool progress = true; progress;) {
      progress = false;
      for (std::uint32_t v = 0; v < bound(); ++v) {
        if (placed[v]) continue;
        Vec3 sum{0, 0, 0};
        int n = 0;
        for (std::uint32_t w : next[v])
          if (placed[w]) {
            sum = sum + out.mesh.points[w];
            ++n;
          }
        if (n == 0) continue;
        out.mesh.points[v] = (1.0 / n) * sum;
        placed[v] = true;
        progress = true;
      }
    }
  }
};

/// One round: the hexes of `start` kept as far as they can be part of a valid
/// mesh, each cavity searched, and (with `caps`) filled where the search
/// stopped short; without caps, the fronts it left are in `open`.
ClosedMesh close_round(const QuadSurface& surface, const HexMesh& start, const std::vector<HexSource>& start_source,
                       const closure::Database* db, const std::vector<fill::Cap>& caps,
                       const closure::ClosureOptions& options, std::vector<Quad>& open) {
  closure::Cavities cavities = closure::cavities_left(surface, start.hexes);
  std::map<Hex, HexSource> source_of;
  for (std::size_t h = 0; h < start.hexes.size(); ++h) source_of.emplace(sorted(start.hexes[h]), start_source[h]);
  Builder b;
  b.out.mesh.points = start.points;
  b.placed.assign(start.points.size(), true);
  b.reserve_points(cavities.vertex_bound);
  ClosureReport& report = b.out.report;
  report.peeled = cavities.peeled;
  report.cavities = cavities.pieces.size();
  for (const Hex& h : cavities.kept) b.add(h, source_of.at(sorted(h)));
  const std::size_t first_added = b.out.mesh.hexes.size();
  for (closure::Cavity& cavity : cavities.pieces) {
    report.front_quads += cavity.front.size();
    b.add_neighbours_to(cavity, first_added);
    cavity.front.vertex_bound = b.bound();
    auto search = [&](const closure::Cavity& c, bool again) {
      closure::ClosureOptions sized = options;
      sized.limits.max_expansions = budget_for(c.front.size(), options.limits.max_expansions, again);
      closure::ClosureResult r = closure::close_cavity(c, db, sized);
      report.search.expanded += r.stats.expanded;
      report.search.generated += r.stats.generated;
      report.search.seconds += r.stats.seconds;
      report.search.peak_open = std::max(report.search.peak_open, r.stats.peak_open);
      for (std::size_t i = 0; i < r.hexes.size(); ++i) {
        b.add(r.hexes[i], r.source[i]);
        (r.source[i] == HexSource::database ? report.database : report.searched) += 1;
      }
      b.reserve_points(r.vertex_bound);
      return r;
    };
    closure::ClosureResult r = search(cavity, false);
    // A search that stopped short spent much of its budget on large fronts;
    // one on what it left, alone, goes further, as long as the front shrinks.
    for (std::size_t before = cavity.front.size(); !r.closed && r.left.front.size() < before;) {
      before = r.left.front.size();
      closure::Cavity left = r.left;
      left.front.vertex_bound = b.bound();
      r = search(left, true);
    }
    if (!r.closed) {
      if (caps.empty()) {
        open.insert(open.end(), r.left.front.quads.begin(), r.left.front.quads.end());
        b.out.complete = false;
        continue;
      }
      ++report.filled_cavities;
      report.fill_quads += r.left.front.size();
      b.estimate_positions();
      b.fill(r.left, caps);
    }
  }
  b.estimate_positions();
  return std::move(b.out);
}

void add_up(ClosureReport& total, const ClosureReport& round) {
  total.search.expanded += round.search.expanded;
  total.search.generated += round.search.generated;
  total.search.seconds += round.search.seconds;
  total.search.peak_open = std::max(total.search.peak_open, round.search.peak_open);
}

// The surface's points come first in every mesh closure builds.
void mark_surface_points(ClosedMesh& out, std::size_t surface_points) {
  out.on_boundary.assign(out.mesh.points.size(), false);
  std::fill_n(out.on_boundary.begin(), surface_points, true);
}

}  // namespace

PulledBack without_hexes_on(const HexMesh& m, const std::vector<Quad>& front, std::size_t keep_points) {
  std::set<Hex> stuck;
  for (const Quad& q : front) stuck.insert(sorted_face(q));
  PulledBack out;
  HexMesh& kept = out.mesh;
  std::vector<std::int64_t> renumbered(m.points.size(), -1);
  for (std::size_t p = 0; p < keep_points; ++p) {
    renumbered[p] = static_cast<std::int64_t>(p);
    kept.points.push_back(m.points[p]);
  }
  for (std::size_t index = 0; index < m.hexes.size(); ++index) {
    const Hex& h = m.hexes[index];
    const auto faces = quadmap::outward_faces(h);
    if (std::any_of(faces.begin(), faces.end(), [&](const Quad& f) { return stuck.count(sorted_face(f)) > 0; }))
      continue;
    Hex corners;
    for (int i = 0; i < 8; ++i) {
      std::int64_t& id = renumbered[h[i]];
      if (id < 0) {
        id = static_cast<std::int64_t>(kept.points.size());
        kept.points.push_back(m.points[h[i]]);
      }
      corners[i] = static_cast<std::uint32_t>(id);
    }
    kept.hexes.push_back(corners);
    out.kept.push_back(index);
  }
  return out;
}

ClosedMesh mesh_of_closure(const QuadSurface& surface, const closure::ClosureResult& closed) {
  if (!closed.closed) throw std::logic_error("mesh_of_closure: the search did not close the surface");
  Builder b;
  b.out.mesh.points = surface.points;
  b.placed.assign(surface.points.size(), true);
  b.reserve_points(closed.vertex_bound);
  ClosureReport& report = b.out.report;
  report.cavities = 1;
  report.front_quads = surface.quads.size();
  report.search = closed.stats;
  report.seconds = closed.stats.seconds;
  for (std::size_t i = 0; i < closed.hexes.size(); ++i) {
    b.add(closed.hexes[i], closed.source[i]);
    (closed.source[i] == HexSource::database ? report.database : report.searched) += 1;
  }
  b.estimate_positions();
  mark_surface_points(b.out, surface.points.size());
  return std::move(b.out);
}

ClosedMesh close_cavities(const QuadSurface& surface, const HexMesh& woven, const closure::Database* db,
                          const std::vector<fill::Cap>& caps, const closure::ClosureOptions& options,
                          const std::vector<HexSource>& woven_source) {
  const auto start = std::chrono::steady_clock::now();
  if (!woven_source.empty() && woven_source.size() != woven.hexes.size())
    throw std::logic_error("close_cavities: one source per woven hex");
  HexMesh current = woven;
  const std::vector<HexSource> given_source =
      woven_source.empty() ? std::vector<HexSource>(woven.hexes.size(), HexSource::woven) : woven_source;
  std::vector<HexSource> current_source = given_source;
  ClosureReport total;
  ClosedMesh out;
  for (std::size_t round = 0;; ++round) {
    // The last round may fill; the others leave stuck fronts open, to pull back round them.
    const bool last = round == kMostPullBacks;
    std::vector<Quad> open;
    out = close_round(surface, current, current_source, db, last ? caps : std::vector<fill::Cap>{}, options, open);
    if (round == 0) {
      total.cavities = out.report.cavities;
      total.front_quads = out.report.front_quads;
    }
    add_up(total, out.report);
    if (out.complete || open.empty() || last) break;
    ++total.pull_backs;
    PulledBack back = without_hexes_on(out.mesh, open, surface.points.size());
    current = std::move(back.mesh);
    current_source.clear();
    for (std::size_t h : back.kept) current_source.push_back(out.source[h]);
  }
  // What the mesh holds, by source (hexes kept from earlier rounds included).
  ClosureReport& report = out.report;
  const ClosureReport last_round = report;
  report = total;
  report.filled = last_round.filled, report.pillowed = last_round.pillowed;
  report.filled_cavities = last_round.filled_cavities, report.fill_quads = last_round.fill_quads;
  for (HexSource s : out.source) {
    if (s == HexSource::woven) ++report.woven;
    if (s == HexSource::searched) ++report.searched;
    if (s == HexSource::database) ++report.database;
  }
  // Counted by source, since a pull-back renumbers the points the hexes use.
  report.peeled = static_cast<std::size_t>(std::count(given_source.begin(), given_source.end(),
                                                      HexSource::woven)) - report.woven;
  mark_surface_points(out, surface.points.size());
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace loom::pipeline
