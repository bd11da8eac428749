// `loom gen` and `loom check` end to end: files, verdicts, exit statuses.
#include <doctest/doctest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/check/quality_histogram.hpp"
#include "src/gen/generators.hpp"
#include "src/io/hex_io.hpp"
#include "src/io/surface_io.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::count_lines;
using loom::test::run_cli;
using loom::test::ScratchDir;

using loom::test::slurp;

namespace {

/// Writes `mesh` to dir/name and returns `loom check` of it against dir/box.obj.
test::CliResult check_against_box(const ScratchDir& dir, const std::string& name, const HexMesh& mesh) {
  write_hex_mesh(dir / name, mesh);
  return run_cli("check " + (dir / name).string() + " --boundary " + (dir / "box.obj").string());
}

}  // namespace

TEST_CASE("gen hexgrid then check against the box surface: valid, exit 0") {
  ScratchDir dir("cli-check");
  const auto grid = dir / "grid.vtk", box = dir / "box.obj";
  auto r = run_cli("gen hexgrid 3 4 5 -o " + grid.string());
  REQUIRE(r.status == 0);
  CHECK(r.out == "wrote " + grid.string() + ": hex mesh hexgrid 3 4 5, 60 hexes, 120 nodes\n");
  r = run_cli("gen box 3 4 5 -o " + box.string());
  REQUIRE(r.status == 0);
  CHECK(r.out == "wrote " + box.string() + ": surface box 3 4 5, 94 quads, 96 nodes\n");

  r = run_cli("check " + grid.string() + " --boundary " + box.string());
  CHECK(r.status == 0);
  CHECK(r.out == "valid: 60 hexes, min scaled Jacobian 1.000, mean 1.000, 0 below 0.2\n");
  CHECK(r.err.empty());

  r = run_cli("check " + grid.string() + " --json");
  CHECK(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["valid"] == true);
  CHECK(j["hexes"] == 60);
  CHECK(j["min_scaled_jacobian"] == 1.0);
  CHECK(j["criteria"].size() == 6);
}

TEST_CASE("broken meshes: exit 1 and the verdict names the criterion") {
  ScratchDir dir("cli-broken");
  REQUIRE(run_cli("gen box 3 4 5 -o " + (dir / "box.obj").string()).status == 0);
  const HexMesh grid = gen::hexgrid(3, 4, 5);

  SUBCASE("a deleted hex") {
    HexMesh m = grid;
    m.hexes.erase(m.hexes.begin() + 25);
    const auto r = check_against_box(dir, "deleted.vtk", m);
    CHECK(r.status == 1);
    CHECK(r.out.rfind("invalid: criterion 6 (boundary matches surface) fails: ", 0) == 0);
    CHECK(count_lines(r.out) == 1);
  }
  SUBCASE("a duplicated hex") {
    HexMesh m = grid;
    m.hexes.push_back(m.hexes[9]);
    const auto r = check_against_box(dir, "duplicated.vtu", m);
    CHECK(r.status == 1);
    CHECK(r.out.rfind("invalid: criterion 2 (faces in one or two hexes) fails: hexes 9 and 60 are the same hex", 0) ==
          0);
  }
  SUBCASE("an inverted hex") {
    HexMesh m = grid;
    std::swap(m.hexes[31][1], m.hexes[31][3]);
    std::swap(m.hexes[31][5], m.hexes[31][7]);
    const auto r = check_against_box(dir, "inverted.msh", m);
    CHECK(r.status == 1);
    CHECK(r.out ==
          "invalid: criterion 7 (positive scaled Jacobian) fails: hex 31 has scaled Jacobian -1.000 "
          "(1 hex at or below 0)\n");
  }
  SUBCASE("two hexes sharing two faces") {
    HexMesh m = gen::hexgrid(1, 1, 1);
    m.points.push_back({2, 2, 0});
    m.points.push_back({2, 2, 1});
    const Hex a = m.hexes[0];
    m.hexes.push_back({8, a[1], a[2], a[3], 9, a[5], a[6], a[7]});
    write_hex_mesh(dir / "doublet.vtk", m);
    const auto r = run_cli("check " + (dir / "doublet.vtk").string() + " --json");
    CHECK(r.status == 1);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["valid"] == false);
    CHECK(j["criteria"][2]["detail"] == "hexes 0 and 1 share 2 faces");
    CHECK(j["verdict"].get<std::string>().rfind("invalid: criterion 3 (no doublets)", 0) == 0);
  }
}

TEST_CASE("bad usage and bad input: exit 2, one line on stderr, nothing on stdout") {
  ScratchDir dir("cli-bad");
  const auto grid = dir / "grid.vtk";
  REQUIRE(run_cli("gen hexgrid 2 2 2 -o " + grid.string()).status == 0);
  std::ofstream(dir / "empty.obj") << "# nothing\n";
  std::ofstream(dir / "garbage.vtk") << "not a mesh\n";
  for (const std::string& args : std::vector<std::string>{
           "check " + grid.string() + " --bogus", "check", "check " + (dir / "missing.vtk").string(),
           "check " + grid.string() + " --boundary " + (dir / "missing.obj").string(),
           "check " + (dir / "garbage.vtk").string(), "check " + (dir / "empty.obj").string(),
           "check " + grid.string() + " --boundary " + grid.string()}) {
    CAPTURE(args);
    const auto r = run_cli(args);
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.rfind("loom: error: ", 0) == 0);
    CHECK(r.out.empty());
  }
}

TEST_CASE("gen: bad arguments exit 2 and write nothing") {
  ScratchDir dir("cli-gen-bad");
  const auto out = dir / "out.obj";
  for (const std::string args : {"box 0 1 1", "box 1 2", "box 1 2 3 4", "box x 1 1", "box 1.5 1 1", "pyramid 3",
                                 "torus 2 4", "torus 3 3", "hexgrid 2 2 2", "box 9999999 9999999 1", "cylinder 2"}) {
    CAPTURE(args);
    const auto r = run_cli("gen " + args + " -o " + out.string());
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(out));
  }
  const auto r = run_cli("gen box 1 1 1");
  CHECK(r.status == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(run_cli("gen box 1 1 1 -o " + (dir / "out.txt").string()).status == 2);
  CHECK(std::filesystem::is_empty(dir.path()));
}

TEST_CASE("gen: every kind writes a readable file, byte-identical on a second run") {
  ScratchDir dir("cli-gen-kinds");
  const std::vector<std::pair<std::string, std::size_t>> surfaces{
      {"box 2 3 4", 52},    {"lshape 2", 56},  {"cylinder 2 3", 2 * (4 + 8) + 24},
      {"cubesphere 3", 54}, {"torus 6 4", 24}, {"schneiders", 16},
      {"tet4", 12},         {"spindle", 8},    {"odd7", 7}};
  for (const auto& [args, quads] : surfaces)
    for (const char* ext : {".obj", ".off", ".vtk", ".vtu", ".msh"}) {
      if (std::string(ext) != ".obj" && args != "cylinder 2 3") continue;  // every format once is enough
      CAPTURE(args);
      CAPTURE(ext);
      const auto a = dir / (std::string("a") + ext), b = dir / (std::string("b") + ext);
      REQUIRE(run_cli("gen " + args + " -o " + a.string()).status == 0);
      REQUIRE(run_cli("gen " + args + " -o " + b.string()).status == 0);
      CHECK(read_surface(a).quads.size() == quads);
      CHECK(slurp(a) == slurp(b));
    }
  for (const auto& [args, hexes] :
       std::vector<std::pair<std::string, std::size_t>>{{"hexgrid 2 1 3", 6}, {"ogrid 2 2", 24}}) {
    CAPTURE(args);
    const auto a = dir / "a.vtu";
    REQUIRE(run_cli("gen " + args + " -o " + a.string()).status == 0);
    CHECK(read_hex_mesh(a).hexes.size() == hexes);
  }
  REQUIRE(run_cli("gen ogrid 3 2 -o " + (dir / "o.msh").string()).status == 0);
  REQUIRE(run_cli("gen cylinder 3 2 -o " + (dir / "c.off").string()).status == 0);
  CHECK(run_cli("check " + (dir / "o.msh").string() + " --boundary " + (dir / "c.off").string()).status == 0);
}

TEST_CASE("the scaled Jacobians as a histogram: in check --json, weave's report, and --plot as SVG") {
  ScratchDir dir("histogram");
  HexMesh grid = gen::hexgrid(2, 1, 1);
  QualityHistogram perfect = quality_histogram(grid);
  CHECK(perfect.total() == 2);
  CHECK(perfect.counts.back() == 2);  // scaled Jacobian 1 goes in the last bin, closed at 1
  // Swapping the two faces of one hex turns it inside out: -1, the first bin.
  Hex& h = grid.hexes[1];
  for (int i = 0; i < 4; ++i) std::swap(h[i], h[i + 4]);
  QualityHistogram one_inverted = quality_histogram(grid);
  CHECK(one_inverted.counts.front() == 1);
  CHECK(one_inverted.counts.back() == 1);
  const std::string svg = histogram_svg(one_inverted, "a & <b>");
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg.find("a &amp; &lt;b&gt;") != std::string::npos);
  std::size_t bars = 0;
  for (auto at = svg.find("<rect x="); at != std::string::npos; at = svg.find("<rect x=", at + 1)) ++bars;
  CHECK(bars == 20);

  write_hex_mesh(dir / "bad.vtk", grid);
  auto r = run_cli("check " + (dir / "bad.vtk").string() + " --json --plot " + (dir / "bad.svg").string());
  CHECK(r.status == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["scaled_jacobian_histogram"]["counts"][0] == 1);
  CHECK(j["scaled_jacobian_histogram"]["counts"][19] == 1);
  CHECK(slurp(dir / "bad.svg").rfind("<svg", 0) == 0);

  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "box.vtk").string() + " --report " +
              (dir / "box.json").string() + " --plot " + (dir / "box.svg").string());
  REQUIRE(r.status == 0);
  const auto report = nlohmann::json::parse(slurp(dir / "box.json"));
  CHECK(report["scaled_jacobian_histogram"]["counts"][19] == 8);
  CHECK(slurp(dir / "box.svg").find("scaled Jacobian (8 hexes)") != std::string::npos);
}

TEST_CASE("loom check of a twisted hex: exit 0 by criterion 7, and the line and JSON say its centre is not positive") {
  ScratchDir dir("cli-twisted");
  HexMesh m;  // one hex of quadrangulation 12 4 as placed before the untangler saw centres
  m.points = {{0.329, 0.577, 0.126}, {0.529, 0.499, 0.198}, {0.399, 0.0, 0.379}, {0.696, 0.776, 0.0},
              {0.3, 0.594, 0.148},   {1.0, 0.48, 0.208},   {0.434, 0.177, 0.337}, {0.0, 0.758, 0.288}};
  m.hexes = {{0, 1, 2, 3, 4, 5, 6, 7}};
  write_hex_mesh(dir / "twisted.vtk", m);
  auto r = run_cli("check " + (dir / "twisted.vtk").string());
  CHECK(r.status == 0);
  CHECK_MESSAGE(r.out.find("; but 1 hex with every corner positive has a centre Jacobian <= 0") != std::string::npos, r.out);
  r = run_cli("check " + (dir / "twisted.vtk").string() + " --json");
  CHECK(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["valid"] == true);
  CHECK(j["verdict_below_zero"] == 1);
  CHECK(j["verdict_min_scaled_jacobian"].get<double>() == doctest::Approx(-0.716).epsilon(0.01));
}
