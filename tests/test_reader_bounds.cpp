// Counts in a mesh file are checked against the bytes that follow them before
// anything is sized by them: a crafted count gives one InputError line, never a
// wrapped multiplication, an overflow or a huge allocation (issue 15).
#include <doctest/doctest.h>

#include <string>

#include "src/io/formats.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

std::string error_of(RawMesh (*parse)(std::string_view, const std::string&), const std::string& text) {
  try {
    parse(text, "crafted");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string vtu_piece(const std::string& points, const std::string& coordinates, const std::string& cells,
                      const std::string& connectivity, const std::string& offsets, const std::string& types) {
  return "<Piece NumberOfPoints=\"" + points + "\" NumberOfCells=\"" + cells + "\"><Points>" +
         "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" + coordinates +
         "</DataArray></Points><Cells>" + "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         connectivity + "</DataArray>" + "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
         "</DataArray>" + "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + types +
         "</DataArray></Cells></Piece>";
}

std::string vtu_file(const std::string& pieces) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\"><UnstructuredGrid>" + pieces +
         "</UnstructuredGrid></VTKFile>\n";
}

// A count of 1000 items after which only `filler` bytes of blanks remain: fewer
// than 1000 items can fit, yet more bytes than 1000.
const std::string filler(1500, ' ');

}  // namespace

TEST_CASE("VTU: a point count whose 3 x count wraps to the values present is refused") {
  // 3 * 6148914691236517206 is 2 modulo 2^64: the two coordinates given.
  const std::string text = vtu_file(vtu_piece("6148914691236517206", "0 0", "0", "", "", ""));
  std::string message = error_of(parse_vtu, text);
  CHECK(contains(message, "piece 0 Points has 2 values, expected 3 for each of 6148914691236517206"));

  test::ScratchDir dir("reader-bounds");
  test::spit(dir / "wrap.vtu", text);
  auto r = test::run_cli("check " + (dir / "wrap.vtu").string());
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(contains(r.err, "expected 3 for each of 6148914691236517206"));
}

TEST_CASE("VTU: a node index too large for its piece is refused before the piece offset is added") {
  const std::string one_point = vtu_piece("1", "0 0 0", "0", "", "", "");
  const std::string bad_vertex = vtu_piece("1", "1 1 1", "1", "9223372036854775807", "1", "1");
  std::string message = error_of(parse_vtu, vtu_file(one_point + bad_vertex));
  CHECK(contains(message, "piece 1 cell 0 refers to node 9223372036854775807, but the piece has 1 points"));
}

TEST_CASE("OFF: node and face counts larger than the rest of the file can hold are refused") {
  CHECK(contains(error_of(parse_off, "OFF\n1000 0 0\n" + filler + "0 0 0\n"),
                 "the node count is 1000, which this file cannot hold"));
  CHECK(contains(error_of(parse_off, "OFF\n0 1000 0\n" + filler + "0\n"),
                 "the face count is 1000, which this file cannot hold"));
}

TEST_CASE("legacy VTK ASCII: a POINTS count larger than the rest of the file can hold is refused") {
  const std::string text = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1000 double\n" +
                           filler + "0 0 0\n";
  CHECK(contains(error_of(parse_legacy_vtk, text), "the node count is 1000, which this file cannot hold"));
}

TEST_CASE("legacy VTK BINARY: CELLS and CELL_TYPES counts larger than the payload are refused") {
  const std::string header = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 0 double\n";
  const std::string payload(1500, '\0');
  CHECK(contains(error_of(parse_legacy_vtk, header + "CELLS 1000 8 OFFSETS vtktypeint64\n" + payload),
                 "the CELLS count is 1000, which this file cannot hold"));
  CHECK(contains(error_of(parse_legacy_vtk, header + "CELL_TYPES 1000\n" + payload),
                 "the CELL_TYPES count is 1000, which this file cannot hold"));
}

TEST_CASE("MSH: node counts larger than the rest of the file can hold are refused") {
  const std::string v4 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000 1 1000\n" + filler;
  CHECK(contains(error_of(parse_msh_ascii, v4), "the node count is 1000, which this file cannot hold"));
  const std::string v4_block = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n3 1 0 1000\n" + filler;
  CHECK(contains(error_of(parse_msh_ascii, v4_block), "a node block's node count is 1000, which this file cannot hold"));
  const std::string v2 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000\n" + filler;
  CHECK(contains(error_of(parse_msh_ascii, v2), "the node count is 1000, which this file cannot hold"));
}
