// Surfaces of boxes and of shapes made from boxes, on an integer lattice.
#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/gen/lattice_surface.hpp"

namespace loom::gen {

namespace {
void add_box(LatticeSurface& s, std::int64_t a, std::int64_t b, std::int64_t c) {
  s.add_axis_rect(2, 0, -1, 0, a, 0, b);
  s.add_axis_rect(2, c, +1, 0, a, 0, b);
  s.add_axis_rect(1, 0, -1, 0, c, 0, a);
  s.add_axis_rect(1, b, +1, 0, c, 0, a);
  s.add_axis_rect(0, 0, -1, 0, b, 0, c);
  s.add_axis_rect(0, a, +1, 0, b, 0, c);
}
}  // namespace

QuadSurface box(int a, int b, int c) {
  require_at_least("box", {{"A", a}, {"B", b}, {"C", c}});
  const std::uint64_t ua = a, ub = b, uc = c;
  require_not_too_large("box", 2 * (ua * ub + ub * uc + uc * ua));
  LatticeSurface s;
  add_box(s, a, b, c);
  return s.finish(1.0);
}

QuadSurface lshape(int n) {
  require_at_least("lshape", {{"N", n}});
  require_not_too_large("lshape", 14 * std::uint64_t(n) * std::uint64_t(n));
  // Lattice unit 1/n: the blocks are [0,2n]x[0,n]x[0,n] and [0,n]x[n,2n]x[0,n].
  const std::int64_t m = n;
  LatticeSurface s;
  for (auto [level, sign] : {std::pair<std::int64_t, int>{0, -1}, {m, +1}}) {
    s.add_axis_rect(2, level, sign, 0, 2 * m, 0, m);
    s.add_axis_rect(2, level, sign, 0, m, m, 2 * m);
  }
  s.add_axis_rect(1, 0, -1, 0, m, 0, 2 * m);  // y = 0
  s.add_axis_rect(0, 2 * m, +1, 0, m, 0, m);  // x = 2
  s.add_axis_rect(1, m, +1, 0, m, m, 2 * m);  // y = 1, the inner corner's x > 1 side
  s.add_axis_rect(0, m, +1, m, 2 * m, 0, m);  // x = 1, the inner corner's y > 1 side
  s.add_axis_rect(1, 2 * m, +1, 0, m, 0, m);  // y = 2
  s.add_axis_rect(0, 0, -1, 0, 2 * m, 0, m);  // x = 0
  return s.finish(static_cast<double>(n));
}

QuadSurface cubesphere(int n) {
  require_at_least("cubesphere", {{"N", n}});
  require_not_too_large("cubesphere", 6 * std::uint64_t(n) * std::uint64_t(n));
  // The cube [0,n]^3 scaled to [0,2]^3, shifted to [-1,1]^3 and projected.
  LatticeSurface s;
  add_box(s, n, n, n);
  QuadSurface sphere = s.finish(n / 2.0);
  for (auto& p : sphere.points) {
    p = p - Vec3{1.0, 1.0, 1.0};
    p = (1.0 / norm(p)) * p;
  }
  return sphere;
}

}  // namespace loom::gen
