// gen::bosses: a box with a cylindrical and a block boss on top, meshed all-quad
// by Gmsh (docs/generators.md). Gmsh runs in a child process
// (run_gmsh_isolated); the child sends the nodes and quads back as bytes.
#include <gmsh.h>

#include <cstring>
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
// Element size for K = 1; K divides it, and subdivision then halves every
// edge. For small K the count is set as much by the part's short edges and
// the circles' minimum of 6 points as by the size (K = 1: ~230 quads).
constexpr double kCoarseSize = 3.0;
// K = 50 gives about 130,000 quads in a few seconds.
constexpr int kMaxSize = 50;

// The part, in its own units: the base [0,6]x[0,4]x[0,1.5], a cylinder of
// radius 1 around (1.75, 2) up to z = 3, a block [3.5,5.5]x[1,3] up to z = 2.5.
// The bosses start inside the base so that the fuse meets volumes, not faces.
void build_part() {
  const int base = gmsh::model::occ::addBox(0, 0, 0, 6, 4, 1.5);
  const int cylinder = gmsh::model::occ::addCylinder(1.75, 2, 1, 0, 0, 2, 1);
  const int block = gmsh::model::occ::addBox(3.5, 1, 1, 2, 2, 1.5);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> origins;
  gmsh::model::occ::fuse({{3, base}}, {{3, cylinder}, {3, block}}, fused, origins);
  gmsh::model::occ::synchronize();
  if (fused.size() != 1) fail_input(kWhere, fmt::format("the fuse gave {} volumes, not one", fused.size()));
}

void mesh_all_quads(double size) {
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

// Wire format, native byte order (parent and child are one program):
// node count, then per node its tag and x y z; quad count, then 4 tags each.
template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string encode_mesh() {
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, -1);
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

}  // namespace

QuadSurface bosses(int k) {
  require_at_least("bosses", {{"K", k}});
  if (k > kMaxSize)
    fail_input("gen bosses", fmt::format("K is {}, more than the limit of {}", k, kMaxSize), "choose a smaller K");
  const double size = kCoarseSize / k;
  QuadSurface surface = decode_mesh(run_gmsh_isolated(kWhere, "this is a bug in the bosses generator", [size] {
    build_part();
    mesh_all_quads(size);
    return encode_mesh();
  }));
  // Subdivision makes the count even: a closed mesh of t triangles and q quads
  // has 3t + 4q = 2 * edges, so t is even, and it becomes 3t + 4q quads.
  if (surface.quads.size() % 2 != 0) throw std::logic_error("gen bosses: Gmsh's subdivision gave an odd count");
  // Gmsh orients each face by its surface's parametrisation; validation flips
  // the whole surface outward if needed (and rejects an inconsistent one).
  validate_surface(surface, kWhere);
  return surface;
}

}  // namespace loom::gen
