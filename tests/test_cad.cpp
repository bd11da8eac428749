// loom mesh's first stage (cad/cad_part.hpp) and the command itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <nlohmann/json.hpp>

#include "src/cad/cad_part.hpp"
#include "src/check/surface_angle_bound.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"
#include "support.hpp"

using namespace loom;
using loom::test::run_cli;
using loom::test::ScratchDir;
using loom::test::slurp;
using loom::test::spit;

namespace {

const std::filesystem::path examples = std::filesystem::path(LOOM_SOURCE_DIR) / "examples";

std::array<double, 6> bounding_box(const QuadSurface& s) {
  std::array<double, 6> box{1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
  for (const Vec3& p : s.points)
    for (int a = 0; a < 3; ++a) {
      box[a] = std::min(box[a], p[a]);
      box[a + 3] = std::max(box[a + 3], p[a]);
    }
  return box;
}

}  // namespace

TEST_CASE("cad part: the bundled bracket, as .geo and as STEP, becomes an even closed genus-0 quad surface") {
  const auto geo = cad::quad_surface_of_part(examples / "bracket.geo", 6.0);
  const auto step = cad::quad_surface_of_part(examples / "bracket.step", 6.0);
  for (const auto* part : {&geo, &step}) {
    CHECK(part->faces == 18);
    CHECK(part->size == 6.0);
    CHECK(part->surface.quads.size() % 2 == 0);
    QuadSurface s = part->surface;
    const SurfaceSummary summary = validate_surface(s, "bracket");
    CHECK(summary.genus == 0);
    CHECK(!summary.flipped);
    // The nodes lie on the part: its outline [0,60]x[0,40]x[0,28] is reached, not passed.
    const auto box = bounding_box(s);
    const std::array<double, 6> outline{0, 0, 0, 60, 40, 28};
    for (int i = 0; i < 6; ++i) CHECK(box[i] == doctest::Approx(outline[i]).epsilon(1e-9));
  }
  // The STEP file is the .geo's export: Gmsh meshes the same faces alike.
  CHECK(step.surface.quads.size() == geo.surface.quads.size());

  // The default size is the diagonal / 12; a finer size gives more quads; a rerun the same mesh.
  const auto coarse = cad::quad_surface_of_part(examples / "bracket.geo", std::nullopt);
  CHECK(coarse.size == doctest::Approx(coarse.diagonal / cad::kDefaultDivisions));
  CHECK(coarse.diagonal == doctest::Approx(std::hypot(60.0, 40.0, 28.0)).epsilon(1e-6));
  CHECK(geo.surface.quads.size() > coarse.surface.quads.size());
  const auto again = cad::quad_surface_of_part(examples / "bracket.geo", 6.0);
  CHECK(again.surface.points == geo.surface.points);
  CHECK(again.surface.quads == geo.surface.quads);
}

TEST_CASE("cad part: the other bundled parts become even closed quad surfaces of their genus") {
  struct Part {
    const char* file;
    int faces;
    int genus;
  };
  // A ball; a flange (a hub on a disc, a bore and four bolt holes); a filleted
  // tee of two bars; an angle of two thin walls, filleted, a hole in each; a
  // washer; a link with a hole at each end and a slot; a grate of 3 x 2 holes.
  for (const Part& p : {Part{"sphere.geo", 1, 0}, Part{"flange.geo", 10, 5}, Part{"tee.geo", 7, 0},
                        Part{"wall.geo", 11, 2}, Part{"washer.geo", 4, 1}, Part{"link.geo", 12, 3},
                        Part{"grate.geo", 30, 6}}) {
    CAPTURE(p.file);
    const auto part = cad::quad_surface_of_part(examples / p.file, std::nullopt);
    CHECK(part.faces == p.faces);
    CHECK(part.surface.quads.size() % 2 == 0);
    QuadSurface s = part.surface;
    const SurfaceSummary summary = validate_surface(s, p.file);
    CHECK(summary.genus == p.genus);
    CHECK(!summary.flipped);
  }
}

TEST_CASE("cad part: where one size leaves slivers, the surface is meshed again finer round them only") {
  // At one size the notch's corner, 1 mm from the boss, leaves quads whose
  // least corner sine is 0.0004 in 684 (docs/results.md).
  const auto bracket = cad::quad_surface_of_part(examples / "bracket.geo", std::nullopt);
  CHECK(bracket.meshings >= 2);
  CHECK(bracket.refinement_balls > 0);
  CHECK(surface_angle_bound(bracket.surface).least_sine >= cad::kLeastCornerSine);
  CHECK(bracket.surface.quads.size() < 1000);
  const std::array<double, 6> outline{0, 0, 0, 60, 40, 28};
  const auto box = bounding_box(bracket.surface);
  for (int i = 0; i < 6; ++i) CHECK(box[i] == doctest::Approx(outline[i]).epsilon(1e-9));
  // The tee's one size is good enough: meshed once.
  const auto tee = cad::quad_surface_of_part(examples / "tee.geo", std::nullopt);
  CHECK(tee.meshings == 1);
  CHECK(tee.refinement_balls == 0);
  CHECK(surface_angle_bound(tee.surface).least_sine >= cad::kLeastCornerSine);
}

TEST_CASE("cad part: what is not one readable solid is refused with one line") {
  ScratchDir dir("cad-refused");
  auto refused = [&](const std::string& name, const std::string& text, std::optional<double> size = std::nullopt) {
    spit(dir / name, text);
    std::string message;
    try {
      cad::quad_surface_of_part(dir / name, size);
    } catch (const InputError& e) {
      message = e.what();
    }
    CHECK(message.find('\n') == std::string::npos);
    return message;
  };
  const std::string occ = "SetFactory(\"OpenCASCADE\");\n";
  CHECK(refused("part.txt", "solid").find("not a CAD file") != std::string::npos);
  CHECK(refused("two.geo", occ + "Box(1) = {0,0,0,1,1,1};\nBox(2) = {3,0,0,1,1,1};\n").find("2 solids, not one") !=
        std::string::npos);
  CHECK(refused("sheet.geo", occ + "Rectangle(1) = {0,0,0,1,1};\n").find("0 solids") != std::string::npos);
  CHECK(refused("broken.geo", occ + "Box(1) = {0,0,0,1,1;\n").find("broken.geo") != std::string::npos);
  CHECK(refused("fine.geo", occ + "Box(1) = {0,0,0,1,1,1};\n", 1e-6).find("choose a larger --size") !=
        std::string::npos);
  CHECK(refused("zero.geo", occ + "Box(1) = {0,0,0,1,1,1};\n", 0.0).find("not a positive length") != std::string::npos);
}

TEST_CASE("loom mesh: a part to a hex mesh in one command, its surface kept on request") {
  ScratchDir dir("cad-mesh");
  spit(dir / "box.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0,2,1,1};\n");
  const auto r = run_cli(fmt::format("mesh {} --size 1 -o {} --surface {} --report {}", (dir / "box.geo").string(),
                                     (dir / "box.vtu").string(), (dir / "box.obj").string(), (dir / "box.json").string()));
  CHECK(r.status == 0);
  CHECK(r.out.find("woven:") == 0);
  CHECK(r.err.find("6 faces meshed by Gmsh into") != std::string::npos);
  CHECK(r.err.find("least corner sine 1)") != std::string::npos);
  REQUIRE(std::filesystem::exists(dir / "box.vtu"));
  const QuadSurface surface = read_surface(dir / "box.obj");
  CHECK(surface.quads.size() % 2 == 0);
  const auto report = nlohmann::json::parse(slurp(dir / "box.json"));
  CHECK(report["input"] == (dir / "box.geo").string());
  CHECK(report["valid"] == true);
  CHECK(report["made_by"] == "woven");

  // Bad input: one line, status 2, nothing written.
  spit(dir / "notes.txt", "a box");
  const auto bad = run_cli(fmt::format("mesh {} -o {}", (dir / "notes.txt").string(), (dir / "bad.vtu").string()));
  CHECK(bad.status == 2);
  CHECK(loom::test::count_lines(bad.err) == 1);
  CHECK(bad.err.find("not a CAD file") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "bad.vtu"));
  CHECK(run_cli(fmt::format("mesh {} --size 0 -o {}", (dir / "box.geo").string(), (dir / "bad.vtu").string())).status ==
        2);
  CHECK(!std::filesystem::exists(dir / "bad.vtu"));
  const auto bad_surface = run_cli(fmt::format("mesh {} --surface {} -o {}", (dir / "box.geo").string(),
                                               (dir / "box.stl").string(), (dir / "bad.vtu").string()));
  CHECK(bad_surface.status == 2);
  CHECK(bad_surface.err.find("box.stl") != std::string::npos);
  CHECK(bad_surface.err.find("faces meshed by Gmsh") == std::string::npos);  // refused before meshing
}
