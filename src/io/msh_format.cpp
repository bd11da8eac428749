// Gmsh MSH. ASCII files (2.2, 4.1) are read by our parser, binary ones through
// Gmsh in a child process. Writing is our own MSH 4.1 ASCII: Gmsh 4.8 writes
// coordinates with %.16g, which does not round-trip every double (see
// docs/formats.md).
#include <fmt/format.h>

#include <algorithm>

#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

constexpr const char* reexport_hint = "fix the file or export it again as MSH 4.1 or 2.2";

// Binary files go to Gmsh, which silently accepts a file that stops after a
// complete section; make sure the sections that matter are complete. Binary
// payloads may hold any byte, so only look for the section markers.
void check_binary_sections(std::string_view text, const std::string& where) {
  for (std::string_view section : {"Nodes", "Elements"}) {
    auto begin = text.find(fmt::format("\n${}", section));
    if (begin == std::string_view::npos)
      fail_input(where, fmt::format("no ${} section (truncated?)", section), reexport_hint);
    if (text.find(fmt::format("$End{}", section), begin) == std::string_view::npos)
      fail_input(where, fmt::format("${} section has no $End{} (truncated?)", section, section),
                 "the file is incomplete; write or download it again");
  }
}

// Checks the header; true for a binary file.
bool is_binary_msh(std::string_view text, const std::string& where) {
  TextScanner in(text, where);
  if (in.expect_token("$MeshFormat") != "$MeshFormat")
    fail_input(where, "line 1 is not $MeshFormat", "this is not a Gmsh MSH file; check the extension");
  std::string_view version = in.expect_token("the MSH version");
  if (version != "2.2" && version != "4.1")
    in.fail(fmt::format("MSH version {} is not supported", quote_token(version)), "export the mesh as MSH 4.1 or 2.2");
  return in.integer("the MSH file type (0 ASCII, 1 binary)") == 1;
}

}  // namespace

RawMesh read_msh(const std::filesystem::path& file) {
  const std::string where = file.string();
  const std::string text = read_input_file(file);
  if (!is_binary_msh(text, where)) return parse_msh_ascii(text, where);
  check_binary_sections(text, where);
  return read_msh_with_gmsh(file);
}

std::string msh_text(const CellTable& table) {
  fmt::memory_buffer out;
  auto put = std::back_inserter(out);
  const std::size_t nodes = table.points.size(), cells = table.cell_count(), n = table.nodes_per_cell();
  const int dim = table.dimension();

  Vec3 low{0, 0, 0}, high{0, 0, 0};
  if (nodes > 0) {
    low = high = table.points.front();
    for (const Vec3& p : table.points)
      for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
  }
  fmt::format_to(put, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  // One entity of the mesh's dimension holds everything; it has no physical
  // tags and no bounding entities.
  fmt::format_to(put, "$Entities\n0 0 {} {}\n1 {} {} {} {} {} {} 0 0\n$EndEntities\n", dim == 2 ? 1 : 0,
                 dim == 3 ? 1 : 0, low[0], low[1], low[2], high[0], high[1], high[2]);
  fmt::format_to(put, "$Nodes\n");
  if (nodes == 0) {
    fmt::format_to(put, "0 0 0 0\n");
  } else {
    fmt::format_to(put, "1 {0} 1 {0}\n{1} 1 0 {0}\n", nodes, dim);
    for (std::size_t i = 1; i <= nodes; ++i) fmt::format_to(put, "{}\n", i);
    for (const Vec3& p : table.points) fmt::format_to(put, "{} {} {}\n", p[0], p[1], p[2]);
  }
  fmt::format_to(put, "$EndNodes\n$Elements\n");
  if (cells == 0) {
    fmt::format_to(put, "0 0 0 0\n");
  } else {
    fmt::format_to(put, "1 {0} 1 {0}\n{1} 1 {2} {0}\n", cells, dim, table.msh_type());
    for (std::size_t c = 0; c < cells; ++c) {
      fmt::format_to(put, "{}", c + 1);
      for (std::size_t k = 0; k < n; ++k) fmt::format_to(put, " {}", table.connectivity[c * n + k] + 1);
      fmt::format_to(put, "\n");
    }
  }
  fmt::format_to(put, "$EndElements\n");
  // One $ElementData view per field: name, time 0, time step 0, 1 component.
  for (const CellField& f : table.fields) {
    fmt::format_to(put, "$ElementData\n1\n\"{}\"\n1\n0\n3\n0\n1\n{}\n", f.name, cells);
    for (std::size_t c = 0; c < cells; ++c) {
      fmt::format_to(put, "{} ", c + 1);
      append_cell_value(out, f, c);
      fmt::format_to(put, "\n");
    }
    fmt::format_to(put, "$EndElementData\n");
  }
  return fmt::to_string(out);
}

}  // namespace loom
