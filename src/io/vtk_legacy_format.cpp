// Legacy VTK (.vtk): "# vtk DataFile Version x.y", a title, ASCII or BINARY, then
// DATASET UNSTRUCTURED_GRID (POINTS, CELLS, CELL_TYPES) or POLYDATA (POINTS,
// VERTICES, LINES, POLYGONS). Both the classic cell layout and the 5.x
// OFFSETS/CONNECTIVITY layout are read. Attribute data after the geometry is ignored.
#include <fmt/format.h>

#include <bit>
#include <optional>

#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"
#include "src/io/vtk_cell_types.hpp"
#include "src/util/error.hpp"

namespace loom {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Reads the numeric payload of one section, as ASCII tokens or big-endian binary.
class VtkValues {
 public:
  VtkValues(TextScanner& in, bool binary) : in_(in), binary_(binary) {}

  /// The binary payload starts on the line after its keyword line; call once the
  /// keyword line's own tokens are read.
  void begin_section() {
    if (binary_) in_.seek(in_.offset_after_line());
  }

  double real(std::string_view type, std::string_view what) {
    if (!binary_) return in_.real(what);
    if (type == "float") return std::bit_cast<float>(big_endian<std::uint32_t>(what));
    if (type == "double") return std::bit_cast<double>(big_endian<std::uint64_t>(what));
    in_.fail(fmt::format("binary POINTS of type {} are not supported", quote_token(type)),
             "store points as float or double");
  }

  std::int64_t integer(std::string_view type, std::string_view what) {
    if (!binary_) return in_.integer(what);
    if (type == "int" || type == "vtktypeint32") return static_cast<std::int32_t>(big_endian<std::uint32_t>(what));
    if (type == "vtktypeint64" || type == "long") return static_cast<std::int64_t>(big_endian<std::uint64_t>(what));
    in_.fail(fmt::format("binary integers of type {} are not supported", quote_token(type)),
             "store cells as int, vtktypeint32 or vtktypeint64");
  }

 private:
  template <class Word>
  Word big_endian(std::string_view what) {
    std::size_t at = in_.offset();
    if (at + sizeof(Word) > in_.text().size()) in_.fail_truncated(what);
    Word word = 0;
    for (std::size_t k = 0; k < sizeof(Word); ++k)
      word = static_cast<Word>((word << 8) | static_cast<unsigned char>(in_.text()[at + k]));
    in_.seek(at + sizeof(Word));
    return word;
  }
  TextScanner& in_;
  bool binary_;
};

struct CellBlock {
  std::vector<std::vector<std::int64_t>> cells;
};

// "CELLS n size" / "POLYGONS n size" and their payload, in either layout.
CellBlock read_cell_block(TextScanner& in, VtkValues& values, std::string_view keyword) {
  // Every offset, entry and node is at least one number: 2 bytes in ASCII, more in binary.
  std::size_t first = in.count(fmt::format("the {} count", keyword), 2);
  std::size_t second = in.count(fmt::format("the {} size", keyword), 2);
  CellBlock block;
  // 5.x layout: "CELLS offsets connectivity" then OFFSETS and CONNECTIVITY arrays.
  if (in.peek_token() == "OFFSETS") {
    in.token();
    std::string offsets_type(in.expect_token("the OFFSETS type"));
    values.begin_section();
    std::vector<std::int64_t> offsets(first);
    for (auto& o : offsets) o = values.integer(offsets_type, fmt::format("{} offsets", keyword));
    if (in.expect_token("CONNECTIVITY") != "CONNECTIVITY")
      in.fail(fmt::format("expected CONNECTIVITY after the {} offsets", keyword), "fix the file");
    std::string connectivity_type(in.expect_token("the CONNECTIVITY type"));
    values.begin_section();
    std::vector<std::int64_t> connectivity(second);
    for (auto& c : connectivity) c = values.integer(connectivity_type, fmt::format("{} connectivity", keyword));
    for (std::size_t i = 0; i + 1 < offsets.size(); ++i) {
      if (offsets[i] < 0 || offsets[i] > offsets[i + 1] || offsets[i + 1] > static_cast<std::int64_t>(second))
        in.fail(fmt::format("{} offset {} is out of order or out of range", keyword, i + 1), "fix the offsets");
      block.cells.emplace_back(connectivity.begin() + offsets[i], connectivity.begin() + offsets[i + 1]);
    }
    return block;
  }
  values.begin_section();
  std::size_t used = 0;
  for (std::size_t i = 0; i < first; ++i) {
    std::int64_t size = values.integer("int", fmt::format("the node count of {} entry {}", keyword, i));
    if (size < 0 || used + 1 + static_cast<std::uint64_t>(size) > second)
      in.fail(fmt::format("{} entry {} does not fit the declared size {}", keyword, i, second),
              "fix the cell list or its size");
    used += 1 + static_cast<std::size_t>(size);
    std::vector<std::int64_t> nodes(static_cast<std::size_t>(size));
    for (auto& n : nodes) n = values.integer("int", fmt::format("a node of {} entry {}", keyword, i));
    block.cells.push_back(std::move(nodes));
  }
  if (used != second)
    in.fail(fmt::format("{} declares size {} but its entries use {}", keyword, second, used), "fix the size");
  return block;
}

}  // namespace

RawMesh parse_legacy_vtk(std::string_view text, const std::string& where) {
  TextScanner in(text, where);
  if (!trimmed(in.rest_of_line()).starts_with("# vtk DataFile"))
    fail_input(where, "line 1 is not '# vtk DataFile Version ...'",
               "this is not a legacy VTK file; check the extension or re-export it");
  in.rest_of_line();  // title
  std::string_view encoding = trimmed(in.rest_of_line());
  bool binary = encoding == "BINARY";
  if (!binary && encoding != "ASCII") {
    if (in.at_eof()) in.fail_truncated("ASCII or BINARY");
    fail_input(where, fmt::format("line 3 is {}, not ASCII or BINARY", quote_token(encoding)), "fix the header");
  }
  VtkValues values(in, binary);

  RawMesh mesh;
  std::optional<CellBlock> unstructured_cells;
  std::vector<int> cell_types;
  bool have_points = false, have_cell_types = false;
  std::string dataset;
  while (!in.at_end()) {
    std::string_view keyword = in.token();
    if (keyword == "DATASET") {
      dataset = in.expect_token("the dataset type");
      if (dataset != "UNSTRUCTURED_GRID" && dataset != "POLYDATA")
        in.fail(fmt::format("dataset type {} is not supported", quote_token(dataset)),
                "save the mesh as UNSTRUCTURED_GRID or POLYDATA");
    } else if (dataset.empty()) {
      in.fail(fmt::format("expected DATASET, found {}", quote_token(keyword)), "fix the header");
    } else if (keyword == "POINTS") {
      std::size_t count = in.count("the node count", 6);
      std::string type(in.expect_token("the POINTS data type"));
      values.begin_section();
      mesh.points.resize(count);
      for (std::size_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
          mesh.points[i][k] = values.real(type, fmt::format("coordinate {} of node {}", "xyz"[k], i));
      have_points = true;
    } else if (keyword == "METADATA") {
      in.rest_of_line();
      while (!in.at_eof() && !trimmed(in.rest_of_line()).empty()) {
      }
    } else if (keyword == "CELLS" && dataset == "UNSTRUCTURED_GRID") {
      unstructured_cells = read_cell_block(in, values, keyword);
    } else if (keyword == "CELL_TYPES" && dataset == "UNSTRUCTURED_GRID") {
      std::size_t count = in.count("the CELL_TYPES count", 2);
      values.begin_section();
      cell_types.resize(count);
      for (std::size_t i = 0; i < count; ++i)
        cell_types[i] = static_cast<int>(values.integer("int", fmt::format("the type of cell {}", i)));
      have_cell_types = true;
    } else if (dataset == "POLYDATA" &&
               (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")) {
      int vtk_type = keyword == "VERTICES" ? 2 : keyword == "LINES" ? 4 : keyword == "POLYGONS" ? 7 : 6;
      for (auto& nodes : read_cell_block(in, values, keyword).cells)
        mesh.cells.push_back(
            vtk_cell(vtk_type, std::move(nodes), {"cell", static_cast<std::int64_t>(mesh.cells.size())}));
    } else if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD") {
      break;  // attributes: nothing a mesh needs
    } else {
      in.fail(fmt::format("unexpected keyword {} in a {} dataset", quote_token(keyword), dataset),
              "fix the file or re-export it");
    }
  }
  if (dataset.empty()) in.fail_truncated("DATASET");
  if (!have_points) in.fail_truncated("POINTS");
  if (dataset == "UNSTRUCTURED_GRID") {
    if (!unstructured_cells) in.fail_truncated("CELLS");
    if (!have_cell_types) in.fail_truncated("CELL_TYPES");
    if (cell_types.size() != unstructured_cells->cells.size())
      fail_input(where, fmt::format("{} cells but {} cell types", unstructured_cells->cells.size(), cell_types.size()),
                 "CELLS and CELL_TYPES must list the same number of cells");
    for (std::size_t i = 0; i < cell_types.size(); ++i)
      mesh.cells.push_back(
          vtk_cell(cell_types[i], std::move(unstructured_cells->cells[i]), {"cell", static_cast<std::int64_t>(i)}));
  }
  return mesh;
}

std::string legacy_vtk_text(const CellTable& table) {
  fmt::memory_buffer out;
  auto put = std::back_inserter(out);
  fmt::format_to(put, "# vtk DataFile Version 3.0\n{}\nASCII\nDATASET UNSTRUCTURED_GRID\n",
                 table.shape == CellShape::quad ? "Loom quad surface" : "Loom hex mesh");
  fmt::format_to(put, "POINTS {} double\n", table.points.size());
  for (const Vec3& p : table.points) fmt::format_to(put, "{} {} {}\n", p[0], p[1], p[2]);
  const std::size_t n = table.nodes_per_cell();
  fmt::format_to(put, "CELLS {} {}\n", table.cell_count(), table.cell_count() * (n + 1));
  for (std::size_t c = 0; c < table.cell_count(); ++c) {
    fmt::format_to(put, "{}", n);
    for (std::size_t k = 0; k < n; ++k) fmt::format_to(put, " {}", table.connectivity[c * n + k]);
    fmt::format_to(put, "\n");
  }
  fmt::format_to(put, "CELL_TYPES {}\n", table.cell_count());
  for (std::size_t c = 0; c < table.cell_count(); ++c) fmt::format_to(put, "{}\n", table.vtk_type());
  if (!table.fields.empty()) fmt::format_to(put, "CELL_DATA {}\n", table.cell_count());
  for (const CellField& f : table.fields) {
    fmt::format_to(put, "SCALARS {} {} 1\nLOOKUP_TABLE default\n", f.name,
                   f.kind == CellField::Kind::integer ? "int" : "double");
    for (std::size_t c = 0; c < f.values.size(); ++c) {
      append_cell_value(out, f, c);
      fmt::format_to(put, "\n");
    }
  }
  return fmt::to_string(out);
}

}  // namespace loom
