#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"

namespace loom::gen {

HexMesh hexgrid(int a, int b, int c) {
  require_at_least("hexgrid", {{"A", a}, {"B", b}, {"C", c}});
  require_not_too_large("hexgrid", std::uint64_t(a) * std::uint64_t(b) * std::uint64_t(c));
  const std::uint32_t nx = a + 1, ny = b + 1;
  auto node = [&](int i, int j, int k) { return static_cast<std::uint32_t>(i + nx * (j + ny * k)); };
  HexMesh mesh;
  mesh.points.reserve(std::size_t(nx) * ny * (c + 1));
  for (int k = 0; k <= c; ++k)
    for (int j = 0; j <= b; ++j)
      for (int i = 0; i <= a; ++i) mesh.points.push_back({double(i), double(j), double(k)});
  mesh.hexes.reserve(std::size_t(a) * b * c);
  for (int k = 0; k < c; ++k)
    for (int j = 0; j < b; ++j)
      for (int i = 0; i < a; ++i)
        mesh.hexes.push_back({node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                              node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                              node(i, j + 1, k + 1)});
  return mesh;
}

}  // namespace loom::gen
