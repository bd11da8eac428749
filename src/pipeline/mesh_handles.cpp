#include "src/pipeline/mesh_handles.hpp"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "src/geometry/boundary_layer.hpp"
#include "src/pipeline/candidate.hpp"
#include "src/pipeline/handle_cuts.hpp"

namespace loom::pipeline {

void mesh_through_cuts(MeshingResult& r, const QuadSurface& surface, std::vector<engine::Rule> rules,
                       const MeshingOptions& options) {
  if (options.on_stage) options.on_stage("cutting along meridian disks");
  std::string why_not;
  const auto cut = cut_into_ball(surface, why_not);
  if (!cut) {
    r.closure_failure = "the solid could not be cut into a ball: " + why_not;
    return;
  }
  MeshingResult ball = mesh_surface(cut->ball, std::move(rules), options);
  r.placements += ball.placements;
  r.placement_seconds += ball.placement_seconds;
  const std::string disks = fmt::format("{} disk{}", cut->disks, cut->disks == 1 ? "" : "s");
  if (!ball.combinatorially_valid()) {
    const std::string& why = !ball.closure_failure.empty() ? ball.closure_failure
                             : !ball.failure.empty()       ? ball.failure
                                                           : ball.fill_failure;
    r.closure_failure = fmt::format("cut along {} into a ball, which got no mesh: {}", disks, why);
    return;
  }
  // The ball's boundary layer covers the disks too, two sheets inside the
  // solid once glued. Taken back, the solid is placed (and given its own
  // layer) as a whole; but the sheets give the nodes by the disks room, so
  // both are placed and the better kept (torus 3 x 16: 0.140 with them, -0.510
  // without), on a tie the one without.
  auto glued = [&](bool without_layer) {
    Candidate c;
    HexMesh ball_mesh = *ball.mesh;
    c.source = ball.source;
    geometry::BoundaryLayerReport kept_layer;  // the ball's, when not taken back
    if (without_layer && geometry::remove_boundary_layer(ball_mesh, ball.boundary_layer.hexes_added))
      c.source.resize(ball_mesh.hexes.size());
    else
      kept_layer = ball.boundary_layer;
    c.mesh = glue_disks(ball_mesh, *cut, surface, c.fixed);
    place(c, surface, r);  // sets c.layer when it adds one
    c.layer.hexes_added += kept_layer.hexes_added;
    c.layer.nodes_added += kept_layer.nodes_added;
    return c;
  };
  Candidate c;
  try {
    if (options.on_stage) options.on_stage("placing the glued solid");
    c = glued(true);
    if (ball.boundary_layer.hexes_added > 0) {
      Candidate with_sheets = glued(false);
      if (with_sheets.valid() && (!c.valid() || improves(with_sheets.smoothing, c.smoothing))) c = std::move(with_sheets);
    }
  } catch (const std::runtime_error& e) {
    r.closure_failure = fmt::format("cut along {} into a ball and meshed it, but could not glue it back: {}", disks, e.what());
    return;
  }
  if (!c.valid()) {
    r.closure_failure = fmt::format("cut along {} into a ball and meshed it, but glued back {}", disks, c.why_invalid());
    return;
  }
  r.attempts_before_cut = r.attempts;
  r.stc = std::move(ball.stc);
  r.weave = std::move(ball.weave);
  r.closure = ball.closure;
  r.strategy = ball.strategy;
  r.attempts += ball.attempts;
  r.wide_search_stopped = ball.wide_search_stopped;
  adopt(r, std::move(c), ball.made_by);
  r.cut_disks = cut->disks;
  r.woven_attempt = ball.woven_attempt == 0 ? 0 : r.attempts_before_cut + ball.woven_attempt;
}

}  // namespace loom::pipeline
