// Reads an MSH file through the Gmsh API, in an isolated child process (see
// gmsh_session.hpp). Used for binary MSH, which our ASCII parser does not read.
#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <cstring>
#include <unordered_map>

#include "src/io/formats.hpp"
#include "src/io/gmsh_session.hpp"
#include "src/io/msh_element_types.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

// The child hands the mesh back as bytes: plain values in native byte order
// (parent and child are the same program on the same machine).
class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes_ += s;
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T value{};
    if (pos_ + sizeof value > bytes_.size()) throw std::runtime_error("short message from the Gmsh reader process");
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }
  std::string get_string() {
    auto size = get<std::uint64_t>();
    if (size > bytes_.size() - pos_) throw std::runtime_error("short message from the Gmsh reader process");
    std::string s(bytes_.substr(pos_, size));
    pos_ += size;
    return s;
  }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

std::string encode(const RawMesh& mesh) {
  ByteWriter out;
  out.put<std::uint64_t>(mesh.points.size());
  for (const Vec3& p : mesh.points) out.put(p);
  out.put<std::uint64_t>(mesh.cells.size());
  for (const RawCell& cell : mesh.cells) {
    out.put(static_cast<std::int32_t>(cell.kind));
    out.put(cell.origin.number);
    out.put_string(cell.type_name);
    out.put<std::uint64_t>(cell.nodes.size());
    for (std::int64_t n : cell.nodes) out.put(n);
  }
  return out.take();
}

RawMesh decode(std::string_view bytes) {
  ByteReader in(bytes);
  RawMesh mesh;
  mesh.points.resize(in.get<std::uint64_t>());
  for (Vec3& p : mesh.points) p = in.get<Vec3>();
  mesh.cells.resize(in.get<std::uint64_t>());
  for (RawCell& cell : mesh.cells) {
    cell.kind = static_cast<CellKind>(in.get<std::int32_t>());
    cell.origin = {"element", in.get<std::int64_t>()};
    cell.type_name = in.get_string();
    cell.nodes.resize(in.get<std::uint64_t>());
    for (std::int64_t& n : cell.nodes) n = in.get<std::int64_t>();
  }
  return mesh;
}

RawMesh mesh_from_gmsh_model(const std::string& where) {
  RawMesh mesh;
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::int64_t> index_of_tag;
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    Vec3 p{coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]};
    for (double x : p)
      if (!std::isfinite(x))
        fail_input(where,
                   fmt::format("node {} has a{} coordinate", node_tags[i], std::isnan(x) ? " NaN" : "n infinite"),
                   "every coordinate must be a finite number; fix or remove that node");
    if (!index_of_tag.emplace(node_tags[i], static_cast<std::int64_t>(i)).second)
      fail_input(where, fmt::format("node {} is defined twice", node_tags[i]), "give every node its own tag");
    mesh.points.push_back(p);
  }
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, -1, -1);
  for (std::size_t t = 0; t < types.size(); ++t) {
    std::string name;
    int dimension = 0, order = 0, node_count = 0, primary_nodes = 0;
    std::vector<double> local_coordinates;
    gmsh::model::mesh::getElementProperties(types[t], name, dimension, order, node_count, local_coordinates,
                                            primary_nodes);
    if (node_count <= 0 || element_nodes[t].size() != element_tags[t].size() * static_cast<std::size_t>(node_count))
      fail_input(where, fmt::format("inconsistent {} elements", name), "fix or re-export the file");
    for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
      auto element_tag = static_cast<std::int64_t>(element_tags[t][e]);
      RawCell cell{msh_cell_kind(types[t], dimension), {}, {"element", element_tag}, name};
      for (int k = 0; k < node_count; ++k) {
        auto found = index_of_tag.find(element_nodes[t][e * node_count + k]);
        if (found == index_of_tag.end())
          fail_input(where,
                     fmt::format("element {} refers to node {}, which is not defined", element_tag,
                                 element_nodes[t][e * node_count + k]),
                     "fix the node tag or add the missing node");
        cell.nodes.push_back(found->second);
      }
      mesh.cells.push_back(std::move(cell));
    }
  }
  return mesh;
}

}  // namespace

RawMesh read_msh_with_gmsh(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::string bytes = run_gmsh_isolated(where, "fix the file or export it again as ASCII MSH 4.1", [&] {
    gmsh::open(file.string());
    return encode(mesh_from_gmsh_model(where));
  });
  return decode(bytes);
}

}  // namespace loom
