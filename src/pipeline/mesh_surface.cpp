#include "src/weave/pipeline.hpp"

#include <chrono>
#include <stdexcept>

#include "src/fill/fill.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/util/error.hpp"

namespace loom::weave {

namespace {

/// Fewer hexes <= 0, or as many and fewer < 0.2.
bool improves(const SmoothingReport& a, const SmoothingReport& b) {
  if (a.below_zero_after != b.below_zero_after) return a.below_zero_after < b.below_zero_after;
  return a.below_0_2_after < b.below_0_2_after;
}

/// The boundary layer pillowed into `mesh` and the nodes placed; false (and
/// nothing changed) when the result fails criteria 1-6 or, with `only_if_better`,
/// is not better than what r.smoothing says of the mesh without it.
bool place_with_boundary_layer(MeshingResult& r, HexMesh& mesh, std::vector<bool> fixed, const QuadSurface& surface,
                               bool only_if_better) {
  HexMesh pillowed = mesh;
  const auto layer = geometry::pillow_boundary_layer(pillowed, fixed);
  auto placed = smooth_interior(pillowed, fixed);
  auto check = check_hex_mesh(pillowed, &surface);
  if (!check.combinatorial_valid() || (only_if_better && !improves(placed, r.smoothing))) return false;
  mesh = std::move(pillowed);
  r.smoothing = placed;
  r.check = std::move(check);
  r.boundary_layer = layer;
  return true;
}

/// Node placement, and the boundary layer when it helps. A woven hex with two
/// faces on one flat part of the boundary has corners whose four nodes are
/// all on the boundary: locked, whatever placement does. When some locked
/// corner is below 0.2 the layer goes in first (placing the mesh without it
/// would be wasted work); otherwise the mesh is placed, and a layer is tried
/// when hexes <= 0 or < 0.2 are left, and kept when it does better.
void place(MeshingResult& r, HexMesh& mesh, const std::vector<bool>& on_boundary, const QuadSurface& surface) {
  const auto locked = geometry::locked_corners(mesh, on_boundary);
  if (locked.below_0_2 > 0 && place_with_boundary_layer(r, mesh, on_boundary, surface, false)) return;
  r.smoothing = smooth_interior(mesh, on_boundary);
  r.check = check_hex_mesh(mesh, &surface);
  if (locked.below_0_2 == 0 && r.check->combinatorial_valid() &&
      (r.smoothing.below_zero_after > 0 || r.smoothing.below_0_2_after > 0))
    place_with_boundary_layer(r, mesh, on_boundary, surface, true);
}

void weave_once(MeshingResult& r, const QuadSurface& surface, std::vector<engine::Rule> rules,
                const WeaveOptions& options) {
  r.stc = stc::build_from_surface(surface);
  r.weave = weave(r.stc, std::move(rules), options);
  r.mesh.reset();
  r.check.reset();
  r.failure.clear();
  r.smoothing = {};
  r.boundary_layer = {};
  if (!r.weave.closed) return;
  try {
    std::vector<bool> on_boundary;
    HexMesh mesh = stc::to_hex_mesh(r.stc, &on_boundary);
    place(r, mesh, on_boundary, surface);
    r.mesh = std::move(mesh);
  } catch (const std::runtime_error& e) {
    r.failure = e.what();
  }
}

/// The constructive fill in place of a weave. Its nodes are smoothed, not
/// place()d: the caps are pillowed, so no hex has two faces on the boundary
/// and a boundary layer (place's second resort) could unlock nothing.
void fill_instead(MeshingResult& r, const QuadSurface& surface, const std::filesystem::path& caps) {
  try {
    fill::FilledMesh f = fill::fill_constructively(surface, fill::load_caps(caps));
    r.boundary_layer = {};
    r.failure.clear();
    r.smoothing = smooth_interior(f.mesh, f.on_boundary);
    r.check = check_hex_mesh(f.mesh, &surface);
    r.mesh = std::move(f.mesh);
    r.filled = true;
  } catch (const InputError& e) {
    r.fill_failure = e.what();
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
    if (options.before_attempt) options.before_attempt(r.attempts + 1, attempt.strategy, r.weave);
  }
  if (!r.combinatorially_valid() && !options.fill_caps.empty()) fill_instead(r, surface, options.fill_caps);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace loom::weave
