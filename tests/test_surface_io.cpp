// Surface files: every format round-trips exactly and deterministically, writes
// are atomic, and bad files give one InputError line (tests/data/bad/expected.tsv).
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "src/io/formats.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"
#include "tests/support.hpp"

using namespace loom;
namespace fs = std::filesystem;

using loom::test::slurp;
using loom::test::spit;
using loom::test::unit_cube;

namespace {

// The cube's combinatorics with coordinates that a %.16g writer would not
// round-trip, plus extremes and random doubles over many magnitudes.
QuadSurface awkward_cube() {
  QuadSurface s = unit_cube();
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (auto& p : s.points)
    for (double& x : p) x = std::ldexp(mantissa(rng), exponent(rng));
  s.points[0] = {0.1 + 0.2, 1.0 / 3.0, -0.0};
  s.points[1] = {std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                 -std::numeric_limits<double>::min()};
  s.points[2] = {2.0 / 3.0, 1e23, 123456789.123456789};
  return s;
}

void check_same(const QuadSurface& a, const QuadSurface& b) {
  REQUIRE(a.points.size() == b.points.size());
  REQUIRE(a.quads.size() == b.quads.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      CAPTURE(i);
      CAPTURE(k);
      CHECK(std::signbit(a.points[i][k]) == std::signbit(b.points[i][k]));
      CHECK(a.points[i][k] == b.points[i][k]);
    }
  CHECK(a.quads == b.quads);
}

// What `loom stc FILE` does with a surface: read it, then validate it.
std::string error_of(const fs::path& file) {
  try {
    QuadSurface surface = read_surface(file);
    validate_surface(surface, file.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::vector<std::string> surface_extensions = {".obj", ".off", ".vtk", ".vtu", ".msh"};

}  // namespace

TEST_CASE("every surface format round-trips points and quads exactly") {
  test::ScratchDir dir("surface-io");
  for (const auto& surface : {unit_cube(), awkward_cube()}) {
    for (const auto& ext : surface_extensions) {
      CAPTURE(ext);
      fs::path file = dir / ("s" + ext);
      write_surface(file, surface);
      check_same(read_surface(file), surface);
    }
  }
}

TEST_CASE("extensions are matched case-insensitively") {
  test::ScratchDir dir("surface-io-case");
  for (std::string ext : {".OBJ", ".Off", ".VTK", ".VTU", ".MSH"}) {
    CAPTURE(ext);
    write_surface(dir / ("s" + ext), unit_cube());
    check_same(read_surface(dir / ("s" + ext)), unit_cube());
  }
}

TEST_CASE("surface writes are deterministic and atomic") {
  test::ScratchDir dir("surface-io-det");
  for (const auto& ext : surface_extensions) {
    CAPTURE(ext);
    write_surface(dir / ("a" + ext), awkward_cube());
    write_surface(dir / ("b" + ext), awkward_cube());
    CHECK(slurp(dir / ("a" + ext)) == slurp(dir / ("b" + ext)));
  }
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    ++files;
    CHECK(entry.path().filename().string().find("loom-tmp") == std::string::npos);
  }
  CHECK(files == 2 * surface_extensions.size());
}

TEST_CASE("writing to an unknown extension or a missing directory fails cleanly") {
  test::ScratchDir dir("surface-io-badout");
  CHECK_THROWS_AS(write_surface(dir / "s.stl", unit_cube()), InputError);
  CHECK_THROWS_AS(write_surface(dir / "no-such-dir" / "s.obj", unit_cube()), InputError);
  CHECK(fs::is_empty(dir.path()));
}

TEST_CASE("good surfaces in tests/data/good read with the expected sizes") {
  struct Expected {
    std::string file;
    std::size_t points, quads;
  };
  for (const Expected& e : std::vector<Expected>{{"cube.obj", 8, 6},
                                                 {"cube.off", 8, 6},
                                                 {"cube.vtk", 8, 6},
                                                 {"cube-binary.vtk", 8, 6},
                                                 {"cube-polydata.vtk", 8, 6},
                                                 {"cube.vtu", 8, 6},
                                                 {"cube-msh22.msh", 8, 6},
                                                 {"cube-msh41.msh", 8, 6},
                                                 {"cube-msh22-binary.msh", 8, 6},
                                                 {"cube-msh41-binary.msh", 8, 6},
                                                 {"schneiders-pyramid.obj", 18, 16},
                                                 {"tet-split.obj", 14, 12}}) {
    CAPTURE(e.file);
    QuadSurface s = read_surface(test::data("good/" + e.file));
    CHECK(s.points.size() == e.points);
    CHECK(s.quads.size() == e.quads);
  }
}

TEST_CASE("all cube files describe the same cube") {
  const QuadSurface reference = read_surface(test::data("good/cube.obj"));
  for (std::string file : {"cube.off", "cube.vtk", "cube-binary.vtk", "cube-polydata.vtk", "cube.vtu", "cube-msh22.msh",
                           "cube-msh41.msh", "cube-msh22-binary.msh", "cube-msh41-binary.msh"}) {
    CAPTURE(file);
    check_same(read_surface(test::data("good/" + file)), reference);
  }
}

TEST_CASE("Gmsh reads the MSH files we write as we do") {
  test::ScratchDir dir("surface-io-gmsh");
  write_surface(dir / "s.msh", awkward_cube());
  RawMesh gmsh_view = read_msh_with_gmsh(dir / "s.msh");
  check_same(to_quad_surface(std::move(gmsh_view), "s.msh"), awkward_cube());
}

TEST_CASE("a Gmsh crash on a malformed file becomes an InputError") {
  // Gmsh 4.8.4 dereferences the missing node -1 and dies (a later Gmsh may
  // report an error instead); our ASCII parser rejects it with a line number.
  test::ScratchDir dir("surface-io-crash");
  spit(dir / "bad.msh",
       "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
       "0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 -1\n$EndElements\n");
  std::string gmsh_message, our_message;
  try {
    read_msh_with_gmsh(dir / "bad.msh");
  } catch (const InputError& e) {
    gmsh_message = e.what();
  }
  CHECK(gmsh_message.starts_with((dir / "bad.msh").string() + ": Gmsh"));
  our_message = error_of(dir / "bad.msh");
  CHECK(our_message.find("line 19: element 1 refers to node -1, which $Nodes does not define") != std::string::npos);
}

TEST_CASE("every file in tests/data/bad is rejected with its expected message") {
  std::ifstream manifest(test::data("bad/expected.tsv"));
  REQUIRE(manifest);
  std::string line;
  int cases = 0;
  while (std::getline(manifest, line)) {
    if (line.empty() || line.front() == '#') continue;
    auto tab = line.find('\t');
    REQUIRE(tab != std::string::npos);
    std::string file = line.substr(0, tab), expected = line.substr(tab + 1);
    CAPTURE(file);
    fs::path path = test::data("bad/" + file);
    REQUIRE(fs::exists(path));
    std::string message = error_of(path);
    CAPTURE(message);
    CHECK(message.find(expected) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.starts_with(path.string() + ": "));
    ++cases;
  }
  CHECK(cases >= 20);
}

TEST_CASE("truncating a good file anywhere gives InputError or a smaller surface, never a crash") {
  test::ScratchDir dir("surface-io-trunc");
  for (const auto& ext : surface_extensions) {
    fs::path whole = dir / ("whole" + ext);
    write_surface(whole, unit_cube());
    const std::string text = slurp(whole);
    for (std::size_t cut = 0; cut < text.size(); cut += 7) {
      CAPTURE(ext);
      CAPTURE(cut);
      fs::path part = dir / ("part" + ext);
      spit(part, text.substr(0, cut));
      try {
        QuadSurface s = read_surface(part);
        // A cut at a line end of a line-based format can leave a shorter valid file.
        CHECK(s.quads.size() <= 6);
      } catch (const InputError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
      }
    }
  }
}

TEST_CASE("random bytes and mutated files give InputError, never a crash") {
  test::ScratchDir dir("surface-io-fuzz");
  std::mt19937_64 rng(7);
  for (const auto& ext : surface_extensions) {
    fs::path whole = dir / ("whole" + ext);
    write_surface(whole, unit_cube());
    const std::string text = slurp(whole);
    for (int round = 0; round < 60; ++round) {
      CAPTURE(ext);
      CAPTURE(round);
      std::string bytes = text;
      if (round < 10) {
        bytes.assign(1 + rng() % 300, '\0');
        for (char& c : bytes) c = static_cast<char>(rng());
      } else {
        for (int k = 0; k < 1 + round % 5; ++k) bytes[rng() % bytes.size()] = "0123456789-.e $\n x#"[rng() % 19];
      }
      fs::path file = dir / ("fuzz" + ext);
      spit(file, bytes);
      try {
        read_surface(file);
      } catch (const InputError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
      }
    }
  }
}
