#include "src/mesh/meridians.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "src/mesh/meridian_cycles.hpp"
#include "src/geometry/linking.hpp"
#include "src/mesh/surface_homology.hpp"

namespace loom {

namespace {

using Words = HomologyClass;

// Each basis cycle pushed off the surface along the node normals, by a small
// fraction of the shortest edge: inward (sign -1) into the solid, outward (+1)
// into its complement.
std::optional<std::vector<std::vector<Vec3>>> pushed_cycles(const QuadSurface& s, const SurfaceHomology& h,
                                                            double sign) {
  std::vector<Vec3> normal(s.points.size(), Vec3{0, 0, 0});
  for (const Quad& q : s.quads) {
    const Vec3 area = cross(s.points[q[2]] - s.points[q[0]], s.points[q[3]] - s.points[q[1]]);
    for (std::uint32_t v : q) normal[v] = normal[v] + area;
  }
  double shortest = HUGE_VAL;
  for (const auto& [a, b] : h.edges.ends) shortest = std::min(shortest, norm(s.points[a] - s.points[b]));
  const double push = 1e-3 * shortest;
  std::vector<std::vector<Vec3>> pushed;
  for (const NodeCycle& cycle : h.cycles) {
    std::vector<Vec3>& polygon = pushed.emplace_back();
    for (std::uint32_t v : cycle) {
      const double length = norm(normal[v]);
      if (!(length > 0) || !std::isfinite(length)) return std::nullopt;  // quads round it cancel out
      polygon.push_back(s.points[v] + (sign * push / length) * normal[v]);
    }
  }
  return pushed;
}

// Row i: bit j is lk(cycle i pushed in, cycle j pushed out) mod 2.
std::optional<std::vector<Words>> linking_matrix(const QuadSurface& s, const SurfaceHomology& h) {
  const auto inner = pushed_cycles(s, h, -1), outer = pushed_cycles(s, h, +1);
  if (!inner || !outer) return std::nullopt;
  std::vector<Words> rows(h.rank(), Words(h.words, 0));
  for (std::size_t i = 0; i < h.rank(); ++i)
    for (std::size_t j = 0; j < h.rank(); ++j) {
      const auto lk = linking_number((*inner)[i], (*outer)[j]);
      if (!lk) return std::nullopt;
      if (*lk % 2 != 0) rows[i][j / 64] |= std::uint64_t{1} << (j % 64);
    }
  return rows;
}

}  // namespace

MeridianReport find_meridians(const QuadSurface& surface, std::size_t alternatives) {
  MeridianReport report;
  const SurfaceHomology h = surface_homology(surface);
  report.genus = static_cast<int>(h.rank() / 2);
  if (h.rank() == 0) return report;
  const auto rows = linking_matrix(surface, h);
  if (!rows) {
    report.determined = false;
    return report;
  }
  MeridianSearch search(surface, h, *rows);
  if (!search.consistent()) {
    report.determined = false;
    return report;
  }
  report.meridians = search.basis();
  report.odd = search.odd();
  report.alternatives = search.alternatives(alternatives);
  return report;
}

std::string describe_cycle(const NodeCycle& cycle, std::size_t shown) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < std::min(cycle.size(), shown); ++i) names.push_back(std::to_string(cycle[i]));
  if (cycle.size() > shown) names.push_back("...");
  if (!cycle.empty()) names.push_back(std::to_string(cycle.front()));
  return fmt::format("{} ({} edges)", fmt::join(names, "-"), cycle.size());
}

}  // namespace loom
