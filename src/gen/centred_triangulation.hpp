#pragma once
// A quadrangulation with a centre node added in every quad, joined to its four
// corners: a triangulation of the sphere, which the randquad embedding lays out
// (gen::embed_on_sphere). A layout in which every one of its triangles turns
// counter-clockwise seen from outside draws each quad as a simple polygon,
// star-shaped around its centre.
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::gen {

using Triangle = std::array<std::uint32_t, 3>;

struct CentredTriangulation {
  std::size_t corner_count = 0;                        ///< quad f's centre is node corner_count + f
  std::vector<Triangle> triangles;                     ///< counter-clockwise seen from outside; 4f..4f+3 in quad f
  std::vector<std::vector<std::uint32_t>> neighbours;  ///< per node
  std::vector<std::vector<std::uint32_t>> fan;         ///< per node, the triangles around it

  CentredTriangulation(const std::vector<Quad>& quads, std::size_t node_count)
      : corner_count(node_count), neighbours(node_count + quads.size()), fan(node_count + quads.size()) {
    for (std::size_t f = 0; f < quads.size(); ++f) {
      const auto centre = static_cast<std::uint32_t>(node_count + f);
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t a = quads[f][k], b = quads[f][(k + 1) % 4];
        // Each edge is run once in each direction, so this lists each neighbour once.
        neighbours[a].push_back(b);
        neighbours[a].push_back(centre);
        neighbours[centre].push_back(a);
        const auto t = static_cast<std::uint32_t>(triangles.size());
        triangles.push_back({a, b, centre});
        for (std::uint32_t node : triangles.back()) fan[node].push_back(t);
      }
    }
  }
};

/// Positive when the triangle turns counter-clockwise seen from outside (for
/// points on the unit sphere: it is also less than a hemisphere).
inline double turning(const std::vector<Vec3>& p, const Triangle& t) {
  return dot(p[t[0]], cross(p[t[1]], p[t[2]]));
}

inline std::size_t clockwise_in_fan(const std::vector<Vec3>& p, const CentredTriangulation& mesh, std::uint32_t node) {
  std::size_t count = 0;
  for (std::uint32_t t : mesh.fan[node]) count += turning(p, mesh.triangles[t]) <= 0;
  return count;
}

inline std::size_t clockwise_triangles(const std::vector<Vec3>& p, const CentredTriangulation& mesh) {
  std::size_t count = 0;
  for (const Triangle& t : mesh.triangles) count += turning(p, t) <= 0;
  return count;
}

}  // namespace loom::gen
