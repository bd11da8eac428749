// VTK XML UnstructuredGrid (.vtu) with format="ascii" data arrays. Binary and
// appended arrays are refused with a hint to re-save as ASCII. Several pieces are
// concatenated.
#include <fmt/format.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <sstream>

#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"
#include "src/io/vtk_cell_types.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

using boost::property_tree::ptree;

std::string attribute(const ptree& node, const std::string& name) {
  return node.get<std::string>("<xmlattr>." + name, "");
}

const ptree& child(const ptree& parent, const std::string& name, const std::string& context, const std::string& where) {
  auto found = parent.get_child_optional(name);
  if (!found) fail_input(where, fmt::format("{} has no <{}> element", context, name), "fix or re-export the file");
  return *found;
}

// The data array among `parent`'s children called `name` (or the first one when
// `name` is empty), as whitespace-separated tokens.
std::vector<std::string_view> array_tokens(const ptree& parent, const std::string& name, const std::string& context,
                                           const std::string& where) {
  for (const auto& [tag, node] : parent) {
    if (tag != "DataArray" || (!name.empty() && attribute(node, "Name") != name)) continue;
    std::string format = attribute(node, "format");
    if (format != "ascii")
      fail_input(where,
                 fmt::format("{} data array is stored as {}, which Loom cannot read", context,
                             format.empty() ? "(no format)" : quote_token(format)),
                 "re-save the file with ASCII data (ParaView: Save Data, Data Mode Ascii)");
    std::vector<std::string_view> tokens;
    const std::string& text = node.data();
    std::size_t pos = 0;
    while (true) {
      pos = text.find_first_not_of(" \t\r\n", pos);
      if (pos == std::string::npos) break;
      std::size_t end = text.find_first_of(" \t\r\n", pos);
      if (end == std::string::npos) end = text.size();
      tokens.emplace_back(text.data() + pos, end - pos);
      pos = end;
    }
    return tokens;
  }
  fail_input(where, fmt::format("{} has no '{}' data array", context, name.empty() ? "coordinate" : name),
             "fix or re-export the file");
}

// `count` items of `per_item` values each. The count comes from the file, so it is
// compared with the values present, never multiplied (3 * count can wrap).
template <class Number>
std::vector<Number> numbers(const std::vector<std::string_view>& tokens, std::size_t count, std::size_t per_item,
                            const std::string& context, const std::string& where) {
  if (tokens.size() % per_item != 0 || tokens.size() / per_item != count)
    fail_input(where,
               per_item == 1 ? fmt::format("{} has {} values, expected {}", context, tokens.size(), count)
                             : fmt::format("{} has {} values, expected {} for each of {}", context, tokens.size(),
                                           per_item, count),
               "the file is inconsistent or truncated; re-export it");
  std::vector<Number> values(tokens.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    bool ok = false;
    if constexpr (std::is_same_v<Number, double>) {
      ok = parse_real(tokens[i], values[i]);
    } else {
      ok = parse_integer(tokens[i], values[i]);
    }
    if (!ok)
      fail_input(where, fmt::format("{} value {} is {}, not a number", context, i, quote_token(tokens[i])),
                 "fix the data array");
  }
  return values;
}

std::size_t count_attribute(const ptree& piece, const std::string& name, const std::string& where) {
  std::int64_t value = -1;
  std::string text = attribute(piece, name);
  if (!parse_integer(text, value) || value < 0)
    fail_input(where, fmt::format("<Piece> has {}={}, not a count", name, quote_token(text)), "fix the file");
  return static_cast<std::size_t>(value);
}

void read_piece(const ptree& piece, std::size_t piece_index, RawMesh& mesh, const std::string& where) {
  const std::string label = fmt::format("piece {}", piece_index);
  std::size_t point_count = count_attribute(piece, "NumberOfPoints", where);
  std::size_t cell_count = count_attribute(piece, "NumberOfCells", where);
  const std::int64_t first_point = static_cast<std::int64_t>(mesh.points.size());

  const ptree& points = child(piece, "Points", label, where);
  auto coordinates =
      numbers<double>(array_tokens(points, "", label + " Points", where), point_count, 3, label + " Points", where);
  for (std::size_t i = 0; i < point_count; ++i)
    mesh.points.push_back({coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]});

  const ptree& cells = child(piece, "Cells", label, where);
  auto offsets = numbers<std::int64_t>(array_tokens(cells, "offsets", label + " Cells", where), cell_count, 1,
                                       label + " offsets", where);
  auto types =
      numbers<std::int64_t>(array_tokens(cells, "types", label + " Cells", where), cell_count, 1, label + " types", where);
  auto connectivity_tokens = array_tokens(cells, "connectivity", label + " Cells", where);
  auto connectivity =
      numbers<std::int64_t>(connectivity_tokens, connectivity_tokens.size(), 1, label + " connectivity", where);
  std::int64_t begin = 0;
  for (std::size_t c = 0; c < cell_count; ++c) {
    std::int64_t end = offsets[c];
    if (end < begin || end > static_cast<std::int64_t>(connectivity.size()))
      fail_input(where, fmt::format("{} offset {} is {}, out of order or past the connectivity", label, c, end),
                 "fix the offsets array");
    std::vector<std::int64_t> nodes(connectivity.begin() + begin, connectivity.begin() + end);
    for (auto& n : nodes) {
      // Checked here, while the piece's own numbering is known (adding the
      // offset to a huge index would overflow).
      if (n < 0 || static_cast<std::uint64_t>(n) >= point_count)
        fail_input(where, fmt::format("{} cell {} refers to node {}, but the piece has {} points", label, c, n,
                                      point_count),
                   "fix the connectivity array");
      n += first_point;
    }
    mesh.cells.push_back(
        vtk_cell(static_cast<int>(types[c]), std::move(nodes), {"cell", static_cast<std::int64_t>(mesh.cells.size())}));
    begin = end;
  }
}

}  // namespace

RawMesh parse_vtu(std::string_view text, const std::string& where) {
  ptree document;
  try {
    std::istringstream stream{std::string(text)};
    boost::property_tree::read_xml(stream, document);
  } catch (const boost::property_tree::xml_parser_error& e) {
    std::string message = e.message();
    if (message.find("end of data") != std::string::npos)
      fail_input(where, fmt::format("XML ends early at line {} (truncated?)", e.line()),
                 "the file is incomplete; write or download it again");
    fail_input(where, fmt::format("line {}: XML syntax error: {}", e.line(), message), "fix or re-export the file");
  }
  auto root = document.get_child_optional("VTKFile");
  if (!root) fail_input(where, "no <VTKFile> root element", "this is not a VTK XML file; check the extension");
  if (attribute(*root, "type") != "UnstructuredGrid")
    fail_input(where, fmt::format("VTKFile type is {}, not UnstructuredGrid", quote_token(attribute(*root, "type"))),
               "save the mesh as an unstructured grid (.vtu)");
  if (root->get_child_optional("AppendedData"))
    fail_input(where, "data is stored in an <AppendedData> block, which Loom cannot read",
               "re-save the file with ASCII data (ParaView: Save Data, Data Mode Ascii)");
  const ptree& grid = child(*root, "UnstructuredGrid", "<VTKFile>", where);
  RawMesh mesh;
  std::size_t pieces = 0;
  for (const auto& [tag, piece] : grid)
    if (tag == "Piece") read_piece(piece, pieces++, mesh, where);
  if (pieces == 0) fail_input(where, "<UnstructuredGrid> has no <Piece>", "fix or re-export the file");
  return mesh;
}

std::string vtu_text(const CellTable& table) {
  fmt::memory_buffer out;
  auto put = std::back_inserter(out);
  const std::size_t n = table.nodes_per_cell();
  fmt::format_to(put,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 table.points.size(), table.cell_count());
  if (!table.fields.empty()) {
    fmt::format_to(put, "      <CellData Scalars=\"{}\">\n", table.fields.front().name);
    for (const CellField& f : table.fields) {
      fmt::format_to(put, "        <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n",
                     f.kind == CellField::Kind::integer ? "Int32" : "Float64", f.name);
      for (std::size_t c = 0; c < f.values.size(); ++c) {
        fmt::format_to(put, "          ");
        append_cell_value(out, f, c);
        fmt::format_to(put, "\n");
      }
      fmt::format_to(put, "        </DataArray>\n");
    }
    fmt::format_to(put, "      </CellData>\n");
  }
  fmt::format_to(put,
                 "      <Points>\n"
                 "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const Vec3& p : table.points) fmt::format_to(put, "          {} {} {}\n", p[0], p[1], p[2]);
  fmt::format_to(put,
                 "        </DataArray>\n"
                 "      </Points>\n"
                 "      <Cells>\n"
                 "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (std::size_t c = 0; c < table.cell_count(); ++c) {
    fmt::format_to(put, "         ");
    for (std::size_t k = 0; k < n; ++k) fmt::format_to(put, " {}", table.connectivity[c * n + k]);
    fmt::format_to(put, "\n");
  }
  fmt::format_to(put, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (std::size_t c = 0; c < table.cell_count(); ++c) fmt::format_to(put, "          {}\n", (c + 1) * n);
  fmt::format_to(put, "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (std::size_t c = 0; c < table.cell_count(); ++c) fmt::format_to(put, "          {}\n", table.vtk_type());
  fmt::format_to(put,
                 "        </DataArray>\n"
                 "      </Cells>\n"
                 "    </Piece>\n"
                 "  </UnstructuredGrid>\n"
                 "</VTKFile>\n");
  return fmt::to_string(out);
}

}  // namespace loom
