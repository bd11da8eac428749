#include "src/pipeline/candidate.hpp"

#include <fmt/format.h>

#include "src/geometry/boundary_layer.hpp"

namespace loom::pipeline {

using closure::HexSource;

namespace {

/// The boundary layer pillowed into the candidate and its nodes placed; false
/// (and nothing changed) when the result fails criteria 1-6 or, with
/// `only_if_better`, is not better than the candidate as it is.
bool place_with_boundary_layer(Candidate& c, const QuadSurface& surface, bool only_if_better) {
  HexMesh pillowed = c.mesh;
  std::vector<bool> fixed = c.fixed;
  const auto layer = geometry::pillow_boundary_layer(pillowed, fixed);
  auto placed = weave::smooth_interior(pillowed, fixed);
  auto check = check_hex_mesh(pillowed, &surface);
  if (!check.combinatorial_valid() || (only_if_better && !improves(placed, c.smoothing))) return false;
  c.source.resize(pillowed.hexes.size(), HexSource::pillow);
  c.mesh = std::move(pillowed);
  c.smoothing = placed;
  c.check = std::move(check);
  c.layer = layer;
  return true;
}

}  // namespace

bool improves(const weave::SmoothingReport& a, const weave::SmoothingReport& b) {
  if (a.below_zero_after != b.below_zero_after) return a.below_zero_after < b.below_zero_after;
  return a.below_0_2_after < b.below_0_2_after;
}

void place(Candidate& c, const QuadSurface& surface, MeshingResult& r) {
  const PlacementTally tally(r);
  const auto locked = geometry::locked_corners(c.mesh, c.fixed);
  if (locked.below_0_2 > 0 && place_with_boundary_layer(c, surface, false)) return;
  c.smoothing = weave::smooth_interior(c.mesh, c.fixed);
  c.check = check_hex_mesh(c.mesh, &surface);
  if (locked.below_0_2 == 0 && c.valid() && (c.smoothing.below_zero_after > 0 || c.smoothing.below_0_2_after > 0))
    place_with_boundary_layer(c, surface, true);
}

std::string Candidate::why_invalid() const {
  if (!check) return "the mesh was not checked";
  const auto* f = check->first_failure();
  return f ? fmt::format("criterion {} ({}) fails: {}", f->number, f->name, f->detail) : "";
}

void adopt(MeshingResult& r, Candidate&& c, std::string made_by) {
  r.mesh = std::move(c.mesh);
  r.source = std::move(c.source);
  r.check = std::move(c.check);
  r.smoothing = c.smoothing;
  r.boundary_layer = c.layer;
  r.made_by = std::move(made_by);
}

}  // namespace loom::pipeline
