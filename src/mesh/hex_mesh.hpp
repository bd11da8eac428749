#pragma once
// An all-hexahedral mesh: points and hexes in VTK node order. Nodes 0-3 are one
// face, 4-7 the opposite face with i+4 joined to i; a positively oriented hex has
// 4-7 on the side the right-hand normal of 0-1-2-3 points to (the unit cube is
// 0=(0,0,0) 1=(1,0,0) 2=(1,1,0) 3=(0,1,0), 4-7 the same at z=1).
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/vec3.hpp"

namespace loom {

using Hex = std::array<std::uint32_t, 8>;

struct HexMesh {
  std::vector<Vec3> points;
  std::vector<Hex> hexes;
};

}  // namespace loom
