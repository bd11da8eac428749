#include "src/cad/gmsh_quads.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

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
