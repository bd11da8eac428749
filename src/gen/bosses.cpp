// gen::bosses and gen::bosses_free: a box with a cylindrical and a block boss
// on top, meshed all-quad by Gmsh (docs/generators.md), as a block-structured
// mesh or a free (unstructured) one. Gmsh runs in a child process
// (run_gmsh_isolated); the child sends the nodes and quads back as bytes.
#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "src/cad/gmsh_quads.hpp"
#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/io/gmsh_session.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

namespace {

constexpr const char* kWhere = "gen bosses";
constexpr const char* kHint = "this is a bug in the bosses generator";
// Free variant: element size for K = 1; K divides it, and subdivision then halves every
// edge. For small K the count is set as much by the part's short edges and
// the circles' minimum of 6 points as by the size (K = 1: ~230 quads).
constexpr double kCoarseSize = 3.0;
// K = 50 gives about 130,000 quads (free, 4 s) or 700,000 (blocks, 17 s).
constexpr int kMaxSize = 50;

// The part, in its own units: the base [0,6]x[0,4]x[0,1.5], a cylinder of
// radius 0.8 around (1.75, 2) up to z = 3, a block [3.5,5.5]x[1,3] up to z = 2.5.
constexpr double kCx = 1.75, kCy = 2, kRadius = 0.8;
// The block decomposition's O-grid round the cylinder: an inner square of
// half-width kInner, and an outer square of half-width kOuter (its sides lie
// on the lines y = 1 and y = 3 that also bound the block boss).
constexpr double kInner = 0.3, kOuter = 1.0;

// Free variant: one fused volume. The bosses start inside the base so that
// the fuse meets volumes, not faces.
void build_fused_part() {
  const int base = gmsh::model::occ::addBox(0, 0, 0, 6, 4, 1.5);
  const int cylinder = gmsh::model::occ::addCylinder(kCx, kCy, 1, 0, 0, 2, kRadius);
  const int block = gmsh::model::occ::addBox(3.5, 1, 1, 2, 2, 1.5);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> origins;
  gmsh::model::occ::fuse({{3, base}}, {{3, cylinder}, {3, block}}, fused, origins);
  gmsh::model::occ::synchronize();
  if (fused.size() != 1) fail_input(kWhere, fmt::format("the fuse gave {} volumes, not one", fused.size()));
}

/// A vertical planar quad over the segment (x0,y0)-(x1,y1), z from z0 to z1.
int vertical_face(double x0, double y0, double x1, double y1, double z0, double z1) {
  namespace occ = gmsh::model::occ;
  const int a = occ::addPoint(x0, y0, z0), b = occ::addPoint(x1, y1, z0);
  const int c = occ::addPoint(x1, y1, z1), d = occ::addPoint(x0, y0, z1);
  return occ::addPlaneSurface(
      {occ::addCurveLoop({occ::addLine(a, b), occ::addLine(b, c), occ::addLine(c, d), occ::addLine(d, a)})});
}

// Block variant: the same part cut into 29 topological cubes (a grid of
// columns in the base, the block boss, and an O-grid round the cylinder
// through base and boss) by fragmenting with the cutting faces. Every face on
// the boundary is then four-sided. Returns the boundary surfaces.
std::vector<int> build_block_part() {
  namespace occ = gmsh::model::occ;
  gmsh::vectorpair object{{3, occ::addBox(0, 0, 0, 6, 4, 1.5)}}, tools;
  tools.push_back({3, occ::addBox(3.5, 1, 0, 2, 2, 2.5)});
  tools.push_back({3, occ::addBox(kCx - kInner, kCy - kInner, 0, 2 * kInner, 2 * kInner, 3)});
  tools.push_back({3, occ::addBox(kCx - kOuter, kCy - kOuter, 0, 2 * kOuter, 2 * kOuter, 1.5)});
  const int cylinder = occ::addCylinder(kCx, kCy, 0, 0, 0, 3, kRadius);
  // OCC's cylinder has a seam at angle 0: turned onto a diagonal, it is one of the cuts.
  occ::rotate({{3, cylinder}}, kCx, kCy, 0, 0, 0, 1, std::numbers::pi / 4);
  tools.push_back({3, cylinder});
  for (double y : {1.0, 3.0}) tools.push_back({2, vertical_face(0, y, 6, y, 0, 1.5)});
  for (double x : {kCx - kOuter, kCx + kOuter, 3.5, 5.5}) tools.push_back({2, vertical_face(x, 0, x, 4, 0, 1.5)});
  for (int i = 0; i < 4; ++i) {  // the O-grid's diagonals, from the inner square's corners to the outer's
    const double a = std::numbers::pi / 4 + i * std::numbers::pi / 2;
    const double ux = std::numbers::sqrt2 * std::cos(a), uy = std::numbers::sqrt2 * std::sin(a);
    tools.push_back({2, vertical_face(kCx + kInner * ux, kCy + kInner * uy, kCx + kOuter * ux, kCy + kOuter * uy, 0, 3)});
  }
  gmsh::vectorpair pieces;
  std::vector<gmsh::vectorpair> origins;
  occ::fragment(object, tools, pieces, origins);
  occ::synchronize();
  gmsh::vectorpair volumes, boundary;
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::getBoundary(volumes, boundary, true, false, false);
  std::vector<int> surfaces;
  for (const auto& [dim, tag] : boundary) {
    gmsh::vectorpair curves;
    gmsh::model::getBoundary({{2, tag}}, curves, false, false, false);
    if (curves.size() != 4)
      fail_input(kWhere, fmt::format("boundary surface {} of the block decomposition has {} sides, not 4", tag,
                                     curves.size()),
                 kHint);
    surfaces.push_back(tag);
  }
  return surfaces;
}

// Every curve gets 2k edges, so each four-sided patch is a 2k x 2k grid
// whose opposite sides agree, and the count (patches x 4k^2) is even.
void mesh_blocks(const std::vector<int>& surfaces, int k) {
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) gmsh::model::mesh::setTransfiniteCurve(tag, 2 * k + 1);
  for (int s : surfaces) {
    gmsh::model::mesh::setTransfiniteSurface(s);
    gmsh::model::mesh::setRecombine(2, s);
  }
  gmsh::model::mesh::generate(2);
}

void require_size(const char* kind, int k) {
  require_at_least(kind, {{"K", k}});
  if (k > kMaxSize)
    fail_input(fmt::format("gen {}", kind), fmt::format("K is {}, more than the limit of {}", k, kMaxSize),
               "choose a smaller K");
}

}  // namespace

QuadSurface bosses(int k) {
  require_size("bosses", k);
  QuadSurface surface = cad::decode_quads(run_gmsh_isolated(kWhere, kHint, [k] {
    const std::vector<int> surfaces = build_block_part();
    mesh_blocks(surfaces, k);
    return cad::encode_quads(surfaces, kWhere, kHint);
  }), kWhere);
  // Make the patches agree; validation then turns the whole surface outward if needed.
  cad::orient_consistently(surface);
  validate_surface(surface, kWhere);
  return surface;
}

QuadSurface bosses_free(int k) {
  require_size("bosses-free", k);
  const double size = kCoarseSize / k;
  const std::string where = "gen bosses-free";
  QuadSurface surface = cad::decode_quads(run_gmsh_isolated(where, kHint, [size, &where] {
    build_fused_part();
    cad::mesh_free_quads(size);
    return cad::encode_quads({}, where, kHint);
  }), where);
  if (surface.quads.size() % 2 != 0) throw std::logic_error("gen bosses-free: Gmsh's subdivision gave an odd count");
  cad::orient_consistently(surface);
  validate_surface(surface, "gen bosses-free");
  return surface;
}

}  // namespace loom::gen
