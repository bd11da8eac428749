// Exodus II output through the SEACAS Exodus C library (Debian libexodusii-dev).
// The file holds:
//  - title "Loom hex mesh", 3 dimensions, coordinates named x y z, nodes 1..N in
//    Loom's node order;
//  - one element block, id 1, named "hexes": HEX8 elements 1..M in Loom's order;
//  - one side set, id 1, named "boundary": every face held by exactly one hex, as
//    (element, side), sorted by element then side;
//  - every cell field as an element variable of that block at time step 1, time 0
//    (Exodus variables are doubles; integer fields hold whole numbers).
// An empty mesh has no block, no side set and no variables.
//
// Node order: Exodus HEX8 numbers its corners as VTK_HEXAHEDRON does (1-4 one
// face, counter-clockwise seen from 5-8; 5-8 the opposite face, 4+i joined to i;
// Exodus II manual, "Element Types", and VTK's vtkHexahedron), so the
// connectivity is Loom's shifted by one, with no permutation. tests/test_exodus.cpp
// checks this through the library's own side-node table.
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <exodusII.h>

#include "src/io/formats.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

/// The corners (0-based, VTK order) of Exodus HEX8 sides 1..6, as the Exodus II
/// manual's side set table lists them (each seen from outside: outward normal).
/// libexoIIv2c's ex_get_side_set_node_list gives the same table.
constexpr std::array<std::array<int, 4>, 6> kExodusHexSides{
    {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}}};

struct SideSet {
  std::vector<int> elements;  ///< 1-based
  std::vector<int> sides;     ///< 1-based, kExodusHexSides order
};

/// The faces used by exactly one hex, identified by their node sets. Any table is
/// accepted (repeated or degenerate hexes too): nothing here assumes validity.
SideSet boundary_sides(const CellTable& table) {
  struct Face {
    std::array<std::uint32_t, 4> nodes;  // sorted
    int element, side;
  };
  std::vector<Face> faces;
  faces.reserve(6 * table.cell_count());
  for (std::size_t h = 0; h < table.cell_count(); ++h)
    for (int s = 0; s < 6; ++s) {
      Face f{{}, static_cast<int>(h) + 1, s + 1};
      for (int k = 0; k < 4; ++k) f.nodes[k] = table.connectivity[8 * h + kExodusHexSides[s][k]];
      std::sort(f.nodes.begin(), f.nodes.end());
      faces.push_back(f);
    }
  // Stable: equal faces keep (element, side) order, and so do the singles kept.
  std::stable_sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.nodes < b.nodes; });
  std::vector<std::pair<int, int>> single;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].nodes == faces[i].nodes) ++j;
    if (j == i + 1) single.emplace_back(faces[i].element, faces[i].side);
    i = j;
  }
  std::sort(single.begin(), single.end());
  SideSet set;
  for (const auto& [element, side] : single) {
    set.elements.push_back(element);
    set.sides.push_back(side);
  }
  return set;
}

/// An open Exodus file, closed on every path out; library errors become one-line
/// InputErrors naming the call.
class ExodusWriter {
public:
  ExodusWriter(const std::filesystem::path& file, std::string shown_file) : shown_(std::move(shown_file)) {
    ex_opts(0);  // neither print nor exit on errors: we report them ourselves
    int cpu_word_size = sizeof(double), io_word_size = 8;
    id_ = ex_create(file.c_str(), EX_CLOBBER, &cpu_word_size, &io_word_size);
    check(id_, "ex_create");
  }
  ~ExodusWriter() {
    if (id_ >= 0) ex_close(id_);
  }
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  int id() const { return id_; }

  /// Negative statuses are errors; positive ones are warnings and pass.
  void check(int status, const char* call) const {
    if (status >= 0) return;
    const char* message = nullptr;
    const char* function = nullptr;
    int code = 0;
    ex_get_err(&message, &function, &code);
    std::string what = message && *message ? message : "no message";
    std::replace(what.begin(), what.end(), '\n', ' ');
    fail_input(shown_, fmt::format("cannot write the Exodus II file: {}: {} (code {})", call, what, code),
               "check the path, permissions and free space");
  }

  void close() {
    const int id = id_;
    id_ = -1;
    check(ex_close(id), "ex_close");
  }

private:
  std::string shown_;
  int id_ = -1;
};

/// Exodus ids and counts are 32-bit ints here.
void check_fits(const CellTable& table, const std::string& shown_file) {
  if (table.points.size() > INT_MAX || 6 * table.cell_count() > INT_MAX)
    fail_input(shown_file, "the mesh is too large for 32-bit Exodus ids", "write it as .vtu or .msh");
}

void put_coordinates(const ExodusWriter& exo, const CellTable& table) {
  std::array<std::vector<double>, 3> axes;
  for (auto& axis : axes) axis.reserve(table.points.size());
  for (const Vec3& p : table.points)
    for (int k = 0; k < 3; ++k) axes[k].push_back(p[k]);
  exo.check(ex_put_coord(exo.id(), axes[0].data(), axes[1].data(), axes[2].data()), "ex_put_coord");
  std::array<std::string, 3> names{"x", "y", "z"};
  std::array<char*, 3> name_pointers{names[0].data(), names[1].data(), names[2].data()};
  exo.check(ex_put_coord_names(exo.id(), name_pointers.data()), "ex_put_coord_names");
}

void put_hex_block(const ExodusWriter& exo, const CellTable& table) {
  const std::int64_t hexes = static_cast<std::int64_t>(table.cell_count());
  exo.check(ex_put_block(exo.id(), EX_ELEM_BLOCK, 1, "HEX8", hexes, 8, 0, 0, 0), "ex_put_block");
  exo.check(ex_put_name(exo.id(), EX_ELEM_BLOCK, 1, "hexes"), "ex_put_name");
  std::vector<int> connectivity;
  connectivity.reserve(table.connectivity.size());
  for (std::uint32_t node : table.connectivity) connectivity.push_back(static_cast<int>(node) + 1);
  exo.check(ex_put_conn(exo.id(), EX_ELEM_BLOCK, 1, connectivity.data(), nullptr, nullptr), "ex_put_conn");
}

void put_boundary_side_set(const ExodusWriter& exo, const CellTable& table) {
  const SideSet set = boundary_sides(table);
  exo.check(ex_put_set_param(exo.id(), EX_SIDE_SET, 1, static_cast<std::int64_t>(set.elements.size()), 0),
            "ex_put_set_param");
  if (!set.elements.empty())
    exo.check(ex_put_set(exo.id(), EX_SIDE_SET, 1, set.elements.data(), set.sides.data()), "ex_put_set");
  exo.check(ex_put_name(exo.id(), EX_SIDE_SET, 1, "boundary"), "ex_put_name");
}

void put_element_variables(const ExodusWriter& exo, const CellTable& table) {
  const int count = static_cast<int>(table.fields.size());
  exo.check(ex_put_variable_param(exo.id(), EX_ELEM_BLOCK, count), "ex_put_variable_param");
  std::vector<std::string> names;
  for (const CellField& f : table.fields) names.push_back(f.name);
  std::vector<char*> name_pointers;
  for (std::string& name : names) name_pointers.push_back(name.data());
  exo.check(ex_put_variable_names(exo.id(), EX_ELEM_BLOCK, count, name_pointers.data()), "ex_put_variable_names");
  std::vector<int> truth_table(table.fields.size(), 1);  // one block, every variable on it
  exo.check(ex_put_truth_table(exo.id(), EX_ELEM_BLOCK, 1, count, truth_table.data()), "ex_put_truth_table");
  const double time = 0;
  exo.check(ex_put_time(exo.id(), 1, &time), "ex_put_time");
  for (int v = 0; v < count; ++v) {
    const CellField& f = table.fields[v];
    exo.check(ex_put_var(exo.id(), 1, EX_ELEM_BLOCK, v + 1, 1, static_cast<std::int64_t>(f.values.size()),
                         f.values.data()),
              "ex_put_var");
  }
}

}  // namespace

void write_exodus(const std::filesystem::path& file, const CellTable& table, const std::string& shown_file) {
  if (table.shape != CellShape::hexahedron) throw std::invalid_argument("write_exodus: only hex meshes are written");
  check_fits(table, shown_file);
  const bool has_hexes = table.cell_count() > 0;
  ExodusWriter exo(file, shown_file);
  exo.check(ex_put_init(exo.id(), "Loom hex mesh", 3, static_cast<std::int64_t>(table.points.size()),
                        static_cast<std::int64_t>(table.cell_count()), has_hexes ? 1 : 0, 0, has_hexes ? 1 : 0),
            "ex_put_init");
  if (!table.points.empty()) put_coordinates(exo, table);
  if (has_hexes) {
    put_hex_block(exo, table);
    put_boundary_side_set(exo, table);
    if (!table.fields.empty()) put_element_variables(exo, table);
  }
  exo.close();
}

}  // namespace loom
