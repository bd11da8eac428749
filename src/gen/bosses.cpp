// gen::bosses and gen::bosses_free: a box with a cylindrical and a block boss
// on top, meshed all-quad by Gmsh (docs/generators.md), as a block-structured
// mesh or a free (unstructured) one. Gmsh runs in a child process
// (run_gmsh_isolated); the child sends the nodes and quads back as bytes.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <map>
#include <stdexcept>
#include <string_view>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/io/gmsh_session.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

namespace {

constexpr const char* kWhere = "gen bosses";
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
                 "this is a bug in the bosses generator");
    surfaces.push_back(tag);
  }
  return surfaces;
}

void mesh_free(double size) {
  // Gmsh 4.8's names (later versions call them Mesh.MeshSize...). The sizes
  // stored at the OCC points would override the maximum: ignore them.
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", size);
  gmsh::option::setNumber("Mesh.CharacteristicLengthFromPoints", 0);
  gmsh::option::setNumber("Mesh.MinimumCirclePoints", 6);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay (8 crashes Gmsh 4.8.4 here)
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  // Simple recombination, not blossom: Gmsh 4.8.4's blossom breaks ties by
  // memory address, so the same call pairs triangles differently from run to
  // run (2 and 3 throw). Subdivision turns what is left into quads anyway.
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 0);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);    // split into quads only
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::removeDuplicateNodes();
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

// Wire format, native byte order (parent and child are one program):
// node count, then per node its tag and x y z; quad count, then 4 tags each.
template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// `surfaces`: the surfaces whose elements to send (empty: all).
std::string encode_mesh(const std::vector<int>& surfaces) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  if (surfaces.empty()) gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, -1);
  for (int s : surfaces) {
    std::vector<int> t;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(t, tags, nodes, 2, s);
    types.insert(types.end(), t.begin(), t.end());
    element_tags.insert(element_tags.end(), tags.begin(), tags.end());
    element_nodes.insert(element_nodes.end(), nodes.begin(), nodes.end());
  }
  constexpr int gmsh_quad = 3;
  std::string out;
  put<std::uint64_t>(out, node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    put<std::uint64_t>(out, node_tags[i]);
    for (int k = 0; k < 3; ++k) put(out, coordinates[3 * i + k]);
  }
  std::size_t quads = 0;
  for (std::size_t t = 0; t < types.size(); ++t) {
    if (types[t] != gmsh_quad)
      fail_input(kWhere, fmt::format("Gmsh left {} surface elements of type {}", element_tags[t].size(), types[t]),
                 "this is a bug in the bosses generator");
    quads += element_tags[t].size();
  }
  put<std::uint64_t>(out, quads);
  for (std::size_t t = 0; t < types.size(); ++t)
    for (std::size_t tag : element_nodes[t]) put<std::uint64_t>(out, tag);
  return out;
}

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T value{};
    if (pos_ + sizeof value > bytes_.size()) throw std::runtime_error("gen bosses: short message from Gmsh");
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

// Nodes are numbered in order of first use by the quads, so every node is used.
QuadSurface decode_mesh(std::string_view bytes) {
  Reader in(bytes);
  std::map<std::uint64_t, Vec3> position;
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    const auto tag = in.get<std::uint64_t>();
    position[tag] = in.get<Vec3>();
  }
  QuadSurface surface;
  std::map<std::uint64_t, std::uint32_t> index;
  const auto quads = in.get<std::uint64_t>();
  for (std::uint64_t q = 0; q < quads; ++q) {
    Quad quad;
    for (std::uint32_t& corner : quad) {
      const auto tag = in.get<std::uint64_t>();
      auto [it, added] = index.emplace(tag, static_cast<std::uint32_t>(surface.points.size()));
      if (added) surface.points.push_back(position.at(tag));
      corner = it->second;
    }
    surface.quads.push_back(quad);
  }
  return surface;
}

/// Flips quads so that each edge is walked in opposite directions by its two
/// quads (a walk across shared edges from the first quad of each component). A surface that cannot
/// be oriented is left for validation to reject.
void orient_consistently(QuadSurface& surface) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> quads_at;
  auto key = [](std::uint32_t a, std::uint32_t b) { return std::pair{std::min(a, b), std::max(a, b)}; };
  for (std::size_t q = 0; q < surface.quads.size(); ++q)
    for (int i = 0; i < 4; ++i) quads_at[key(surface.quads[q][i], surface.quads[q][(i + 1) % 4])].push_back(q);
  auto walks = [&](std::size_t q, std::uint32_t a, std::uint32_t b) {
    for (int i = 0; i < 4; ++i)
      if (surface.quads[q][i] == a && surface.quads[q][(i + 1) % 4] == b) return true;
    return false;
  };
  std::vector<bool> done(surface.quads.size(), false);
  for (std::size_t start = 0; start < surface.quads.size(); ++start) {
    if (done[start]) continue;
    done[start] = true;
    std::vector<std::size_t> queue{start};
    while (!queue.empty()) {
      const std::size_t q = queue.back();
      queue.pop_back();
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t a = surface.quads[q][i], b = surface.quads[q][(i + 1) % 4];
        for (std::size_t other : quads_at[key(a, b)]) {
          if (done[other]) continue;
          done[other] = true;
          if (walks(other, a, b)) std::reverse(surface.quads[other].begin(), surface.quads[other].end());
          queue.push_back(other);
        }
      }
    }
  }
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
  QuadSurface surface = decode_mesh(run_gmsh_isolated(kWhere, "this is a bug in the bosses generator", [k] {
    const std::vector<int> surfaces = build_block_part();
    mesh_blocks(surfaces, k);
    return encode_mesh(surfaces);
  }));
  // Gmsh orients each patch by its own parametrisation: make the patches
  // agree, then validation turns the whole surface outward if needed.
  orient_consistently(surface);
  validate_surface(surface, kWhere);
  return surface;
}

QuadSurface bosses_free(int k) {
  require_size("bosses-free", k);
  const double size = kCoarseSize / k;
  QuadSurface surface = decode_mesh(run_gmsh_isolated("gen bosses-free", "this is a bug in the bosses generator", [size] {
    build_fused_part();
    mesh_free(size);
    return encode_mesh({});
  }));
  // Subdivision makes the count even: a closed mesh of t triangles and q quads
  // has 3t + 4q = 2 * edges, so t is even, and it becomes 3t + 4q quads.
  if (surface.quads.size() % 2 != 0) throw std::logic_error("gen bosses-free: Gmsh's subdivision gave an odd count");
  orient_consistently(surface);
  validate_surface(surface, "gen bosses-free");
  return surface;
}

}  // namespace loom::gen
