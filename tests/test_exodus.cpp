// Exodus II output (.exo .e), read back with the Exodus library itself: nodes,
// HEX8 connectivity (same corner order as VTK), the boundary side set (element,
// side) in Exodus's HEX8 side numbering, and the cell fields as element variables.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include <exodusII.h>
#include <fmt/format.h>

#include "src/check/hex_boundary.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/io/hex_io.hpp"
#include "src/io/surface_io.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;
namespace fs = std::filesystem;

namespace {

/// What the Exodus library reads from a file (ids and node numbers 1-based).
struct ExodusContents {
  std::string title;
  int dimensions = 0, nodes = 0, elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
  std::array<std::vector<double>, 3> coordinates;
  std::string topology;  ///< of block 1
  int nodes_per_element = 0;
  std::vector<int> connectivity;
  std::string block_name, side_set_name;
  std::vector<int> side_elements, sides;
  std::vector<std::array<int, 4>> side_nodes;  ///< the library's own nodes of each (element, side)
  std::vector<double> times;
  std::vector<std::string> variable_names;
  std::vector<std::vector<double>> variables;  ///< per variable, at time step 1
};

class OpenExodus {
public:
  explicit OpenExodus(const fs::path& file) {
    ex_opts(0);
    int cpu_word_size = sizeof(double), io_word_size = 0;
    float version = 0;
    id = ex_open(file.c_str(), EX_READ, &cpu_word_size, &io_word_size, &version);
  }
  ~OpenExodus() {
    if (id >= 0) ex_close(id);
  }
  OpenExodus(const OpenExodus&) = delete;
  OpenExodus& operator=(const OpenExodus&) = delete;
  int id = -1;
};

std::string name_of(int id, ex_entity_type type) {
  std::array<char, MAX_STR_LENGTH + 1> name{};
  REQUIRE(ex_get_name(id, type, 1, name.data()) >= 0);
  return name.data();
}

ExodusContents read_exodus(const fs::path& file) {
  OpenExodus exo(file);
  REQUIRE(exo.id >= 0);
  const int id = exo.id;
  ExodusContents c;
  std::array<char, MAX_LINE_LENGTH + 1> title{};
  REQUIRE(ex_get_init(id, title.data(), &c.dimensions, &c.nodes, &c.elements, &c.blocks, &c.node_sets, &c.side_sets) == 0);
  c.title = title.data();
  for (auto& axis : c.coordinates) axis.resize(c.nodes);
  if (c.nodes > 0)
    REQUIRE(ex_get_coord(id, c.coordinates[0].data(), c.coordinates[1].data(), c.coordinates[2].data()) == 0);
  if (c.blocks > 0) {
    ex_block block{};
    block.id = 1;
    block.type = EX_ELEM_BLOCK;
    REQUIRE(ex_get_block_param(id, &block) == 0);
    c.topology = block.topology;
    c.nodes_per_element = static_cast<int>(block.num_nodes_per_entry);
    c.connectivity.resize(block.num_entry * block.num_nodes_per_entry);
    REQUIRE(ex_get_conn(id, EX_ELEM_BLOCK, 1, c.connectivity.data(), nullptr, nullptr) == 0);
    c.block_name = name_of(id, EX_ELEM_BLOCK);
  }
  if (c.side_sets > 0) {
    int count = 0, factors = 0;
    REQUIRE(ex_get_set_param(id, EX_SIDE_SET, 1, &count, &factors) == 0);
    c.side_elements.resize(count);
    c.sides.resize(count);
    c.side_nodes.resize(count);
    std::vector<int> nodes_per_side(count);
    if (count > 0) {
      REQUIRE(ex_get_set(id, EX_SIDE_SET, 1, c.side_elements.data(), c.sides.data()) == 0);
      REQUIRE(ex_get_side_set_node_list(id, 1, nodes_per_side.data(), c.side_nodes.data()->data()) == 0);
    }
    for (int n : nodes_per_side) CHECK(n == 4);
    c.side_set_name = name_of(id, EX_SIDE_SET);
  }
  c.times.resize(ex_inquire_int(id, EX_INQ_TIME));
  for (std::size_t t = 0; t < c.times.size(); ++t) REQUIRE(ex_get_time(id, static_cast<int>(t) + 1, &c.times[t]) == 0);
  int variables = 0;
  REQUIRE(ex_get_variable_param(id, EX_ELEM_BLOCK, &variables) == 0);
  std::vector<std::array<char, MAX_STR_LENGTH + 1>> names(variables);
  std::vector<char*> name_pointers;
  for (auto& name : names) name_pointers.push_back(name.data());
  if (variables > 0) REQUIRE(ex_get_variable_names(id, EX_ELEM_BLOCK, variables, name_pointers.data()) == 0);
  for (int v = 0; v < variables; ++v) {
    c.variable_names.emplace_back(names[v].data());
    std::vector<double> values(c.elements);
    REQUIRE(ex_get_var(id, 1, EX_ELEM_BLOCK, v + 1, 1, c.elements, values.data()) == 0);
    c.variables.push_back(std::move(values));
  }
  return c;
}

/// Whether `a` is `b` rotated (the same quad with the same orientation).
bool same_cycle(std::array<std::uint32_t, 4> a, const std::array<std::uint32_t, 4>& b) {
  for (int r = 0; r < 4; ++r, std::rotate(a.begin(), a.begin() + 1, a.end()))
    if (a == b) return true;
  return false;
}

/// Checks that `exo` is `mesh` with `fields`: nodes, connectivity with no
/// reordering, a side set that is exactly the boundary (each side outward, as
/// the library's side table turns it into nodes), and the variables' values.
void check_contents(const ExodusContents& exo, const HexMesh& mesh, const std::vector<CellField>& fields) {
  CHECK(exo.title == "Loom hex mesh");
  CHECK(exo.dimensions == 3);
  REQUIRE(exo.nodes == static_cast<int>(mesh.points.size()));
  REQUIRE(exo.elements == static_cast<int>(mesh.hexes.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(exo.coordinates[k][i] == mesh.points[i][k]);
  CHECK(exo.blocks == 1);
  CHECK(exo.node_sets == 0);
  CHECK(exo.topology == "HEX8");
  CHECK(exo.nodes_per_element == 8);
  CHECK(exo.block_name == "hexes");
  REQUIRE(exo.connectivity.size() == 8 * mesh.hexes.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (int k = 0; k < 8; ++k) CHECK(exo.connectivity[8 * h + k] == static_cast<int>(mesh.hexes[h][k]) + 1);

  // The boundary, found independently (src/check), oriented outward.
  std::vector<std::uint32_t> mesh_node;
  const QuadSurface boundary = hex_mesh_boundary(mesh, &mesh_node);
  std::map<std::array<std::uint32_t, 4>, std::array<std::uint32_t, 4>> outward;  // sorted nodes -> quad
  for (const Quad& q : boundary.quads) {
    std::array<std::uint32_t, 4> nodes{mesh_node[q[0]], mesh_node[q[1]], mesh_node[q[2]], mesh_node[q[3]]};
    auto key = nodes;
    std::sort(key.begin(), key.end());
    outward[key] = nodes;
  }
  CHECK(exo.side_sets == 1);
  CHECK(exo.side_set_name == "boundary");
  REQUIRE(exo.sides.size() == boundary.quads.size());
  std::set<std::array<std::uint32_t, 4>> seen;
  for (std::size_t i = 0; i < exo.sides.size(); ++i) {
    CAPTURE(i);
    CHECK(exo.side_elements[i] >= 1);
    CHECK(exo.side_elements[i] <= exo.elements);
    CHECK(exo.sides[i] >= 1);
    CHECK(exo.sides[i] <= 6);
    std::array<std::uint32_t, 4> nodes{};
    for (int k = 0; k < 4; ++k) nodes[k] = static_cast<std::uint32_t>(exo.side_nodes[i][k] - 1);
    auto key = nodes;
    std::sort(key.begin(), key.end());
    const auto found = outward.find(key);
    REQUIRE(found != outward.end());  // the side is a boundary face ...
    CHECK(same_cycle(nodes, found->second));  // ... and the library sees it outward, as Loom does
    CHECK(seen.insert(key).second);  // named once
  }

  if (fields.empty() || mesh.hexes.empty()) {
    CHECK(exo.variable_names.empty());
    return;
  }
  REQUIRE(exo.times.size() == 1);
  CHECK(exo.times[0] == 0.0);
  REQUIRE(exo.variable_names.size() == fields.size());
  for (std::size_t v = 0; v < fields.size(); ++v) {
    CHECK(exo.variable_names[v] == fields[v].name);
    CHECK(exo.variables[v] == fields[v].values);
  }
}

std::string error_of(const std::function<void()>& write) {
  try {
    write();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("a hexgrid written as Exodus II reads back through the Exodus library") {
  test::ScratchDir dir("exodus-grid");
  HexMesh mesh = gen::hexgrid(2, 2, 1);
  mesh.points[4][2] = 0.1 + 0.2;  // a coordinate that only round-trips exactly as a double
  std::vector<CellField> fields{{"source", {0, 1, 2, 4}},
                                {"scaled_jacobian", {}, CellField::Kind::real}};
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) fields[1].values.push_back(scaled_jacobian(mesh, h));
  for (const std::string ext : {".exo", ".e", ".EXO"}) {
    CAPTURE(ext);
    write_hex_mesh(dir / ("m" + ext), mesh, fields);
    check_contents(read_exodus(dir / ("m" + ext)), mesh, fields);
  }
  write_hex_mesh(dir / "plain.exo", mesh);
  check_contents(read_exodus(dir / "plain.exo"), mesh, {});
  // Deterministic: the same mesh gives the same bytes.
  write_hex_mesh(dir / "again.exo", mesh, fields);
  CHECK(test::slurp(dir / "again.exo") == test::slurp(dir / "m.exo"));
}

TEST_CASE("Exodus HEX8 sides are numbered as the Exodus II manual draws them") {
  // On the unit cube: side 1 is y=0, 2 is x=1, 3 is y=1, 4 is x=0, 5 is z=0, 6 is z=1.
  test::ScratchDir dir("exodus-sides");
  const HexMesh cube = gen::hexgrid(1, 1, 1);
  write_hex_mesh(dir / "cube.exo", cube);
  const ExodusContents exo = read_exodus(dir / "cube.exo");
  REQUIRE(exo.sides == std::vector<int>{1, 2, 3, 4, 5, 6});
  const std::array<std::pair<int, double>, 6> plane{{{1, 0.0}, {0, 1.0}, {1, 1.0}, {0, 0.0}, {2, 0.0}, {2, 1.0}}};
  for (int s = 0; s < 6; ++s) {
    CAPTURE(s + 1);
    for (int node : exo.side_nodes[s]) CHECK(cube.points[node - 1][plane[s].first] == plane[s].second);
  }
}

TEST_CASE("an empty hex mesh is a valid Exodus file with no block") {
  test::ScratchDir dir("exodus-empty");
  write_hex_mesh(dir / "e.exo", HexMesh{});
  const ExodusContents exo = read_exodus(dir / "e.exo");
  CHECK(exo.nodes == 0);
  CHECK(exo.elements == 0);
  CHECK(exo.blocks == 0);
  CHECK(exo.side_sets == 0);
}

TEST_CASE("Exodus write errors are one-line InputErrors and leave no file") {
  test::ScratchDir dir("exodus-errors");
  const HexMesh mesh = gen::hexgrid(1, 1, 1);
  std::string err = error_of([&] { write_hex_mesh(dir / "no" / "m.exo", mesh); });
  CHECK(err.find("output directory does not exist") != std::string::npos);
  // A directory where the temporary file would go makes the library's create fail.
  fs::create_directory(dir / fmt::format(".m.loom-tmp-{}.exo", ::getpid()));
  err = error_of([&] { write_hex_mesh(dir / "m.exo", mesh); });
  CHECK(err.find("m.exo: cannot write the Exodus II file: ex_create") != std::string::npos);
  CHECK(err.find('\n') == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "m.exo"));
  CHECK_THROWS_AS(read_hex_mesh(dir / "m.e"), InputError);
}

TEST_CASE("loom weave -o out.exo carries the same cell fields as the .vtu output") {
  test::ScratchDir dir("exodus-weave");
  REQUIRE(test::run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  const std::string weave = "weave " + (dir / "box.obj").string() + " -o ";
  REQUIRE(test::run_cli(weave + (dir / "out.vtu").string()).status == 0);
  const auto r = test::run_cli(weave + (dir / "out.exo").string());
  REQUIRE(r.status == 0);
  CHECK(r.out.find("wrote " + (dir / "out.exo").string()) != std::string::npos);

  const HexMesh mesh = read_hex_mesh(dir / "out.vtu");
  const ExodusContents exo = read_exodus(dir / "out.exo");
  // The .vtu's cell data arrays, in order: names and values.
  const std::string vtu = test::slurp(dir / "out.vtu");
  std::vector<CellField> fields;
  for (std::size_t at = vtu.find("<DataArray type=\""); at < vtu.find("<Points>");
       at = vtu.find("<DataArray type=\"", at + 1)) {
    const std::size_t name = vtu.find("Name=\"", at) + 6;
    CellField f{vtu.substr(name, vtu.find('"', name) - name), {}};
    std::size_t line = vtu.find('\n', at) + 1;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h, line = vtu.find('\n', line) + 1)
      f.values.push_back(std::stod(vtu.substr(line, vtu.find('\n', line) - line)));
    fields.push_back(f);
  }
  REQUIRE(fields.size() == 6);
  CHECK(fields[0].name == "source");
  CHECK(fields[1].name == "scaled_jacobian");
  CHECK(fields[2].name == "sheet_i");
  CHECK(fields[3].name == "sheet_j");
  CHECK(fields[4].name == "sheet_k");
  CHECK(fields[5].name == "inversion_cause");
  check_contents(exo, mesh, fields);
  // The side set is the woven mesh's boundary: the box's 24 quads.
  CHECK(exo.sides.size() == read_surface(dir / "box.obj").quads.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    CHECK(exo.variables[1][h] == scaled_jacobian(mesh, h));
    CHECK(exo.variables[0][h] >= 0);
    CHECK(exo.variables[0][h] <= 4);
  }
}
