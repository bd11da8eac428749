// `loom stc` end to end, `--dot` output, and the one-line, exit-2 contract for
// every bad input under tests/data/bad.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "src/io/hex_io.hpp"
#include "tests/support.hpp"

using loom::test::run_cli;
using loom::test::ScratchDir;
namespace fs = std::filesystem;

using loom::test::slurp;

namespace {
nlohmann::json stc_json(const fs::path& mesh) {
  auto r = run_cli("stc " + mesh.string() + " --json");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  return nlohmann::json::parse(r.out);
}

// Hexes of the unit cube at x, y, z, numbered on a 3 x 3 x 4 lattice of points.
loom::HexMesh lattice_hexes(const std::vector<std::array<int, 3>>& cubes) {
  loom::HexMesh m;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) m.points.push_back({double(x), double(y), double(z)});
  auto id = [](int x, int y, int z) { return static_cast<std::uint32_t>(x + 3 * y + 9 * z); };
  for (auto [x, y, z] : cubes)
    m.hexes.push_back({id(x, y, z), id(x + 1, y, z), id(x + 1, y + 1, z), id(x, y + 1, z), id(x, y, z + 1),
                       id(x + 1, y, z + 1), id(x + 1, y + 1, z + 1), id(x, y + 1, z + 1)});
  return m;
}

}  // namespace

TEST_CASE("loom stc refuses a hex mesh that fails a combinatorial criterion, naming it (exit 2)") {
  ScratchDir dir("stc-invalid");
  loom::HexMesh along_edge = lattice_hexes({{0, 0, 0}, {1, 1, 0}});
  loom::HexMesh face_thrice = lattice_hexes({{0, 0, 0}, {0, 0, 1}, {0, 0, 1}});
  loom::HexMesh degenerate = lattice_hexes({{0, 0, 0}});
  degenerate.hexes[0][6] = degenerate.hexes[0][5];
  loom::HexMesh inverted = lattice_hexes({{0, 0, 0}});  // only criterion 7 fails: it has an STC
  std::swap(inverted.hexes[0][1], inverted.hexes[0][3]);
  std::swap(inverted.hexes[0][5], inverted.hexes[0][7]);
  const std::pair<loom::HexMesh, std::string> cases[] = {
      {along_edge, "criterion 4 (manifold) fails: around edge"},
      {face_thrice, "criterion 2 (faces in one or two hexes) fails: hexes 1 and 2 are the same hex"},
      {degenerate, "criterion 1 (distinct nodes) fails: hex 0 uses node"},
  };
  for (const auto& [mesh, expected] : cases) {
    CAPTURE(expected);
    loom::write_hex_mesh(dir / "bad.vtk", mesh);
    auto r = run_cli("stc " + (dir / "bad.vtk").string() + " --dot " + (dir / "dot").string());
    CHECK(r.status == 2);
    CHECK(loom::test::count_lines(r.err) == 1);
    CHECK(r.err.rfind("loom: error: " + (dir / "bad.vtk").string() + ": not a valid hex mesh", 0) == 0);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "dot"));
  }
  loom::write_hex_mesh(dir / "inverted.vtk", inverted);
  CHECK(run_cli("stc " + (dir / "inverted.vtk").string()).status == 0);
}

TEST_CASE("loom stc reports hexes, sheets and chords of a hex grid") {
  ScratchDir dir("stc");
  REQUIRE(run_cli("gen hexgrid 3 4 5 -o " + (dir / "grid.vtk").string()).status == 0);
  auto j = stc_json(dir / "grid.vtk");
  CHECK(j["hexes"] == 60);
  CHECK(j["sheets"] == 12);
  CHECK(j["chords"] == 47);
  CHECK(j["self_intersecting_sheets"] == 0);
  auto text = run_cli("stc " + (dir / "grid.vtk").string());
  CHECK(text.out.find("60 hexes") != std::string::npos);
  CHECK(text.out.find("12 sheets, 47 chords") != std::string::npos);
}

TEST_CASE("loom stc reports the loops of a surface") {
  ScratchDir dir("stc");
  SUBCASE("box 3 4 5: twelve loops") {
    REQUIRE(run_cli("gen box 3 4 5 -o " + (dir / "box.obj").string()).status == 0);
    auto j = stc_json(dir / "box.obj");
    CHECK(j["loops"] == 12);
    CHECK(j["chords"] == 94);
    CHECK(j["self_intersecting_sheets"] == 0);
  }
  SUBCASE("Schneiders' pyramid: two loops, one crossing itself in 8 quads") {
    REQUIRE(run_cli("gen schneiders -o " + (dir / "pyr.off").string()).status == 0);
    auto j = stc_json(dir / "pyr.off");
    CHECK(j["loops"] == 2);
    CHECK(j["self_intersecting_sheets"] == 1);
    int crossing = 0;
    for (auto& sh : j["sheet_list"])
      if (sh["self_intersecting"] == true) crossing = sh["self_crossing_quads"];
    CHECK(crossing == 8);
    auto text = run_cli("stc " + (dir / "pyr.off").string());
    CHECK(text.out.find("crosses itself in 8 quads") != std::string::npos);
    CHECK(j["genus"] == 0);
  }
  SUBCASE("a torus has genus 1") {
    REQUIRE(run_cli("gen torus 4 6 -o " + (dir / "torus.vtk").string()).status == 0);
    CHECK(stc_json(dir / "torus.vtk")["genus"] == 1);
  }
}

TEST_CASE("loom stc --dot writes DOT that Graphviz accepts, the same on every run") {
  ScratchDir dir("dot");
  REQUIRE(run_cli("gen hexgrid 2 2 3 -o " + (dir / "grid.msh").string()).status == 0);
  REQUIRE(run_cli("gen schneiders -o " + (dir / "pyr.obj").string()).status == 0);
  for (std::string mesh : {"grid.msh", "pyr.obj"}) {
    auto out1 = dir / (mesh + ".dot1"), out2 = dir / (mesh + ".dot2");
    REQUIRE(run_cli("stc " + (dir / mesh).string() + " --dot " + out1.string()).status == 0);
    REQUIRE(run_cli("stc " + (dir / mesh).string() + " --dot " + out2.string()).status == 0);
    int dots = 0;
    for (auto& entry : fs::directory_iterator(out1)) {
      if (entry.path().extension() != ".dot") continue;
      ++dots;
      std::string cmd = "dot -Tsvg " + entry.path().string() + " -o /dev/null 2>/dev/null";
      CHECK_MESSAGE(std::system(cmd.c_str()) == 0, entry.path());
      CHECK(slurp(entry.path()) == slurp(out2 / entry.path().filename()));
      auto svg = entry.path();
      svg.replace_extension(".svg");
      CHECK(slurp(svg).find("<svg") != std::string::npos);
    }
    CHECK(dots >= 3);  // stc.dot and at least two sheets
    CHECK(fs::exists(out1 / "sheet-0.dot"));
  }
}

TEST_CASE("every bad input: exit 2, one clear line, nothing written") {
  std::ifstream manifest(loom::test::data("bad/expected.tsv"));
  REQUIRE(manifest);
  std::string line;
  int cases = 0;
  while (std::getline(manifest, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto tab = line.find('\t');
    REQUIRE(tab != std::string::npos);
    std::string file = line.substr(0, tab), expected = line.substr(tab + 1);
    ScratchDir out("bad");
    auto r = run_cli("stc " + loom::test::data("bad/" + file).string() + " --dot " + (out / "dot").string());
    CAPTURE(file);
    CAPTURE(r.err);
    CHECK(r.status == 2);
    CHECK(loom::test::count_lines(r.err) == 1);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK(r.err.rfind("loom: error: ", 0) == 0);
    CHECK_FALSE(fs::exists(out / "dot"));
    ++cases;
  }
  CHECK(cases >= 15);
}

TEST_CASE("bad usage: exit 2 and one line") {
  for (std::string args : {"", "stc", "frobnicate", "stc --bogus x.obj", "stc /no/such/file.obj",
                           "gen box 0 1 1 -o /tmp/never.obj", "gen nosuchkind -o /tmp/never.obj"}) {
    auto r = run_cli(args);
    CAPTURE(args);
    CAPTURE(r.err);
    CHECK(r.status == 2);
    CHECK(loom::test::count_lines(r.err) == 1);
  }
  CHECK_FALSE(fs::exists("/tmp/never.obj"));
}
