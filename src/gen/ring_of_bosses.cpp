#include <set>

#include "src/check/hex_boundary.hpp"
#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"

namespace loom::gen {

namespace {

/// The cells of the square ring of side `side` in walking order, from (0, 0)
/// along +x, then +y, -x and -y: 4 (side - 1) cells.
std::vector<std::pair<int, int>> ring_cells(int side) {
  std::vector<std::pair<int, int>> cells;
  for (int x = 0; x < side - 1; ++x) cells.emplace_back(x, 0);
  for (int y = 0; y < side - 1; ++y) cells.emplace_back(side - 1, y);
  for (int x = side - 1; x > 0; --x) cells.emplace_back(x, side - 1);
  for (int y = side - 1; y > 0; --y) cells.emplace_back(0, y);
  return cells;
}

}  // namespace

QuadSurface ring_of_bosses(int bosses, int k) {
  require_at_least("ring", {{"N", bosses}, {"K", k}});
  require_not_too_large("ring", std::uint64_t(bosses) * std::uint64_t(k));
  // Three ring cells per boss: two apart, bosses either side of a corner would share an edge.
  int side = 3;
  while (4 * (side - 1) < 3 * bosses) ++side;
  require_not_too_large("ring", 2 * std::uint64_t(side) * side * std::uint64_t(k) * k * k);
  const auto cells = ring_cells(side);
  std::set<std::pair<int, int>> ring(cells.begin(), cells.end()), bossed;
  for (int b = 0; b < bosses; ++b) bossed.insert(cells[std::size_t(b) * cells.size() / std::size_t(bosses)]);

  HexMesh grid = hexgrid(side * k, side * k, 2 * k);
  for (Vec3& p : grid.points) p = (1.0 / k) * p;
  std::erase_if(grid.hexes, [&](const Hex& hex) {
    Vec3 centre{0, 0, 0};
    for (std::uint32_t v : hex) centre = centre + 0.125 * grid.points[v];
    const std::pair<int, int> cell{static_cast<int>(centre[0]), static_cast<int>(centre[1])};
    return centre[2] < 1 ? !ring.contains(cell) : !bossed.contains(cell);
  });
  return hex_mesh_boundary(grid);
}

}  // namespace loom::gen
