#include "src/check/hex_boundary.hpp"
#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"

namespace loom::gen {

QuadSurface plate_with_holes(int holes, int k) {
  require_at_least("plate", {{"N", holes}, {"K", k}});
  // In 64 bits before anything is made: 2N + 1 alone overflows an int at N = 2^30.
  const std::uint64_t length = 2 * std::uint64_t(holes) + 1, side = std::uint64_t(k);
  require_not_too_large("plate", length * side);
  require_not_too_large("plate", 6 * length * side * side * side);
  HexMesh grid = hexgrid((2 * holes + 1) * k, 3 * k, k);
  for (Vec3& p : grid.points) p = (1.0 / k) * p;
  // Hole h is the unit square [2h+1, 2h+2] x [1, 2].
  std::erase_if(grid.hexes, [&](const Hex& hex) {
    Vec3 centre{0, 0, 0};
    for (std::uint32_t v : hex) centre = centre + 0.125 * grid.points[v];
    const int x = static_cast<int>(centre[0]), y = static_cast<int>(centre[1]);
    return y == 1 && x % 2 == 1;
  });
  return hex_mesh_boundary(grid);
}

}  // namespace loom::gen
