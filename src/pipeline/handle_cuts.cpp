#include "src/pipeline/handle_cuts.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <unordered_map>

#include <stdexcept>

#include <fmt/format.h>

#include "src/check/hex_topology.hpp"
#include "src/closure/cavities.hpp"
#include "src/quadmap/quad_map.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"

namespace loom::pipeline {

namespace {

// Short meridians tried, beyond the basis, when no basis cycle takes a disk.
constexpr std::size_t kAlternativeMeridians = 32;

using DirectedEdges = std::unordered_map<std::uint64_t, std::uint32_t>;  // a -> b to the quad holding it

std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

DirectedEdges directed_edges(const QuadSurface& s) {
  DirectedEdges quad_of;
  for (std::uint32_t q = 0; q < s.quads.size(); ++q)
    for (int k = 0; k < 4; ++k) quad_of[key(s.quads[q][k], s.quads[q][(k + 1) % 4])] = q;
  return quad_of;
}

int corner_of(const Quad& q, std::uint32_t v) { return static_cast<int>(std::find(q.begin(), q.end(), v) - q.begin()); }

// The quads at c[k] on the left of the walk c[k-1] -> c[k] -> c[k+1]: from the
// one holding c[k] -> c[k+1] round c[k] to the one holding c[k-1] -> c[k].
std::optional<std::vector<std::uint32_t>> left_fan(const QuadSurface& s, const DirectedEdges& quad_of,
                                                   const NodeCycle& c, std::size_t k) {
  const std::uint32_t v = c[k], next = c[(k + 1) % c.size()], before = c[(k + c.size() - 1) % c.size()];
  auto start = quad_of.find(key(v, next));
  if (start == quad_of.end()) return std::nullopt;
  std::vector<std::uint32_t> fan{start->second};
  for (;;) {
    const Quad& q = s.quads[fan.back()];
    const std::uint32_t incoming = q[(corner_of(q, v) + 3) % 4];
    if (incoming == before) return fan;
    auto across = quad_of.find(key(v, incoming));
    if (across == quad_of.end() || fan.size() > s.quads.size()) return std::nullopt;
    fan.push_back(across->second);
  }
}

std::optional<std::string> unusable(const QuadSurface& s, const NodeCycle& c, const DirectedEdges& quad_of) {
  if (c.size() < 4 || c.size() % 2 != 0)
    return fmt::format("a meridian has {} edges, and a disk's grid needs an even number, at least 4", c.size());
  std::vector<bool> on_cycle(s.points.size(), false);
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (on_cycle[c[k]]) return fmt::format("the meridian {} passes node {} twice", describe_cycle(c), c[k]);
    on_cycle[c[k]] = true;
    const std::uint32_t next = c[(k + 1) % c.size()];
    if (!quad_of.contains(key(c[k], next)) || !quad_of.contains(key(next, c[k])))
      return fmt::format("nodes {} and {} of a meridian are not joined by an edge", c[k], next);
  }
  return std::nullopt;
}

// Grid sides a x b with 2 (a + b) = m, as square as the count allows.
std::pair<int, int> grid_for(std::size_t m) {
  const int a = static_cast<int>(m / 4);
  return {a, static_cast<int>(m / 2) - a};
}

// Position k of the grid's boundary walk (0,0) -> (a,0) -> (a,b) -> (0,b) -> (0,0)
// at grid node (i, j), or -1 inside.
int boundary_position(int i, int j, int a, int b) {
  if (j == 0) return i;
  if (i == a) return a + j;
  if (j == b) return a + b + (a - i);
  if (i == 0) return 2 * a + b + (b - j);
  return -1;
}

// The Coons patch of the boundary at grid node (i, j).
Vec3 coons(const std::vector<Vec3>& boundary, int a, int b, int i, int j) {
  auto at = [&](int ii, int jj) { return boundary[static_cast<std::size_t>(boundary_position(ii, jj, a, b)) % boundary.size()]; };
  const double u = static_cast<double>(i) / a, v = static_cast<double>(j) / b;
  const Vec3 sides = (1 - v) * at(i, 0) + v * at(i, b) + (1 - u) * at(0, j) + u * at(a, j);
  const Vec3 corners = (1 - u) * (1 - v) * at(0, 0) + u * (1 - v) * at(a, 0) + (1 - u) * v * at(0, b) + u * v * at(a, b);
  return sides - corners;
}

// The meridian started so that the grid's corners fall where it turns most
// (a square section's corners go to the square's), and on no node that one
// quad alone holds on either side: there the cap's corner quad and that quad
// would share three nodes (criterion 6 of the ball's surface fails).
std::optional<NodeCycle> started_for_corners(const QuadSurface& s, const DirectedEdges& quad_of, const NodeCycle& c) {
  std::vector<std::size_t> quads_round(s.points.size(), 0);
  for (const Quad& q : s.quads)
    for (std::uint32_t v : q) ++quads_round[v];
  const std::size_t m = c.size();
  std::vector<bool> lone_quad(m);
  std::vector<double> turn(m);
  for (std::size_t k = 0; k < m; ++k) {
    const auto fan = left_fan(s, quad_of, c, k);
    if (!fan) return std::nullopt;
    lone_quad[k] = fan->size() == 1 || quads_round[c[k]] - fan->size() == 1;
    const Vec3 in = s.points[c[k]] - s.points[c[(k + m - 1) % m]], out = s.points[c[(k + 1) % m]] - s.points[c[k]];
    turn[k] = std::acos(std::clamp(dot(in, out) / (norm(in) * norm(out)), -1.0, 1.0));
  }
  const auto [a, b] = grid_for(m);
  std::optional<std::size_t> best;
  double best_turn = -1;
  for (std::size_t start = 0; start < m; ++start) {
    bool fits = true;
    double turning = 0;
    for (std::size_t corner : {std::size_t{0}, std::size_t(a), std::size_t(a + b), std::size_t(2 * a + b)}) {
      fits = fits && !lone_quad[(start + corner) % m];
      turning += turn[(start + corner) % m];
    }
    if (fits && turning > best_turn + 1e-9) {
      best = start;
      best_turn = turning;
    }
  }
  if (!best) return std::nullopt;
  NodeCycle started(c.begin() + static_cast<std::ptrdiff_t>(*best), c.end());
  started.insert(started.end(), c.begin(), c.begin() + static_cast<std::ptrdiff_t>(*best));
  return started;
}

}  // namespace

std::optional<CutSurface> cut_along_disk(const QuadSurface& surface, const NodeCycle& meridian, std::string& why_not) {
  const DirectedEdges quad_of = directed_edges(surface);
  if (auto why = unusable(surface, meridian, quad_of)) {
    why_not = *why;
    return std::nullopt;
  }
  const auto started = started_for_corners(surface, quad_of, meridian);
  if (!started) {
    why_not = fmt::format("the meridian {} turns round a single quad wherever a disk's corner could go",
                          describe_cycle(meridian));
    return std::nullopt;
  }
  const NodeCycle& c = *started;
  CutSurface cut;
  cut.ball = surface;
  for (std::uint32_t v = 0; v < surface.points.size(); ++v) cut.glued.push_back(v);
  const auto n = static_cast<std::uint32_t>(surface.points.size());
  std::vector<std::uint32_t> copy(c.size());
  std::vector<std::vector<std::uint32_t>> quads_at(surface.points.size());
  for (std::uint32_t q = 0; q < surface.quads.size(); ++q)
    for (std::uint32_t v : surface.quads[q]) quads_at[v].push_back(q);
  // The push is a quarter of the shortest edge on or leaving C: less would
  // do, but more could fold the quads beside C (a thin ring's inner side) or
  // the disk itself (a thick ring's).
  Vec3 area{0, 0, 0}, left_side{0, 0, 0};
  double shortest = HUGE_VAL;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::uint32_t next = c[(k + 1) % c.size()], before = c[(k + c.size() - 1) % c.size()];
    area = area + 0.5 * cross(surface.points[c[k]], surface.points[next]);
    shortest = std::min(shortest, norm(surface.points[next] - surface.points[c[k]]));
    for (std::uint32_t q : quads_at[c[k]]) {
      const Quad& quad = surface.quads[q];
      const int at = corner_of(quad, c[k]);
      for (std::uint32_t w : {quad[(at + 1) % 4], quad[(at + 3) % 4]})
        if (w != next && w != before) shortest = std::min(shortest, norm(surface.points[w] - surface.points[c[k]]));
    }
  }
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto fan = left_fan(surface, quad_of, c, k);
    if (!fan) {
      why_not = fmt::format("the quads round node {} of a meridian do not form one fan", c[k]);
      return std::nullopt;
    }
    for (std::uint32_t q : *fan)
      for (std::uint32_t v : surface.quads[q]) left_side = left_side + (surface.points[v] - surface.points[c[k]]);
    copy[k] = static_cast<std::uint32_t>(cut.ball.points.size());
    cut.ball.points.push_back(surface.points[c[k]]);
    cut.glued.push_back(c[k]);
    for (std::uint32_t q : quads_at[c[k]])
      if (std::find(fan->begin(), fan->end(), q) == fan->end())
        for (std::uint32_t& v : cut.ball.quads[q])
          if (v == c[k]) v = copy[k];
  }
  // Two copies of the disk: the left one faces away from the left quads, so
  // its quads run along C backwards; the right one forwards.
  const auto [a, b] = grid_for(c.size());
  std::vector<Vec3> boundary;
  for (std::uint32_t v : c) boundary.push_back(surface.points[v]);
  const Vec3 normal = (1.0 / norm(area)) * area;
  const Vec3 push = (dot(left_side, normal) >= 0 ? 0.25 : -0.25) * shortest * normal;
  std::vector<std::uint32_t> left_grid((a + 1) * (b + 1)), right_grid((a + 1) * (b + 1));
  for (int j = 0; j <= b; ++j)
    for (int i = 0; i <= a; ++i) {
      const std::size_t g = static_cast<std::size_t>(j * (a + 1) + i);
      const int k = boundary_position(i, j, a, b);
      if (k >= 0) {
        left_grid[g] = c[static_cast<std::size_t>(k) % c.size()];
        right_grid[g] = copy[static_cast<std::size_t>(k) % c.size()];
        continue;
      }
      const Vec3 p = coons(boundary, a, b, i, j);
      const auto disk_node = n + static_cast<std::uint32_t>(cut.disk_points.size());
      cut.disk_points.push_back(p);
      left_grid[g] = static_cast<std::uint32_t>(cut.ball.points.size());
      cut.ball.points.push_back(p + push);
      cut.glued.push_back(disk_node);
      right_grid[g] = static_cast<std::uint32_t>(cut.ball.points.size());
      cut.ball.points.push_back(p - push);
      cut.glued.push_back(disk_node);
    }
  for (std::size_t k = 0; k < c.size(); ++k) {
    cut.ball.points[c[k]] = surface.points[c[k]] + push;
    cut.ball.points[copy[k]] = surface.points[c[k]] - push;
  }
  for (int j = 0; j < b; ++j)
    for (int i = 0; i < a; ++i) {
      auto g = [&](int ii, int jj) { return static_cast<std::size_t>(jj * (a + 1) + ii); };
      cut.ball.quads.push_back({right_grid[g(i, j)], right_grid[g(i + 1, j)], right_grid[g(i + 1, j + 1)],
                                right_grid[g(i, j + 1)]});
      cut.ball.quads.push_back({left_grid[g(i, j)], left_grid[g(i, j + 1)], left_grid[g(i + 1, j + 1)],
                                left_grid[g(i + 1, j)]});
    }
  return cut;
}

std::optional<CutSurface> cut_into_ball(const QuadSurface& surface, std::string& why_not) {
  const auto n = static_cast<std::uint32_t>(surface.points.size());
  CutSurface whole;
  whole.ball = surface;
  for (std::uint32_t v = 0; v < n; ++v) whole.glued.push_back(v);
  for (int genus_before = INT_MAX;;) {
    // Each cut is checked as any input is: a disk that meets the surface, or
    // a meridian with a chord, shows here rather than in the ball's mesh.
    QuadSurface checked = whole.ball;
    SurfaceSummary report;
    try {
      report = validate_surface(checked, "the solid cut along " + std::to_string(whole.disks) + " disks");
    } catch (const InputError& e) {
      why_not = e.what();
      return std::nullopt;
    }
    if (report.flipped || checked.points.size() != whole.ball.points.size()) {
      why_not = "a cut turned the surface inside out";
      return std::nullopt;
    }
    // The cavity closure needs more than validation does: three quads or more
    // at every node, no two quads on one diagonal.
    const quadmap::QuadMap map = quadmap::from_surface(whole.ball);
    if (auto bad = closure::improper_vertices(map); !bad.empty()) {
      const auto degree = quadmap::degrees(map);
      why_not = fmt::format("after {} cut{} node {} ({} quads) is not proper", whole.disks, whole.disks == 1 ? "" : "s",
                            bad.front(), degree[bad.front()]);
      return std::nullopt;
    }
    if (report.genus == 0) return whole;
    if (!report.meridians_known || report.meridians.empty() || report.genus >= genus_before) {
      why_not = report.meridians_known ? "no meridian was found to cut along"
                                       : "the meridians could not be found (the surface meets itself, or is too thin)";
      return std::nullopt;
    }
    genus_before = report.genus;
    // Any meridian lowers the genus by one: the shortest that takes a disk is
    // cut, tried among the basis first, then among more short ones (a disk
    // needs four corners where the meridian does not turn round one quad).
    std::optional<CutSurface> step;
    std::string first_why_not;
    std::size_t tried = 0;
    auto try_each = [&](const std::vector<NodeCycle>& meridians) {
      for (const NodeCycle& meridian : meridians) {
        if (step) return;
        ++tried;
        step = cut_along_disk(whole.ball, meridian, why_not);
        if (!step && first_why_not.empty()) first_why_not = why_not;
      }
    };
    try_each(report.meridians);
    if (!step) try_each(find_meridians(whole.ball, kAlternativeMeridians).alternatives);
    if (!step) {
      why_not = fmt::format("{}; nor did any of the {} other short meridians found take a disk", first_why_not, tried - 1);
      return std::nullopt;
    }
    const auto before = static_cast<std::uint32_t>(whole.ball.points.size());
    const auto disks_before = static_cast<std::uint32_t>(whole.disk_points.size());
    std::vector<std::uint32_t> glued;
    glued.reserve(step->glued.size());
    for (std::uint32_t g : step->glued) glued.push_back(g < before ? whole.glued[g] : n + disks_before + (g - before));
    whole.glued = std::move(glued);
    whole.ball = std::move(step->ball);
    whole.disk_points.insert(whole.disk_points.end(), step->disk_points.begin(), step->disk_points.end());
    ++whole.disks;
  }
}

HexMesh glue_disks(const HexMesh& ball_mesh, const CutSurface& cut, const QuadSurface& surface, std::vector<bool>& fixed) {
  std::map<Vec3, std::uint32_t> ball_node_at;
  for (std::uint32_t v = 0; v < cut.ball.points.size(); ++v) ball_node_at.emplace(cut.ball.points[v], v);
  HexMesh glued;
  glued.points = surface.points;
  glued.points.insert(glued.points.end(), cut.disk_points.begin(), cut.disk_points.end());
  fixed.assign(glued.points.size(), false);
  std::fill(fixed.begin(), fixed.begin() + static_cast<std::ptrdiff_t>(surface.points.size()), true);
  // Only nodes on the ball mesh's boundary are looked up by position: an
  // inner node may sit where a boundary one does (a layer's copy unmoved).
  const HexTopology topology = build_hex_topology(ball_mesh);
  std::vector<bool> on_boundary(ball_mesh.points.size(), false);
  for (std::size_t h = 0; h < ball_mesh.hexes.size(); ++h)
    for (int f = 0; f < 6; ++f)
      if (topology.is_boundary_face(topology.hex_faces[6 * h + static_cast<std::size_t>(f)]))
        for (std::uint32_t v : face_nodes(ball_mesh.hexes[h], f)) on_boundary[v] = true;
  std::vector<bool> used(ball_mesh.points.size(), false);
  for (const Hex& h : ball_mesh.hexes)
    for (std::uint32_t v : h) used[v] = true;
  std::vector<std::uint32_t> target(ball_mesh.points.size(), UINT32_MAX);
  for (std::uint32_t v = 0; v < ball_mesh.points.size(); ++v) {
    if (!used[v]) continue;
    auto at = on_boundary[v] ? ball_node_at.find(ball_mesh.points[v]) : ball_node_at.end();
    if (on_boundary[v] && at == ball_node_at.end())
      throw std::runtime_error("glue_disks: a boundary node of the ball's mesh is on no node of its surface");
    if (at != ball_node_at.end()) {
      target[v] = cut.glued[at->second];
    } else {
      target[v] = static_cast<std::uint32_t>(glued.points.size());
      glued.points.push_back(ball_mesh.points[v]);
      fixed.push_back(false);
    }
  }
  for (const Hex& h : ball_mesh.hexes) {
    Hex out;
    for (int k = 0; k < 8; ++k) out[k] = target[h[k]];
    glued.hexes.push_back(out);
  }
  return glued;
}

}  // namespace loom::pipeline
