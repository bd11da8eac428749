#pragma once
// Solids with handles in mesh_surface (internal to src/pipeline/): cut into a
// ball along meridian disks (handle_cuts.hpp), the ball meshed by
// mesh_surface, its mesh glued back and placed again.
#include <vector>

#include "engine/rule.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace loom::pipeline {

/// A solid with handles, cut into a ball (handle_cuts.hpp), the ball meshed
/// by the whole pipeline, and its mesh glued and placed again, the surface's
/// nodes fixed and the disks' free. The result reports the ball's weave.
void mesh_through_cuts(MeshingResult& r, const QuadSurface& surface, std::vector<engine::Rule> rules,
                       const MeshingOptions& options);

}  // namespace loom::pipeline
