// The constructive fill (src/fill): its plan, the caps it reads, the meshes it
// builds (criteria 1-6 on every surface tried), and `loom weave` using it when
// no weave closes.
#include <doctest/doctest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/fill/cap.hpp"
#include "src/fill/fill.hpp"
#include "src/fill/fill_plan.hpp"
#include "src/gen/generators.hpp"
#include "src/geometry/boundary_layer.hpp"
#include "src/io/hex_io.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/util/error.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

const std::vector<fill::Cap>& shipped_caps() {
  static const auto caps = fill::load_caps(fill::default_caps_dir());
  return caps;
}

void write(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST_CASE("fill plan: a proper two-colouring and a perfect matching of the quads") {
  for (int f : {6, 12, 30, 80})
    for (std::uint64_t seed : {1, 2, 3}) {
      CAPTURE(f);
      CAPTURE(seed);
      QuadSurface s = gen::randquad(f, seed);
      fill::FillPlan plan = fill::plan_fill(s);
      for (const auto& [u, v] : plan.edge_nodes) CHECK(plan.white[u] != plan.white[v]);
      for (std::uint32_t q = 0; q < s.quads.size(); ++q) {
        int even = 0;
        for (std::uint32_t e : plan.quad_edges[q]) even += plan.even_edge[e];
        CHECK(even == 1);
        CHECK(plan.mate[plan.mate[q]] == q);
        CHECK(plan.mate[q] != q);
        // The mate is across the even edge: the two quads share it.
        std::uint32_t shared = 0;
        for (std::uint32_t e : plan.quad_edges[q])
          for (std::uint32_t f : plan.quad_edges[plan.mate[q]]) shared += e == f && plan.even_edge[e];
        CHECK(shared == 1);
      }
    }
}

TEST_CASE("fill: criteria 1-6 hold on block shapes, spheres and random quadrangulations") {
  std::vector<std::pair<std::string, QuadSurface>> cases = {
      {"box 2 2 2", gen::box(2, 2, 2)}, {"lshape 2", gen::lshape(2)}, {"tet4", gen::tet4()},
      {"cubesphere 3", gen::cubesphere(3)}, {"schneiders", gen::schneiders()}};
  for (int f = 6; f <= 40; f += 2) cases.push_back({fmt::format("randquad {}", f), gen::randquad(f, std::uint64_t(f))});
  for (const auto& [name, surface] : cases) {
    CAPTURE(name);
    fill::FilledMesh m = fill::fill_constructively(surface, shipped_caps());
    ValidityReport check = check_hex_mesh(m.mesh, &surface);
    const CriterionResult* failed = check.first_failure();
    CHECK_MESSAGE(check.combinatorial_valid(), (failed ? failed->detail : std::string()));
    CHECK(m.core_hexes == 8 * surface.quads.size());  // two tets a quad, four hexes a tet
    CHECK(m.cap_hexes + m.core_hexes == m.mesh.hexes.size());
    // The published bound (Verhetsel, Pellerin & Remacle 2019): a cap of 36,
    // its pillow of 18, half its pair's pillow of 32 and 8 core hexes a quad.
    CHECK(m.mesh.hexes.size() == 78 * surface.quads.size());
    for (std::size_t v = 0; v < m.on_boundary.size(); ++v) CHECK(m.on_boundary[v] == (v < surface.points.size()));
  }
}

TEST_CASE("fill: what it cannot fill is an input error that says why") {
  QuadSurface odd = gen::odd7();
  CHECK_THROWS_WITH_AS(fill::fill_constructively(odd, shipped_caps()), doctest::Contains("even"), InputError);
  QuadSurface torus = gen::torus(4, 4);
  CHECK_THROWS_WITH_AS(fill::fill_constructively(torus, shipped_caps()), doctest::Contains("Euler characteristic 0"),
                       InputError);
}

TEST_CASE("caps: a malformed line names its file and line; a missing cap is reported") {
  loom::test::ScratchDir dir("caps");
  for (const auto& e : std::filesystem::directory_iterator(fill::default_caps_dir()))
    std::filesystem::copy_file(e.path(), dir / e.path().filename());
  CHECK(fill::load_caps(dir.path()).size() == shipped_caps().size());
  write(dir / "cap_even_ab.cap", "even ab\nhex a_t b_t c_t d_t a_b b_b c_b x_q\n");
  CHECK_THROWS_WITH_AS(fill::load_caps(dir.path()), doctest::Contains("cap_even_ab.cap: line 2: 'x_q' is not a cap node"),
                       InputError);
  std::filesystem::remove(dir / "cap_even_ab.cap");
  CHECK_THROWS_WITH_AS(fill::load_caps(dir.path()), doctest::Contains("no cap with even wall ab"), InputError);
}

TEST_CASE("pillow_region: one hex on each quad of the region's boundary, the rest of the mesh untouched") {
  HexMesh grid = gen::hexgrid(3, 1, 1);  // hexes 0 1 2 in a row
  std::vector<bool> fixed(grid.points.size(), false);
  const Hex last = grid.hexes[2];
  auto report = geometry::pillow_region(grid, 0, 2, fixed);
  CHECK(report.hexes_added == 10);  // the two-hex block's boundary
  CHECK(grid.hexes.size() == 13);
  CHECK(grid.hexes[2] == last);
  CHECK(check_hex_mesh(grid).combinatorial_valid());
}

TEST_CASE("loom weave closes what no weave closes; --closure none (or --no-fill) stops instead") {
  loom::test::ScratchDir dir("fillcli");
  std::filesystem::create_directory(dir / "rules");
  std::filesystem::copy_file(weave::default_rules_dir() / "cross.rule", dir / "rules" / "cross.rule");
  REQUIRE(loom::test::run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  std::string args = "weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --attempts 2 --rules " +
                     (dir / "rules").string() + " --report " + (dir / "r.json").string();
  // Crossing without seaming never closes: the closure meshes the box instead.
  auto r = loom::test::run_cli(args);
  CHECK((r.status == 0 || r.status == 3));
  auto j = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  CHECK(j["closed"] == false);
  CHECK(j["combinatorially_valid"] == true);
  CHECK((j["made_by"] == "closed" || j["made_by"] == "searched"));
  CHECK(r.out.rfind(j["made_by"].get<std::string>() + ": ", 0) == 0);
  CHECK(j["hex_sources"]["woven"].get<std::size_t>() + j["hex_sources"]["searched"].get<std::size_t>() +
            j["hex_sources"]["database"].get<std::size_t>() + j["hex_sources"]["filled"].get<std::size_t>() +
            j["hex_sources"]["pillow"].get<std::size_t>() ==
        j["hexes"].get<std::size_t>());
  // The quality per source adds up to the mesh's, and each source's histogram to its hexes.
  std::size_t inverted = 0;
  for (const auto& [name, q] : j["quality_by_source"].items()) {
    CHECK(q["hexes"] == j["hex_sources"][name]);
    std::size_t binned = 0;
    for (const auto& c : q["scaled_jacobian_histogram"]["counts"]) binned += c.get<std::size_t>();
    CHECK(binned == q["hexes"].get<std::size_t>());
    CHECK(q["min_scaled_jacobian"].get<double>() >= j["min_scaled_jacobian"].get<double>());
    inverted += q["inverted"].get<std::size_t>();
  }
  CHECK(inverted == j["below_zero"].get<std::size_t>());
  // Each hex's source (0 woven ... 4 pillow) and scaled Jacobian as cell fields, as many values as hexes.
  const std::string vtk = loom::test::slurp(dir / "out.vtk");
  const auto source = vtk.find("SCALARS source int 1\nLOOKUP_TABLE default\n");
  const auto quality = vtk.find("SCALARS scaled_jacobian double 1\nLOOKUP_TABLE default\n");
  REQUIRE(source != std::string::npos);
  REQUIRE(quality != std::string::npos);
  CHECK(loom::test::count_lines(vtk.substr(source, quality - source)) == 2 + j["hexes"].get<int>());
  const auto sheet = vtk.find("SCALARS sheet_i int 1\nLOOKUP_TABLE default\n");
  REQUIRE(sheet != std::string::npos);
  CHECK(loom::test::count_lines(vtk.substr(quality, sheet - quality)) == 2 + j["hexes"].get<int>());
  auto check = loom::test::run_cli("check " + (dir / "out.vtk").string() + " --boundary " + (dir / "box.obj").string());
  CHECK((check.status == 0 || check.out.find("criterion 7") != std::string::npos));  // only the geometry may fail
  std::filesystem::remove(dir / "out.vtk");
  CHECK(loom::test::run_cli(args + " --partial").status == r.status);  // the weave's state, beside the mesh
  CHECK(std::filesystem::exists(dir / "out.partial.vtk"));
  for (const char* off : {" --closure none", " --no-fill"}) {
    std::filesystem::remove(dir / "out.vtk");
    r = loom::test::run_cli(args + off);
    CHECK(r.status == 1);
    CHECK(r.err.find("weave did not close") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
  }
  CHECK(loom::test::run_cli(args + " --closure sometimes").status == 2);
}

TEST_CASE("a rules directory brings its own closure database and fill caps, or none") {
  const auto shipped = pipeline::default_meshing_options(weave::default_rules_dir());
  CHECK(shipped.database == closure::database_file(weave::default_rules_dir()));
  CHECK(shipped.fill_caps == fill::default_caps_dir());

  loom::test::ScratchDir dir("rulesdb");
  std::filesystem::create_directory(dir / "rules");
  std::filesystem::copy_file(weave::default_rules_dir() / "cross.rule", dir / "rules" / "cross.rule");
  const auto bare = pipeline::default_meshing_options(dir / "rules");
  CHECK(bare.database.empty());
  CHECK(bare.fill_caps.empty());

  // Crossing alone never closes the box: what closes it is the search, with
  // the database only where the rules directory has one.
  REQUIRE(loom::test::run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  const std::string args = "weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() +
                           " --attempts 1 --rules " + (dir / "rules").string() + " --report " + (dir / "r.json").string();
  auto r = loom::test::run_cli(args);
  CHECK_MESSAGE((r.status == 0 || r.status == 3), r.err);
  auto j = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  CHECK(j["hex_sources"]["database"] == 0);
  CHECK(j["hex_sources"]["searched"].get<int>() > 0);

  std::filesystem::copy(weave::default_rules_dir() / "closure", dir / "rules" / "closure");
  const auto with_database = pipeline::default_meshing_options(dir / "rules");
  CHECK(with_database.database == closure::database_file(dir / "rules"));
  CHECK(with_database.fill_caps.empty());
}
