#include "src/weave/pipeline.hpp"

#include <chrono>
#include <stdexcept>

#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"

namespace loom::weave {

MeshingResult mesh_surface(const QuadSurface& surface, std::vector<engine::Rule> rules, const WeaveOptions& options) {
  auto start = std::chrono::steady_clock::now();
  MeshingResult r;
  r.stc = stc::build_from_surface(surface);
  r.weave = weave(r.stc, std::move(rules), options);
  if (r.weave.closed) {
    try {
      std::vector<bool> on_boundary;
      HexMesh mesh = stc::to_hex_mesh(r.stc, &on_boundary);
      r.smoothing = smooth_interior(mesh, on_boundary);
      r.check = check_hex_mesh(mesh, &surface);
      r.mesh = std::move(mesh);
    } catch (const std::runtime_error& e) {
      r.failure = e.what();
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace loom::weave
