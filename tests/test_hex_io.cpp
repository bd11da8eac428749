// Hex mesh files: .vtk .vtu .msh round-trip exactly and deterministically, in
// VTK node order; bad files give InputError.
#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "src/io/hex_io.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;
namespace fs = std::filesystem;

using loom::test::slurp;
using loom::test::spit;

namespace {

// Two unit cubes side by side along x, with one node nudged off the grid.
HexMesh two_hexes() {
  HexMesh m;
  for (double z : {0.0, 1.0})
    for (double y : {0.0, 1.0})
      for (double x : {0.0, 1.0, 2.0}) m.points.push_back({x, y, z});
  auto id = [](int x, int y, int z) { return static_cast<std::uint32_t>(x + 3 * y + 6 * z); };
  for (int x = 0; x < 2; ++x)
    m.hexes.push_back({id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0), id(x, 0, 1), id(x + 1, 0, 1),
                       id(x + 1, 1, 1), id(x, 1, 1)});
  m.points[4] = {1.0 / 3.0, 0.1 + 0.2, 1e-310};
  return m;
}

const std::vector<std::string> hex_extensions = {".vtk", ".vtu", ".msh"};

}  // namespace

TEST_CASE("every hex format round-trips points and hexes exactly") {
  test::ScratchDir dir("hex-io");
  const HexMesh mesh = two_hexes();
  for (const auto& ext : hex_extensions) {
    CAPTURE(ext);
    write_hex_mesh(dir / ("m" + ext), mesh);
    HexMesh back = read_hex_mesh(dir / ("m" + ext));
    CHECK(back.points == mesh.points);
    CHECK(back.hexes == mesh.hexes);
  }
}

TEST_CASE("cell fields are written in every format, and the mesh still reads back the same") {
  test::ScratchDir dir("hex-fields");
  const HexMesh mesh = two_hexes();
  const std::map<std::string, std::vector<std::string>> marks{
      {".vtk",
       {"CELL_DATA 2", "SCALARS source int 1", "LOOKUP_TABLE default\n3\n-1\n",
        "SCALARS quality double 1\nLOOKUP_TABLE default\n0.30000000000000004\n-0.5\n"}},
      {".vtu",
       {"<CellData Scalars=\"source\">", "type=\"Int32\" Name=\"source\"", "          3\n          -1\n",
        "type=\"Float64\" Name=\"quality\"", "          0.30000000000000004\n          -0.5\n"}},
      {".msh",
       {"$ElementData\n1\n\"source\"\n", "1 3\n2 -1\n$EndElementData", "$ElementData\n1\n\"quality\"\n",
        "1 0.30000000000000004\n2 -0.5\n$EndElementData"}}};
  const std::vector<CellField> fields{{"source", {3, -1}}, {"quality", {0.1 + 0.2, -0.5}, CellField::Kind::real}};
  for (const auto& ext : hex_extensions) {
    CAPTURE(ext);
    write_hex_mesh(dir / ("m" + ext), mesh, fields);
    const std::string text = slurp(dir / ("m" + ext));
    for (const auto& mark : marks.at(ext)) CHECK(text.find(mark) != std::string::npos);
    HexMesh back = read_hex_mesh(dir / ("m" + ext));
    CHECK(back.points == mesh.points);
    CHECK(back.hexes == mesh.hexes);
  }
  CHECK_THROWS_AS(write_hex_mesh(dir / "bad.vtk", mesh, {{"source", {1}}}), std::invalid_argument);
  CHECK_THROWS_AS(write_hex_mesh(dir / "bad.vtk", mesh, {{"source", {1, 0.5}}}), std::invalid_argument);
  CHECK_THROWS_AS(write_hex_mesh(dir / "bad.vtk", mesh, {{std::string(33, 'a'), {1, 2}}}), std::invalid_argument);
  CHECK_FALSE(fs::exists(dir / "bad.vtk"));
}

TEST_CASE("an empty hex mesh round-trips in every format") {
  test::ScratchDir dir("hex-io-empty");
  for (const auto& ext : hex_extensions) {
    CAPTURE(ext);
    write_hex_mesh(dir / ("e" + ext), HexMesh{});
    HexMesh back = read_hex_mesh(dir / ("e" + ext));
    CHECK(back.points.empty());
    CHECK(back.hexes.empty());
  }
}

TEST_CASE("hex writes are deterministic, and MSH is version 4.1 with VTK node order") {
  test::ScratchDir dir("hex-io-det");
  for (const auto& ext : hex_extensions) {
    write_hex_mesh(dir / ("a" + ext), two_hexes());
    write_hex_mesh(dir / ("b" + ext), two_hexes());
    CHECK(slurp(dir / ("a" + ext)) == slurp(dir / ("b" + ext)));
  }
  std::string msh = slurp(dir / "a.msh");
  CHECK(msh.starts_with("$MeshFormat\n4.1 0 8\n"));
  // Element 1 is the first hex with 1-based node tags, type 5 (8-node hexahedron).
  CHECK(msh.find("\n3 1 5 2\n1 1 2 5 4 7 8 11 10\n") != std::string::npos);
}

TEST_CASE("a surface file is not a hex mesh, and non-hex cells are rejected") {
  test::ScratchDir dir("hex-io-bad");
  auto message = [](const fs::path& file) -> std::string {
    try {
      read_hex_mesh(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  CHECK(message(dir / "m.obj").find("unknown hex mesh file format") != std::string::npos);
  write_hex_mesh(dir / "m.exo", two_hexes());  // written, but not read back by Loom
  CHECK(message(dir / "m.exo").find("does not read them") != std::string::npos);
  CHECK(message(dir / "missing.vtk").find("file not found") != std::string::npos);

  spit(dir / "tet.vtk",
       "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n"
       "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n");
  CHECK(message(dir / "tet.vtk").find("cell 0 is a tetrahedron, not a hexahedron") != std::string::npos);

  spit(dir / "range.vtk",
       "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 0\n"
       "CELLS 1 9\n8 0 0 0 0 0 0 0 8\nCELL_TYPES 1\n12\n");
  CHECK(message(dir / "range.vtk").find("refers to node 8") != std::string::npos);

  write_hex_mesh(dir / "m.msh", two_hexes());
  std::string text = slurp(dir / "m.msh");
  spit(dir / "cut.msh", text.substr(0, text.size() - 20));
  CHECK(message(dir / "cut.msh").find("truncated") != std::string::npos);
}

TEST_CASE("boundary quads stored beside the hexes are ignored") {
  test::ScratchDir dir("hex-io-quads");
  spit(dir / "mixed.vtk",
       "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
       "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1\n"
       "CELLS 2 14\n4 0 3 2 1\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 2\n9\n12\n");
  HexMesh m = read_hex_mesh(dir / "mixed.vtk");
  CHECK(m.hexes.size() == 1);
  CHECK(m.points.size() == 8);
}

TEST_CASE("truncated and mutated hex files give InputError, never a crash") {
  test::ScratchDir dir("hex-io-fuzz");
  std::mt19937_64 rng(11);
  for (const auto& ext : hex_extensions) {
    write_hex_mesh(dir / ("whole" + ext), two_hexes());
    const std::string text = slurp(dir / ("whole" + ext));
    for (std::size_t cut = 0; cut < text.size(); cut += 5) {
      CAPTURE(ext);
      CAPTURE(cut);
      spit(dir / ("part" + ext), text.substr(0, cut));
      try {
        HexMesh m = read_hex_mesh(dir / ("part" + ext));
        CHECK(m.hexes.size() <= 2);
      } catch (const InputError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
      }
    }
    for (int round = 0; round < 40; ++round) {
      std::string bytes = text;
      for (int k = 0; k < 1 + round % 4; ++k) bytes[rng() % bytes.size()] = "0123456789-.e $\n x#"[rng() % 19];
      spit(dir / ("fuzz" + ext), bytes);
      try {
        read_hex_mesh(dir / ("fuzz" + ext));
      } catch (const InputError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
      }
    }
  }
}
