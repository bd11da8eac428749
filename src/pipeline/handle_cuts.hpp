#pragma once
// A solid with handles meshed as a ball: cut open along one disk per meridian
// (meridians.hpp), each disk given a quad grid, the ball meshed like any
// genus-0 surface, and the two copies of every disk glued back together.
//
// Cutting the surface along a meridian C splits each node of C in two: the
// quads on C's left keep the node, those on its right get a copy. Each side's
// hole is closed by a copy of the disk, an a x b grid with 2(a + b) = |C|
// whose inner nodes sit on the Coons patch of C. The two sides are pushed
// apart along the disk's normal, each by a quarter of the shortest edge on
// or leaving C, so that the ball's surface does not touch itself; gluing puts
// them back.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/meridians.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::pipeline {

struct CutSurface {
  QuadSurface ball;
  /// For each node of `ball`, the node of the glued mesh it becomes: a node of
  /// the surface cut, or surface.points.size() + k for disk node k.
  std::vector<std::uint32_t> glued;
  std::vector<Vec3> disk_points;  ///< the disks' inner nodes, on their patches
  int disks = 0;
};

/// The surface cut along one disk spanning `meridian`, or why not: it must be
/// a simple cycle of at least 4 edges, an even number.
std::optional<CutSurface> cut_along_disk(const QuadSurface& surface, const NodeCycle& meridian, std::string& why_not);

/// The surface cut along a disk spanning the shortest meridian found that takes one, again
/// and again until it is a ball (genus 0), or why not. Each cut lowers the
/// genus by one; the meridians are found afresh each time, so later disks may
/// cross the earlier ones' sides.
std::optional<CutSurface> cut_into_ball(const QuadSurface& surface, std::string& why_not);

/// A hex mesh of the ball (its boundary nodes where `cut.ball` has them) glued
/// into one of the solid: the surface's nodes first, in its order, then the
/// disks' inner nodes, then the ball's inner nodes. `fixed` marks the surface's.
HexMesh glue_disks(const HexMesh& ball_mesh, const CutSurface& cut, const QuadSurface& surface, std::vector<bool>& fixed);

}  // namespace loom::pipeline
