// Budgets a user sets on loom weave (--max-seconds, --max-memory) stop the run
// cleanly, status 1 and one line, nothing written; --progress reports stages
// when stderr is not a terminal.
#include <doctest/doctest.h>

#include <filesystem>

#include "tests/support.hpp"

using loom::test::run_cli;
using loom::test::ScratchDir;

using loom::test::run_cli_unchecked;

TEST_CASE("--max-seconds stops a long weave with one line naming its stage, and writes nothing") {
  ScratchDir dir("budget");
  REQUIRE(run_cli("gen box 30 30 30 -o " + (dir / "box.obj").string()).status == 0);
  // 27,000 hexes: over a second of weaving, with the invariant checks far more.
  auto r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --report " +
                   (dir / "r.json").string() + " --max-seconds 0.3");
  CHECK(r.status == 1);
  CHECK(loom::test::count_lines(r.err) == 1);
  CHECK_MESSAGE(r.err.rfind("loom: stopped at the --max-seconds budget (0.3 s) while weaving (", 0) == 0, r.err);
  CHECK(r.err.find("nothing written") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
  CHECK_FALSE(std::filesystem::exists(dir / "r.json"));
  for (const auto& f : std::filesystem::directory_iterator(dir.path()))  // no temporary left either
    CHECK(f.path().filename() == "box.obj");
}

// AddressSanitizer reserves its shadow memory in the data segment that
// --max-memory caps, so a sanitized loom cannot start under a small cap.
#ifndef LOOM_SANITIZED
TEST_CASE("--max-memory stops a weave that needs more, with one line and status 1") {
  ScratchDir dir("memory");
  REQUIRE(run_cli("gen box 30 30 30 -o " + (dir / "box.obj").string()).status == 0);
  // The weave of this box peaks near 100 MB.
  auto r = run_cli_unchecked("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() +
                             " --max-memory 60");
  CHECK(r.status == 1);
  CHECK(loom::test::count_lines(r.err) == 1);
  CHECK_MESSAGE(r.err.rfind("loom: out of memory: ", 0) == 0, r.err);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
}

TEST_CASE("--max-memory: the wide search gives way, and the mesh found before it is written") {
  // Quadrangulation 14 54: 79 hexes before the wide search, which needs 3.6 GB
  // to find 67; under a 1,500 MB cap it runs out, and the 79 stay.
  ScratchDir dir("memory-wide");
  REQUIRE(run_cli("gen quadrangulation 14 54 -o " + (dir / "q.obj").string()).status == 0);
  auto r = run_cli_unchecked("weave " + (dir / "q.obj").string() + " -o " + (dir / "out.vtk").string() +
                             " --max-memory 1500");
  CHECK_MESSAGE((r.status == 0 || r.status == 3), r.err);
  CHECK(r.out.find("searched: ") == 0);
  CHECK(r.err.find("loom: out of memory") == std::string::npos);
  CHECK_MESSAGE(r.err.find("loom: note: the last searches for a mesh within 72 hexes stopped: out of memory;") !=
                    std::string::npos,
                r.err);
  CHECK(std::filesystem::exists(dir / "out.vtk"));
}
#endif

TEST_CASE("--progress writes a line as each stage starts, also into a file; bad budgets are refused") {
  ScratchDir dir("progress");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  const std::string weave = "weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string();
  auto r = run_cli(weave + " --progress");
  CHECK(r.status == 0);
  CHECK_MESSAGE(r.err.find(" s: weaving (") != std::string::npos, r.err);
  CHECK(r.err.find(" s: placing nodes\n") != std::string::npos);
  // Budgets too large to mean anything are no budget, not an overflow.
  r = run_cli(weave + " --max-seconds 1e300 --max-memory 18446744073709551615");
  CHECK_MESSAGE(r.status == 0, r.err);
  for (const char* bad : {" --max-seconds 0", " --max-seconds -1", " --max-memory 0", " --max-seconds soon"}) {
    r = run_cli(weave + bad);
    CHECK_MESSAGE(r.status == 2, bad);
    CHECK(loom::test::count_lines(r.err) == 1);
  }
}
