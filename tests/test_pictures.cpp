// Pictures never take a run down: Graphviz runs in a child process, a layout
// that crashes it is retried with straight edges, and what still cannot be
// drawn is left out with one warning. The trace is written step by step.
#include <doctest/doctest.h>

#include <filesystem>
#include <utility>

#include <fmt/format.h>
#include <stdexcept>

#include "engine/dot.hpp"
#include "engine/rule_compiler.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/pictures.hpp"
#include "src/stc/build.hpp"
#include "src/weave/step_dump.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::run_cli;
using loom::test::ScratchDir;

TEST_CASE("a sheet diagram that crashes Graphviz 2.43's spline router is drawn with straight edges") {
  // A step picture of `loom weave --dot-steps` on randquad 16 --seed 4: `dot -Tsvg` on it
  // dies of a segmentation fault, and so did loom, in-process.
  const std::string dot = test::slurp(test::data("graphviz-2.43-crash.dot"));
  REQUIRE(dot.find("splines=true") != std::string::npos);
  const std::string svg = engine::render_svg(dot);
  CHECK(svg.find("<svg") != std::string::npos);
  CHECK(svg.find("</svg>") != std::string::npos);
}

TEST_CASE("what Graphviz cannot draw is counted, not written, and named once") {
  CHECK_THROWS_AS(engine::render_svg("graph { a -- }"), std::runtime_error);
  CHECK_THROWS_WITH_AS(engine::render_svg("graph { a -- b }", "nosuchlayout"), "Graphviz layout 'nosuchlayout' failed",
                       std::runtime_error);
  ScratchDir dir("pictures");
  stc::PictureFailures failures;
  stc::write_svg(dir / "bad.svg", "graph { a -- }", failures);
  stc::write_svg(dir / "good.svg", "graph { a -- b }", failures);
  CHECK(failures.count == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "bad.svg"));
  CHECK(std::filesystem::exists(dir / "good.svg"));
  CHECK(failures.warning().rfind("loom: warning: 1 picture could not be drawn and is left out (first: ", 0) == 0);
  CHECK(failures.warning().find("bad.svg: Graphviz could not parse the DOT text") != std::string::npos);
}

TEST_CASE("--no-svg writes the DOT files only; the trace holds every step before a rule failed") {
  ScratchDir dir("nosvg");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  auto r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --dot " +
                   (dir / "dot").string() + " --dot-steps --no-svg -q");
  REQUIRE(r.status == 0);
  std::size_t dots = 0, svgs = 0;
  for (const auto& f : std::filesystem::recursive_directory_iterator(dir / "dot")) {
    dots += f.path().extension() == ".dot";
    svgs += f.path().extension() == ".svg";
  }
  CHECK(dots > 20);
  CHECK(svgs == 0);

  // A rule that breaks the STC once the box is woven: the 20 steps before it are in the trace.
  std::filesystem::create_directories(dir / "rules");
  for (auto& f : std::filesystem::directory_iterator(weave::default_rules_dir()))
    if (f.path().extension() == ".rule") std::filesystem::copy_file(f.path(), dir / "rules" / f.path().filename());
  test::spit(dir / "rules" / "del.rule",
             "rule del {\n  priority -100\n  match { v: node where boundary == 1 }\n  rewrite { delete v }\n}\n");
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out2.vtk").string() + " --rules " +
              (dir / "rules").string() + " --trace " + (dir / "trace.txt").string() + " --attempts 1");
  CHECK(r.status == 2);
  CHECK(r.err.find("rule 'del' left ") != std::string::npos);
  const std::string trace = test::slurp(dir / "trace.txt");
  CHECK(trace.rfind("# attempt 1: strategy ", 0) == 0);
  CHECK(test::trace_applications(trace, false).size() == 20);
  CHECK_FALSE(std::filesystem::exists(dir / "out2.vtk"));
}

TEST_CASE("--dot draws the mesh written, closure's and the layer's hexes included; with no mesh, the weave's state") {
  ScratchDir dir("dotmesh");
  auto hexes_drawn = [&](const std::filesystem::path& dot) {
    const std::string text = test::slurp(dot);
    std::size_t n = 0;
    for (std::size_t at = text.find("[label=\"hex "); at != std::string::npos; at = text.find("[label=\"hex ", at + 1)) ++n;
    return n;
  };
  // The spindle: 44 hexes from the database and an 8-hex layer, none woven.
  REQUIRE(run_cli("gen spindle -o " + (dir / "s.obj").string()).status == 0);
  auto r = run_cli("weave " + (dir / "s.obj").string() + " -o " + (dir / "s.vtk").string() +
                   " --prefer fewest-hexes --no-svg --dot " + (dir / "dot").string() + " --partial");
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("closed: 52 hexes = 0 woven", 0) == 0);
  CHECK(hexes_drawn(dir / "dot" / "stc.dot") == 52);
  // --partial still draws the weave's own state, which is not the mesh.
  CHECK(hexes_drawn(dir / "s.partial" / "stc.dot") != 52);

  // Woven, then a boundary layer: 16 woven + 40 pillow hexes drawn.
  REQUIRE(run_cli("gen cylinder 2 2 -o " + (dir / "c.obj").string()).status == 0);
  r = run_cli("weave " + (dir / "c.obj").string() + " -o " + (dir / "c.vtk").string() + " --no-svg --dot " +
              (dir / "layer").string());
  REQUIRE(r.status == 0);
  CHECK(r.out.find("(+40 hexes)") != std::string::npos);
  CHECK(hexes_drawn(dir / "layer" / "stc.dot") == 56);

  r = run_cli("weave " + (dir / "s.obj").string() + " -o " + (dir / "t.vtk").string() +
              " --closure none --no-svg --dot " + (dir / "open").string());
  CHECK(r.status == 1);
  CHECK(std::filesystem::exists(dir / "open" / "stc.dot"));
  CHECK(hexes_drawn(dir / "open" / "stc.dot") < 52);
}

TEST_CASE("step pictures: DOT files as the weave goes, SVGs only when rendered, none of an attempt cleared") {
  // Drawing is what made `--dot-steps` slow (randquad 20 seed 2: 16 attempts,
  // over 40 minutes): only the attempt kept is drawn, once the weave is over.
  ScratchDir dir("step-svgs");
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  weave::StepDumper dumper(dir / "steps", true);
  auto count = [&](const char* extension) {
    std::size_t n = 0;
    for (const auto& f : std::filesystem::directory_iterator(dir / "steps")) n += f.path().extension() == extension;
    return n;
  };
  weave::WeaveOptions options;
  std::size_t steps = 0;
  options.after_step = [&](const engine::Application& a, const stc::Stc& s) {
    dumper.dump(a, s);
    ++steps;
  };
  stc::Stc first = stc::build_from_surface(gen::box(1, 1, 2));
  weave::weave(first, rules, options);
  REQUIRE(steps > 0);
  CHECK(count(".dot") >= steps);
  CHECK(count(".svg") == 0);
  dumper.clear();
  CHECK(count(".dot") == 0);
  CHECK(dumper.render() == 0);

  stc::Stc second = stc::build_from_surface(gen::box(1, 1, 1));
  steps = 0;
  weave::weave(second, rules, options);
  REQUIRE(steps > 0);
  const std::size_t dots = count(".dot");
  CHECK(dumper.render() == dots);
  CHECK(count(".svg") == dots);
  CHECK(dumper.render() == 0);
}

// The run itself is the point of this case, so it cannot shrink; under
// ASan+UBSan (-DLOOM_SANITIZE=ON) its 16 attempts would take most of ctest's
// 300 s, and it is skipped there (the cases above draw pictures sanitized).
#ifdef LOOM_SANITIZED
constexpr bool kSkipLongRun = true;
#else
constexpr bool kSkipLongRun = false;
#endif

// The two runs of issue 14: they died in Graphviz (exit 134 and 139), then
// took 7 and over 40 minutes drawing every attempt's pictures; now they draw
// the attempt kept (48 and 120 s alone, nearly all of it Graphviz's layouts).
// Each is a ctest entry of its own (tests/CMakeLists.txt), so that the two
// run side by side and neither nears the 300 s limit on a loaded machine.
void check_step_pictures(int faces, int seed) {
  {
    ScratchDir dir("randquad-steps");
    REQUIRE(run_cli(fmt::format("gen randquad {} --seed {} -o {}", faces, seed, (dir / "q.obj").string())).status == 0);
    auto r = run_cli("weave " + (dir / "q.obj").string() + " -o " + (dir / "q.vtk").string() + " --dot " +
                     (dir / "dot").string() + " --dot-steps --trace " + (dir / "t.txt").string());
    CHECK((r.status == 0 || r.status == 3));
    std::size_t step_dots = 0, step_svgs = 0;
    for (const auto& f : std::filesystem::directory_iterator(dir / "dot" / "steps")) {
      const std::string name = f.path().filename().string();
      if (name.find("sheet") != std::string::npos) continue;
      step_dots += f.path().extension() == ".dot";
      step_svgs += f.path().extension() == ".svg";
    }
    // One picture per application of the last attempt, undone ones included.
    CHECK(step_dots == test::trace_applications(test::slurp(dir / "t.txt"), false).size());
    CHECK(step_dots > 100);
    // A step picture Graphviz cannot draw is named in the one warning line.
    if (step_svgs < step_dots) CHECK(r.err.find("could not be drawn") != std::string::npos);
    CHECK(step_svgs > step_dots / 2);
  }
}

TEST_CASE("loom weave --dot-steps on randquad 16 seed 4 completes, with a picture of every step or a warning" *
          doctest::skip(kSkipLongRun)) {
  check_step_pictures(16, 4);
}

TEST_CASE("loom weave --dot-steps on randquad 20 seed 2 completes, with a picture of every step or a warning" *
          doctest::skip(kSkipLongRun)) {
  check_step_pictures(20, 2);
}
