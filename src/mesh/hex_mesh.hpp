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

/// The same hex with its two faces 0-3 and 4-7 swapped: a hex read in a
/// mirror image is left-handed, and this makes it right-handed again.
inline Hex mirror_hex(const Hex& h) { return {h[4], h[5], h[6], h[7], h[0], h[1], h[2], h[3]}; }

}  // namespace loom
