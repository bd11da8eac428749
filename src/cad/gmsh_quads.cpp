#include "src/cad/gmsh_quads.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

#include "src/check/surface_angle_bound.hpp"
#include "src/util/error.hpp"

namespace loom::cad {

namespace {

// Wire format, native byte order (parent and child are one program):
// node count, then per node its tag and x y z; quad count, then 4 tags each.
template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& where) : bytes_(bytes), where_(where) {}
  template <class T>
  T get() {
    T value{};
    if (pos_ + sizeof value > bytes_.size())
      fail_input(where_, "short message from Gmsh's process", "this is a bug in Loom; please report it");
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }

 private:
  std::string_view bytes_;
  const std::string& where_;
  std::size_t pos_ = 0;
};

}  // namespace

void mesh_free_quads(double size) {
  // Gmsh 4.8's names (later versions call them Mesh.MeshSize...). The sizes
  // stored at the CAD points would override the maximum: ignore them.
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", size);
  gmsh::option::setNumber("Mesh.CharacteristicLengthFromPoints", 0);
  gmsh::option::setNumber("Mesh.MinimumCirclePoints", 6);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay (8 crashes Gmsh 4.8.4)
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  // Simple recombination, not blossom: Gmsh 4.8.4's blossom breaks ties by
  // memory address, so the same call pairs triangles differently from run to
  // run (2 and 3 throw). Subdivision turns what is left into quads anyway.
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 0);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);  // split into quads only
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::removeDuplicateNodes();
}

namespace {

struct Ball {
  Vec3 centre;
  double radius, size;
};

/// Adds balls[from...] as Gmsh fields (tags 2, 3, ...) and makes the least
/// of all of them the background size (field 1).
void add_to_size_field(const std::vector<Ball>& balls, std::size_t from) {
  if (balls.size() == from) return;
  if (from > 0) gmsh::model::mesh::field::remove(1);
  for (std::size_t b = from; b < balls.size(); ++b) {
    const int tag = static_cast<int>(b) + 2;
    gmsh::model::mesh::field::add("Ball", tag);
    gmsh::model::mesh::field::setNumber(tag, "XCenter", balls[b].centre[0]);
    gmsh::model::mesh::field::setNumber(tag, "YCenter", balls[b].centre[1]);
    gmsh::model::mesh::field::setNumber(tag, "ZCenter", balls[b].centre[2]);
    gmsh::model::mesh::field::setNumber(tag, "Radius", balls[b].radius);
    gmsh::model::mesh::field::setNumber(tag, "VIn", balls[b].size);
    gmsh::model::mesh::field::setNumber(tag, "VOut", 1e22);
  }
  std::vector<double> tags;
  for (std::size_t b = 0; b < balls.size(); ++b) tags.push_back(static_cast<double>(b) + 2);
  gmsh::model::mesh::field::add("Min", 1);
  gmsh::model::mesh::field::setNumbers(1, "FieldsList", tags);
  gmsh::model::mesh::field::setAsBackgroundMesh(1);
}

}  // namespace

RefinedQuads mesh_refined_quads(double size, double wanted, const std::vector<int>& surfaces, const std::string& where,
                                const std::string& hint) {
  // One round takes the bundled bracket's slivers (least sine 0.0004) to
  // 0.23 and the flange's (0.095) take three; a corner no size opens is given
  // up on after five, and the quad count is held to eight times the first's.
  constexpr int kMostRounds = 5;
  constexpr std::size_t kMostGrowth = 8;
  std::vector<Ball> balls;
  RefinedQuads best;
  std::size_t first_quads = 0;
  for (int round = 0; round <= kMostRounds; ++round) {
    if (round > 0) gmsh::model::mesh::clear();
    mesh_free_quads(size);
    std::string bytes = encode_quads(surfaces, where, hint);
    const QuadSurface surface = decode_quads(bytes, where);
    if (round == 0) first_quads = surface.quads.size();
    if (surface.quads.size() > kMostGrowth * first_quads) break;
    std::vector<Ball> added;
    double least = 1;
    for (const Quad& q : surface.quads) {
      const double sine = least_corner_sine(surface, q);
      least = std::min(least, sine);
      if (sine >= wanted) continue;
      Vec3 centre{0, 0, 0};
      double longest = 0;
      for (int i = 0; i < 4; ++i) {
        const Vec3& p = surface.points[q[static_cast<std::size_t>(i)]];
        centre = centre + p;
        longest = std::max(longest, norm(surface.points[q[static_cast<std::size_t>((i + 1) % 4)]] - p));
      }
      // Gmsh meshes at twice the quads' edge (the subdivision halves it), so
      // its size there was about 2 * longest. Smaller radii or steps left
      // slivers for more rounds; larger ones grew the bracket's quads by half.
      added.push_back({0.25 * centre, 1.5 * longest, std::max(1.5 * longest, size / 64)});
    }
    if (round == 0 || least > best.least_sine) best = {std::move(bytes), least, 0, static_cast<int>(balls.size())};
    best.meshings = round + 1;
    if (added.empty()) break;
    const std::size_t from = balls.size();
    balls.insert(balls.end(), added.begin(), added.end());
    add_to_size_field(balls, from);
  }
  return best;
}

std::string encode_quads(const std::vector<int>& surfaces, const std::string& where, const std::string& hint) {
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
      fail_input(where, fmt::format("Gmsh left {} surface elements of type {}, not quads", element_tags[t].size(), types[t]),
                 hint);
    quads += element_tags[t].size();
  }
  put<std::uint64_t>(out, quads);
  for (std::size_t t = 0; t < types.size(); ++t)
    for (std::size_t tag : element_nodes[t]) put<std::uint64_t>(out, tag);
  return out;
}

QuadSurface decode_quads(std::string_view bytes, const std::string& where) {
  Reader in(bytes, where);
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
      const auto at = position.find(tag);
      if (at == position.end())
        fail_input(where, fmt::format("Gmsh's quad {} uses node {}, which it did not send", q, tag),
                   "this is a bug in Loom; please report it");
      auto [it, added] = index.emplace(tag, static_cast<std::uint32_t>(surface.points.size()));
      if (added) surface.points.push_back(at->second);
      corner = it->second;
    }
    surface.quads.push_back(quad);
  }
  return surface;
}

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

}  // namespace loom::cad
