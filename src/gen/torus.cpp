#include <cmath>
#include <numbers>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

QuadSurface torus(int n, int m) {
  // Fewer than 3 quads around either circle would weld a quad onto itself.
  require_at_least("torus", {{"N", n}, {"M", m}}, 3);
  require_not_too_large("torus", std::uint64_t(n) * std::uint64_t(m));
  if ((n * m) % 2 != 0)
    fail_input("gen torus",
               fmt::format("{} x {} quads is odd, and no hex mesh has an odd number of boundary quads", n, m),
               "make N or M even");
  constexpr double major = 2.0, minor = 1.0;
  auto node = [&](int i, int j) { return static_cast<std::uint32_t>((i % n) * m + (j % m)); };
  QuadSurface s;
  for (int i = 0; i < n; ++i) {
    const double around = 2 * std::numbers::pi * i / n;
    for (int j = 0; j < m; ++j) {
      const double tube = 2 * std::numbers::pi * j / m;
      const double r = major + minor * std::cos(tube);
      s.points.push_back({r * std::cos(around), r * std::sin(around), minor * std::sin(tube)});
    }
  }
  // d/d(around) x d/d(tube) points away from the tube's core: outward.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) s.quads.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
  return s;
}

}  // namespace loom::gen
