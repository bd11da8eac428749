// The cylinder: an O-grid disk (centre square plus four ring blocks) swept along
// the z axis, as a hex mesh and as its boundary surface.
#include <cmath>
#include <numbers>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"

namespace loom::gen {

namespace {

constexpr double kHalfSquare = 0.5;  // half-width of the centre square; the rim has radius 1
constexpr double kHeight = 2.0;

struct Point2 {
  double x, y;
};

/// The cap's quad mesh in the plane, quads counter-clockwise seen from +z.
struct Disk {
  std::vector<Point2> points;
  std::vector<Quad> quads;
  std::vector<std::uint32_t> rim;  ///< the 4n rim nodes, counter-clockwise
};

Disk ogrid_disk(int n) {
  const int d = cylinder_ring_depth(n);
  const int around = 4 * n;
  Disk disk;
  auto grid = [&](int i, int j) { return static_cast<std::uint32_t>(i + (n + 1) * j); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      disk.points.push_back({-kHalfSquare + 2 * kHalfSquare * i / n, -kHalfSquare + 2 * kHalfSquare * j / n});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) disk.quads.push_back({grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)});

  // The square's boundary, counter-clockwise from the corner (s,-s); it is ring layer 0.
  std::vector<std::uint32_t> square_rim;
  for (int k = 0; k < around; ++k) {
    const int side = k / n, t = k % n;
    switch (side) {
      case 0:
        square_rim.push_back(grid(n, t));
        break;
      case 1:
        square_rim.push_back(grid(n - t, n));
        break;
      case 2:
        square_rim.push_back(grid(0, n - t));
        break;
      default:
        square_rim.push_back(grid(t, 0));
        break;
    }
  }
  std::vector<std::vector<std::uint32_t>> ring{square_rim};
  for (int r = 1; r <= d; ++r) {
    std::vector<std::uint32_t> layer;
    for (int k = 0; k < around; ++k) {
      const double angle = -std::numbers::pi / 4 + k * (std::numbers::pi / 2) / n;
      const Point2 inner = disk.points[square_rim[k]], outer{std::cos(angle), std::sin(angle)};
      const double t = double(r) / d;
      layer.push_back(static_cast<std::uint32_t>(disk.points.size()));
      disk.points.push_back(r == d ? outer
                                   : Point2{inner.x + t * (outer.x - inner.x), inner.y + t * (outer.y - inner.y)});
    }
    ring.push_back(std::move(layer));
  }
  for (int r = 0; r < d; ++r)
    for (int k = 0; k < around; ++k) {
      const int next = (k + 1) % around;
      disk.quads.push_back({ring[r][k], ring[r + 1][k], ring[r + 1][next], ring[r][next]});
    }
  disk.rim = ring.back();
  return disk;
}

double layer_height(int layer, int h) { return kHeight * layer / h; }

void check_cylinder_args(const char* kind, int n, int h, bool hexes) {
  require_at_least(kind, {{"N", n}, {"H", h}});
  const std::uint64_t un = n, uh = h, d = cylinder_ring_depth(n);
  const std::uint64_t cap = un * un + 4 * un * d;
  require_not_too_large(kind, hexes ? cap * uh : 2 * cap + 4 * un * uh);
}

}  // namespace

int cylinder_ring_depth(int n) { return (n + 1) / 2; }

HexMesh ogrid_cylinder(int n, int h) {
  check_cylinder_args("ogrid", n, h, true);
  const Disk disk = ogrid_disk(n);
  const auto per_layer = static_cast<std::uint32_t>(disk.points.size());
  HexMesh mesh;
  for (int layer = 0; layer <= h; ++layer)
    for (const auto& p : disk.points) mesh.points.push_back({p.x, p.y, layer_height(layer, h)});
  for (int layer = 0; layer < h; ++layer) {
    const std::uint32_t lo = layer * per_layer, hi = lo + per_layer;
    for (const auto& q : disk.quads)
      mesh.hexes.push_back({q[0] + lo, q[1] + lo, q[2] + lo, q[3] + lo, q[0] + hi, q[1] + hi, q[2] + hi, q[3] + hi});
  }
  return mesh;
}

QuadSurface cylinder(int n, int h) {
  check_cylinder_args("cylinder", n, h, false);
  const Disk disk = ogrid_disk(n);
  const auto per_cap = static_cast<std::uint32_t>(disk.points.size());
  QuadSurface s;
  for (int cap : {0, h})
    for (const auto& p : disk.points) s.points.push_back({p.x, p.y, layer_height(cap, h)});
  for (const auto& q : disk.quads) s.quads.push_back({q[0], q[3], q[2], q[1]});  // bottom faces -z
  for (const auto& q : disk.quads) s.quads.push_back({q[0] + per_cap, q[1] + per_cap, q[2] + per_cap, q[3] + per_cap});

  // Rim nodes per layer: the caps' rims at the ends, new nodes in between.
  const std::size_t around = disk.rim.size();
  std::vector<std::vector<std::uint32_t>> rim(h + 1);
  for (std::uint32_t node : disk.rim) {
    rim[0].push_back(node);
    rim[h].push_back(node + per_cap);
  }
  for (int layer = 1; layer < h; ++layer)
    for (std::uint32_t node : disk.rim) {
      rim[layer].push_back(static_cast<std::uint32_t>(s.points.size()));
      s.points.push_back({disk.points[node].x, disk.points[node].y, layer_height(layer, h)});
    }
  for (int layer = 0; layer < h; ++layer)
    for (std::size_t k = 0; k < around; ++k) {
      const std::size_t next = (k + 1) % around;
      s.quads.push_back({rim[layer][k], rim[layer][next], rim[layer + 1][next], rim[layer + 1][k]});
    }
  return s;
}

}  // namespace loom::gen
