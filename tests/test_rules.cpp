// Rule files: parse and compile errors name file:line:column; the anchored
// matcher finds exactly what Boost's VF2 finds; a new rule file is applied
// without recompiling.
#include <doctest/doctest.h>

#include <map>

#include <fstream>
#include <sstream>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "engine/vf2_reference.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "tests/rule_errors.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::compile_error;
using loom::test::run_cli;
using loom::test::ScratchDir;

namespace {
const engine::Schema& schema() { return *stc::StcSchema::get().schema; }


void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}
}  // namespace

TEST_CASE("broken rule files fail at load time with file:line:column") {
  CHECK(compile_error("rule r {\n  match {\n    v: node\n    v.nosuchport == v\n  }\n}\n") ==
        "bad.rule:4:5: a node has no port 'nosuchport'");
  CHECK(compile_error("rule r { match { v: vertex } }") ==
        "bad.rule:1:18: expected a kind (hex, face, edge, node, chord, sheet), found 'vertex'");
  CHECK(compile_error("rule r { match { f: face\n f.node == f } }") ==
        "bad.rule:2:2: port 'node' has 4 slots: give an index, e.g. node[0] or node[_]");
  CHECK(compile_error("rule r { match { v: node } rewrite { v.point = } }") ==
        "bad.rule:1:48: expected a number, a name, 'none', 'max(...)', 'min(...)' or '(', found '}'");
  CHECK(compile_error("rule r { priority x }") == "bad.rule:1:19: expected a number, found 'x'");
  CHECK(compile_error("rule r { match { v: node } rewrite { call frobnicate(v) } }").empty());  // actions are checked by the engine
  CHECK(compile_error("rule r { match { v: node\n f: face\n f.node[2] == w } }") == "bad.rule:3:2: unknown variable 'w'");
  CHECK(compile_error("rule r { match { v: node $ } }") == "bad.rule:1:26: unexpected character '$'");
  CHECK(compile_error("") == "bad.rule:1:1: expected 'rule', found end of file");
  CHECK(compile_error("rule r { match { f: face } rewrite { f.chord = k\n new k: chord } }") ==
        "bad.rule:1:48: 'k' is used before its 'new'");
  CHECK(compile_error("rule r { match { f: face\n v: node } rewrite { f.cell[0] = v } }") ==
        "bad.rule:2:22: expected a hex, found a node");
  CHECK(compile_error("rule r { match { f: face } rewrite { f.layer = f } }") ==
        "bad.rule:1:38: attribute 'layer' takes a number, not an element");
  CHECK(compile_error("rule r { match { f: face\n e: edge\n f.node[0] == e } }") ==
        "bad.rule:3:2: port 'node' points at a node, but 'e' is an edge");
}

TEST_CASE("an unknown action is reported when the engine is built") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  auto rules = engine::compile_rules("rule r { match { v: node } rewrite { call frobnicate(v) } }", "x.rule", schema());
  CHECK_THROWS_WITH_AS(engine::Engine(stc.graph(), rules, weave::weave_actions(stc), {}),
                       "x.rule:1:38: expected a known action, found 'frobnicate'", engine::RuleError);
}

TEST_CASE("the anchored matcher and VF2 find the same matches for every shipped rule") {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), schema());
  REQUIRE(rules.size() >= 2);
  // Weave states of a small box: initial, and after some rule applications.
  for (std::size_t steps : {0u, 1u, 2u, 3u, 5u, 8u}) {
    stc::Stc stc = stc::build_from_surface(gen::box(2, 2, 1));
    engine::Engine eng(stc.graph(), rules, weave::weave_actions(stc), {});
    for (std::size_t s = 0; s < steps; ++s) REQUIRE(eng.step());
    engine::Matcher matcher(stc.graph());
    for (const auto& rule : rules) {
      CAPTURE(rule.name);
      CAPTURE(steps);
      std::set<std::vector<engine::Id>> anchored, reference;
      matcher.each(rule, [&](const engine::Match& m) {
        std::vector<engine::Id> main(m.elements.begin(), m.elements.begin() + rule.pattern_vars);
        if (std::set<engine::Id>(main.begin(), main.end()).size() == main.size()) anchored.insert(main);
        return true;
      });
      engine::vf2_matches(stc.graph(), rule, [&](const std::vector<engine::Id>& m) {
        reference.insert(m);
        return true;
      });
      CHECK(anchored == reference);
      if (rule.name == "cross" && steps == 0) CHECK(anchored.size() == 8 * 3);  // 8 corners, 3 rotations
    }
  }
}

namespace {

/// What the engine applies to the initial STC of `surface`, step by step (up
/// to `max_steps`), incrementally or with a full rescan after every step.
struct Run {
  std::vector<std::vector<engine::Id>> matched;
  std::vector<std::string> rules;
  std::size_t whiskers_left = 0;
};

Run run_engine(const QuadSurface& surface, const std::vector<engine::Rule>& rules, bool full_rescan,
               std::size_t max_steps) {
  stc::Stc stc = stc::build_from_surface(surface);
  engine::Engine eng(stc.graph(), rules, weave::weave_actions(stc), {});
  eng.set_full_rescan(full_rescan);
  engine::Application app;
  Run run;
  while (run.matched.size() < max_steps && eng.step(&app)) {
    run.matched.push_back(app.matched.elements);
    run.rules.push_back(app.rule->name);
  }
  run.whiskers_left = stc.whiskers();
  return run;
}

}  // namespace

TEST_CASE("incremental matching chooses exactly what a full rescan after every step chooses") {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), schema());
  for (const auto& surface : {gen::box(3, 3, 2), gen::lshape(2), gen::box(1, 4, 2)}) {
    const Run incremental = run_engine(surface, rules, false, 100000), full = run_engine(surface, rules, true, 100000);
    CHECK(incremental.whiskers_left == 0);
    CHECK(incremental.matched.size() > 10);
    CHECK(incremental.matched == full.matched);
  }
}

TEST_CASE("incremental matching agrees with a full rescan on weaves where every shipped rule applies") {
  // Degenerate weaves: negative patterns block and unblock seams, and the
  // low-priority rules (seam_through, pillows, wedge, pillow_face) fire.
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), schema());
  std::map<std::string, std::size_t> applied;
  for (const auto& surface : {gen::schneiders(), gen::randquad(20, 5), gen::randquad(14, 4), gen::randquad(18, 1),
                              gen::randquad(16, 1), gen::randquad(8, 0)}) {
    const Run incremental = run_engine(surface, rules, false, 600), full = run_engine(surface, rules, true, 600);
    CHECK(incremental.matched.size() > 10);
    CHECK(incremental.matched == full.matched);
    for (const auto& name : incremental.rules) ++applied[name];
  }
  for (const auto& r : rules) CHECK_MESSAGE(applied[r.name] > 0, r.name << " never applied: the case does not cover it");
}

TEST_CASE("a rule's test is asked of each match before its rewrite: a match that fails it is passed over, not counted") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  std::set<engine::Id> asked;
  engine::Actions actions;
  // Holds for the second node it is asked about only.
  actions.add_test("second", {{"v", stc.ids().node}}, [&](engine::Graph&, std::span<const engine::Id> args) {
    asked.insert(args[0]);
    return asked.size() == 2;
  });
  actions.add("mark", {{"v", stc.ids().node}},
              [&](engine::Graph& g, std::span<const engine::Id> args) { g.set(args[0], stc.ids().node_boundary, 7); });
  auto rules = engine::compile_rules(
      "rule r { match { v: node where boundary == 1\n test second(v) } rewrite { call mark(v) } }", "r.rule", schema());
  engine::Engine eng(stc.graph(), rules, actions);
  REQUIRE(eng.step());
  CHECK(asked.size() == 2);
  CHECK(eng.applications().at("r") == 1);
  while (eng.step()) {
  }
  CHECK(asked.size() == stc.graph().size(stc.ids().node));  // each asked once
  CHECK(eng.counters().steps == 1);
  std::size_t marked = 0;
  for (engine::Id n : stc.graph().members(stc.ids().node)) marked += stc.graph().get(n, stc.ids().node_boundary) == 7;
  CHECK(marked == 1);
}

TEST_CASE("tests are held to their signatures when rules load, and only the main pattern may ask one") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  auto message = [&](const std::string& text) -> std::string {
    try {
      engine::Engine(stc.graph(), engine::compile_rules(text, "t.rule", schema()), weave::weave_actions(stc));
    } catch (const engine::RuleError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(message("rule t { match { n: node\n test nosuch(n) } }") == "t.rule:2:2: expected a known test, found 'nosuch'");
  CHECK(message("rule t { match { n: node\n test pillow_improper(n) } }") ==
        "t.rule:2:2: expected a known test, found 'pillow_improper'");  // an action, not a test
  CHECK(message("rule t { match { n: node\n } rewrite { call pillow_improper_helps(n) } }") ==
        "t.rule:2:14: expected a known action, found 'pillow_improper_helps'");
  CHECK(message("rule t { match { n, m: node\n test pillow_improper_helps(n, m) } }") ==
        "t.rule:2:2: test 'pillow_improper_helps' takes 1 argument (node n), found 2");
  CHECK(message("rule t { match { h: hex\n test pillow_improper_helps(h) } }") ==
        "t.rule:2:2: argument 1 of test 'pillow_improper_helps' (n) must be a node, found 'h', a hex");
  CHECK_THROWS_WITH_AS(engine::compile_rules("rule t { match { n: node not { m: node\n test pillow_improper_helps(m) } } }",
                                             "t.rule", schema()),
                       "t.rule:2:2: test ...(...) is only allowed in the main pattern", engine::RuleError);
}

TEST_CASE("a call with the wrong number or kinds of arguments is refused when rules load") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  auto error = [&](const std::string& text) {
    auto rules = engine::compile_rules(text, "x.rule", schema());
    try {
      engine::Engine(stc.graph(), rules, weave::weave_actions(stc), {});
    } catch (const engine::RuleError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error("rule r { match { n: node\n v: node } rewrite { call place_hex_corner(n, v) } }") ==
        "x.rule:2:22: action 'place_hex_corner' takes 5 arguments (node n, node v, node a, node b, node c), found 2");
  CHECK(error("rule r { match { v: node } rewrite { call pillow_star() } }") ==
        "x.rule:1:38: action 'pillow_star' takes 1 argument (node n), found 0");
  CHECK(error("rule r { match { h: hex\n v: node } rewrite { call pillow_doublet(h, v) } }") ==
        "x.rule:2:22: argument 2 of action 'pillow_doublet' (h2) must be a hex, found 'v', a node");
  CHECK(error("rule r { match { v: node } rewrite { call pillow_star(v) } }").empty());
}

TEST_CASE("a new rule file in a temporary directory is applied without recompiling") {
  ScratchDir dir("rules");
  for (auto& f : std::filesystem::directory_iterator(weave::default_rules_dir()))
    if (f.path().extension() == ".rule") std::filesystem::copy_file(f.path(), dir / f.path().filename().string());
  // Marks every boundary node the moment its front valence is 3.
  write(dir / "mark.rule", R"(rule mark {
  priority 30
  match {
    v: node where boundary == 1
    count(face.node -> v where self.cell[0] == none) == 3
  }
  rewrite { v.boundary = 2 }
})");
  auto rules = engine::load_rule_dir(dir.path(), schema());
  auto r = pipeline::mesh_surface(gen::box(2, 2, 2), rules, {});
  CHECK(r.weave.closed);
  CHECK(r.weave.applications.at("mark") >= 8);  // at least the eight corners

  write(dir / "box.obj", "");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  auto cli = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
                     dir.path().string() + " --report " + (dir / "r.json").string());
  CHECK(cli.status == 0);
  std::ifstream report(dir / "r.json");
  auto j = nlohmann::json::parse(report);
  CHECK(j["rule_applications"]["mark"].get<int>() >= 8);
}

TEST_CASE("loom weave fails cleanly without the seam rule, and on a broken rule file") {
  ScratchDir dir("noseam");
  std::filesystem::copy_file(weave::default_rules_dir() / "cross.rule", dir / "cross.rule");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  auto r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --no-fill --rules " +
                   dir.path().string());
  CHECK(r.status == 1);
  CHECK(r.err.rfind("loom: weave did not close in 16 attempts: ", 0) == 0);
  CHECK(r.err.find("whiskers") != std::string::npos);
  CHECK(loom::test::count_lines(r.err) == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));

  write(dir / "broken.rule", "rule broken {\n  match {\n    v: node\n  }\n  rewrite { v.boundary = = 1 }\n}\n");
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
              dir.path().string());
  CHECK(r.status == 2);
  CHECK(loom::test::count_lines(r.err) == 1);
  CHECK(r.err.find("broken.rule:5:26: expected a number") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));

  r = run_cli("rules explain " + (dir / "broken.rule").string());
  CHECK(r.status == 2);
  std::filesystem::remove(dir / "broken.rule");

  // A copy of cross.rule that gives place_hex_corner two of its five
  // arguments: refused at load, before anything is woven.
  {
    std::string cross = loom::test::slurp(dir / "cross.rule");
    const std::string call = "call place_hex_corner(n, v, p12, p23, p31)";
    REQUIRE(cross.find(call) != std::string::npos);
    cross.replace(cross.find(call), call.size(), "call place_hex_corner(n, v)");
    write(dir / "cross.rule", cross);
    for (const std::string& cmd : {"rules list " + dir.path().string(), "rules explain " + (dir / "cross.rule").string(),
                                   "weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() +
                                       " --rules " + dir.path().string()}) {
      r = run_cli(cmd);
      CHECK_MESSAGE(r.status == 2, cmd);
      CHECK(loom::test::count_lines(r.err) == 1);
      CHECK_MESSAGE(r.err.find("cross.rule:75:") != std::string::npos, r.err);
      CHECK(r.err.find("action 'place_hex_corner' takes 5 arguments") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
    std::filesystem::copy_file(weave::default_rules_dir() / "cross.rule", dir / "cross.rule",
                               std::filesystem::copy_options::overwrite_existing);
  }

  write(dir / "action.rule", "rule act {\n  match { v: node }\n  rewrite { call frobnicate(v) }\n}\n");
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
              dir.path().string());
  CHECK(r.status == 2);
  CHECK(r.err.find("action.rule:3:13: expected a known action, found 'frobnicate'") != std::string::npos);
  std::filesystem::remove(dir / "action.rule");

  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
              dir.path().string() + " --strategy sequence:cross,nosuch");
  CHECK(r.status == 2);
  CHECK(r.err.find("no rule 'nosuch' is loaded") != std::string::npos);

  // An output format loom cannot write is refused before any work or any other file.
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.obj").string() + " --report " +
              (dir / "r.json").string());
  CHECK(r.status == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "r.json"));
  r = run_cli("rules explain " + (dir / "cross.rule").string());
  CHECK(r.status == 0);
  CHECK(r.out.find("anchored at v") != std::string::npos);
}

TEST_CASE("loom weave writes the mesh, trace, report and step pictures, the same on every run") {
  ScratchDir dir("weave");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  std::string base = "weave " + (dir / "box.obj").string() + " --strategy random --seed 5";
  auto a = run_cli(base + " -o " + (dir / "a.vtk").string() + " --trace " + (dir / "a.trace").string() + " --dot " +
                   (dir / "dot").string() + " --dot-steps --report " + (dir / "a.json").string());
  auto b = run_cli(base + " -o " + (dir / "b.vtk").string() + " --trace " + (dir / "b.trace").string());
  REQUIRE(a.status == 0);
  REQUIRE(b.status == 0);
  auto slurp = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(slurp(dir / "a.vtk") == slurp(dir / "b.vtk"));
  CHECK(slurp(dir / "a.trace") == slurp(dir / "b.trace"));
  auto j = nlohmann::json::parse(slurp(dir / "a.json"));
  CHECK(j["hexes"] == 8);
  CHECK(j["closed"] == true);
  CHECK(j["valid"] == true);
  int steps = j["steps"];
  CHECK(loom::test::trace_applications(slurp(dir / "a.trace"), false).size() == static_cast<std::size_t>(steps));
  int step_pictures = 0;
  for (auto& f : std::filesystem::directory_iterator(dir / "dot" / "steps"))
    step_pictures += f.path().extension() == ".svg" && f.path().filename().string().find("sheet") == std::string::npos;
  CHECK(step_pictures == steps);
  CHECK(run_cli("check " + (dir / "a.vtk").string() + " --boundary " + (dir / "box.obj").string()).status == 0);

  // The spindle never closes: the trace holds each attempt after a line naming
  // it, and each undo line takes back the latest application still kept.
  REQUIRE(run_cli("gen spindle -o " + (dir / "spindle.obj").string()).status == 0);
  auto s = run_cli("weave " + (dir / "spindle.obj").string() + " -o " + (dir / "s.vtk").string() +
                   " --closure none --attempts 3 --trace " + (dir / "s.trace").string());
  CHECK(s.status == 1);  // no mesh
  const std::string trace = slurp(dir / "s.trace");
  std::size_t headers = 0, undos = 0;
  std::istringstream lines(trace);
  for (std::string line; std::getline(lines, line);) {
    headers += line.rfind("# attempt ", 0) == 0;
    undos += line.rfind("undo ", 0) == 0;
  }
  CHECK(headers == 3);
  CHECK(trace.find("# attempt 2: strategy ") != std::string::npos);
  CHECK(trace.find("seed 2\n") != std::string::npos);
  CHECK(undos > 0);
  const auto all = loom::test::trace_applications(trace, false), kept = loom::test::trace_applications(trace, true);
  CHECK(kept.size() < all.size());
}
