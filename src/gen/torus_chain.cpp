#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

QuadSurface torus_chain(int n, const std::vector<int>& tubes) {
  const std::string kind = tubes.size() == 2 ? "double-torus" : "torus chain";
  require_at_least(kind, {{"N", n}}, tubes.size() > 1 ? 4 : 3);
  std::uint64_t quads = 0;
  for (int m : tubes) {
    require_at_least(kind, {{"M", m}}, 3);
    quads += std::uint64_t(n) * std::uint64_t(m) + 2;
  }
  require_not_too_large(kind, quads);
  if (tubes.size() > 1 && n % 2 != 0)
    fail_input(kind, fmt::format("N = {} is odd, but each torus needs a quad facing the next one and one facing the last", n),
               "make N even");
  constexpr double major = 2.0, minor = 1.0, spacing = 7.0;  // tori 1 apart at their nearest
  QuadSurface s;
  std::vector<std::uint32_t> first_node;
  for (std::size_t t = 0; t < tubes.size(); ++t) {
    const int m = tubes[t];
    first_node.push_back(static_cast<std::uint32_t>(s.points.size()));
    // Half a quad off, so that quad (0, 0) faces +x and quad (n/2, 0) faces -x.
    for (int i = 0; i < n; ++i) {
      const double around = 2 * std::numbers::pi * (i - 0.5) / n;
      for (int j = 0; j < m; ++j) {
        const double tube = 2 * std::numbers::pi * (j - 0.5) / m;
        const double r = major + minor * std::cos(tube);
        s.points.push_back({spacing * static_cast<double>(t) + r * std::cos(around), r * std::sin(around),
                            minor * std::sin(tube)});
      }
    }
  }
  auto node = [&](std::size_t t, int i, int j) {
    return first_node[t] + static_cast<std::uint32_t>((i % n) * tubes[t] + (j % tubes[t]));
  };
  for (std::size_t t = 0; t < tubes.size(); ++t)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < tubes[t]; ++j) {
        const bool towards_next = t + 1 < tubes.size() && i == 0 && j == 0;
        const bool towards_last = t > 0 && i == n / 2 && j == 0;
        if (!towards_next && !towards_last)
          s.quads.push_back({node(t, i, j), node(t, i + 1, j), node(t, i + 1, j + 1), node(t, i, j + 1)});
      }
  // A straight tube of four quads from each torus's +x hole to the next one's
  // -x hole. Corner k of the +x hole faces corner facing[k] of the -x hole (the
  // same y and z); each tube quad runs along the hole's edge the way the
  // removed quad did, which keeps the orientation outward.
  for (std::size_t t = 0; t + 1 < tubes.size(); ++t) {
    const std::array<std::uint32_t, 4> here{node(t, 0, 0), node(t, 1, 0), node(t, 1, 1), node(t, 0, 1)};
    const std::array<std::uint32_t, 4> there{node(t + 1, n / 2, 0), node(t + 1, n / 2 + 1, 0),
                                             node(t + 1, n / 2 + 1, 1), node(t + 1, n / 2, 1)};
    constexpr std::array<int, 4> facing{1, 0, 3, 2};
    for (int k = 0; k < 4; ++k)
      s.quads.push_back({here[k], here[(k + 1) % 4], there[facing[(k + 1) % 4]], there[facing[k]]});
  }
  return s;
}

}  // namespace loom::gen
