#include "src/weave/pipeline.hpp"

#include <chrono>
#include <stdexcept>

#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"

namespace loom::weave {

namespace {

void weave_once(MeshingResult& r, const QuadSurface& surface, std::vector<engine::Rule> rules,
                const WeaveOptions& options) {
  r.stc = stc::build_from_surface(surface);
  r.weave = weave(r.stc, std::move(rules), options);
  r.mesh.reset();
  r.check.reset();
  r.failure.clear();
  r.smoothing = {};
  if (!r.weave.closed) return;
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

}  // namespace

MeshingResult mesh_surface(const QuadSurface& surface, std::vector<engine::Rule> rules, const WeaveOptions& options) {
  auto start = std::chrono::steady_clock::now();
  MeshingResult r;
  WeaveOptions attempt = options;
  const std::uint64_t first_seed = options.strategy.kind == engine::Strategy::Kind::random ? options.strategy.seed : 0;
  for (r.attempts = 1;; ++r.attempts) {
    r.strategy = attempt.strategy;
    weave_once(r, surface, rules, attempt);
    if (r.combinatorially_valid() || r.attempts >= options.attempts) break;
    attempt.strategy = engine::Strategy::parse("random");
    attempt.strategy.seed = first_seed + r.attempts;
    if (options.before_attempt) options.before_attempt(r.attempts + 1, attempt.strategy);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace loom::weave
