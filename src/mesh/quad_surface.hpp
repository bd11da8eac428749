#pragma once
// A quadrilateral surface mesh: points and quads (0-based point indices, counter-
// clockwise seen from outside when the surface is oriented outward).
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/vec3.hpp"

namespace loom {

using Quad = std::array<std::uint32_t, 4>;

struct QuadSurface {
  std::vector<Vec3> points;
  std::vector<Quad> quads;
};

}  // namespace loom
