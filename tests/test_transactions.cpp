// Every application is a transaction: a rewrite that throws, leaves a
// required slot empty or breaks a checked invariant is rolled back, and the
// error names the rule that did it, never a rule that ran later.
#include <doctest/doctest.h>

#include <filesystem>
#include <stdexcept>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::run_cli;
using loom::test::run_cli_unchecked;
using loom::test::ScratchDir;

namespace {
const engine::Schema& schema() { return *stc::StcSchema::get().schema; }

/// What a rollback must restore: every element, slot and attribute.
std::string fingerprint(const stc::Stc& stc) {
  const engine::Graph& g = stc.graph();
  std::string out = std::to_string(g.size()) + "/" + std::to_string(g.id_bound()) + ":";
  for (engine::Id e = 0; e < g.id_bound(); ++e) {
    if (!g.alive(e)) continue;
    const auto& kind = schema().kind(g.kind(e));
    for (engine::PortId p : kind.ports)
      for (unsigned i = 0; i < schema().port(p).arity; ++i) out += std::to_string(g.at(e, p, i)) + ",";
    for (engine::AttrId a : kind.attributes) out += std::to_string(g.get(e, a)) + ";";
  }
  return out;
}
}  // namespace

TEST_CASE("an action that throws halfway leaves the graph as it was, and the error names the call") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  engine::Actions actions;
  actions.add("half", {{"v", stc.ids().node}}, [&](engine::Graph& g, std::span<const engine::Id> args) {
    g.set(args[0], stc.ids().node_boundary, 5);
    g.add(stc.ids().node);
    throw std::runtime_error("out of ideas");
  });
  auto rules = engine::compile_rules("rule r { match { v: node where boundary == 1 }\nrewrite { v.boundary = 2\n call half(v) } }",
                                     "r.rule", schema());
  const std::string before = fingerprint(stc);
  engine::Engine eng(stc.graph(), rules, actions, {});
  CHECK_THROWS_WITH_AS(eng.step(), "r.rule:3:2: rule 'r' failed here: out of ideas", engine::RuleError);
  CHECK(fingerprint(stc) == before);
  CHECK(stc.check_invariants().empty());
  CHECK(eng.counters().steps == 0);
}

TEST_CASE("a rewrite that deletes an element still in use is rolled back, whatever the invariant checks") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  auto rules = engine::compile_rules("rule del { match { v: node where boundary == 1 } rewrite { delete v } }",
                                     "del.rule", schema());
  const std::string before = fingerprint(stc);
  engine::Engine eng(stc.graph(), rules, weave::weave_actions(stc), {});
  try {
    eng.step();
    FAIL("expected a RuleError");
  } catch (const engine::RuleError& e) {
    const std::string what = e.what();
    CHECK(what.rfind("del.rule:1:6: rule 'del' left face ", 0) == 0);
    CHECK(what.find("'s node[") != std::string::npos);
    CHECK(what.find("the rewrite was rolled back") != std::string::npos);
  }
  CHECK(fingerprint(stc) == before);

  ScratchDir dir("delete");
  for (auto& f : std::filesystem::directory_iterator(weave::default_rules_dir()))
    if (f.path().extension() == ".rule") std::filesystem::copy_file(f.path(), dir / f.path().filename().string());
  test::spit(dir / "del.rule", "rule del {\n  priority 100\n  match { v: node where boundary == 1 }\n  rewrite { delete v }\n}\n");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  auto r = run_cli_unchecked("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
                             dir.path().string());
  CHECK(r.status == 2);  // it was a segmentation fault
  CHECK(test::count_lines(r.err) == 1);
  CHECK_MESSAGE(r.err.find("del.rule:1:6: rule 'del' left face ") != std::string::npos, r.err);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
}

TEST_CASE("--check-rules names the rule that broke an STC invariant, not a rule that tripped over it later") {
  ScratchDir dir("forgets");
  for (auto& f : std::filesystem::directory_iterator(weave::default_rules_dir()))
    if (f.path().extension() == ".rule") std::filesystem::copy_file(f.path(), dir / f.path().filename().string());
  std::string cross = test::slurp(dir / "cross.rule");
  const std::string forgotten = "    f1.cell[0] = h\n";
  REQUIRE(cross.find(forgotten) != std::string::npos);
  cross.erase(cross.find(forgotten), forgotten.size());
  test::spit(dir / "cross.rule", cross);
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  const std::string weave = "weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
                            dir.path().string();

  auto r = run_cli_unchecked(weave + " --check-rules cross");
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK_MESSAGE(r.err.find("cross.rule:11:6: rule 'cross' broke an invariant: ") != std::string::npos, r.err);
  CHECK(r.err.find("rolled back") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));

  r = run_cli_unchecked(weave + " --check-rules all");
  CHECK(r.status == 2);
  CHECK(r.err.find("rule 'cross' broke an invariant") != std::string::npos);

  r = run_cli_unchecked(weave + " --check-rules cross,nosuch");
  CHECK(r.status == 2);
  CHECK(r.err == "loom: error: --check-rules: no rule 'nosuch' is loaded; see 'loom rules list'\n");
}

TEST_CASE("check_after refuses a rule that is not loaded") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  engine::Engine eng(stc.graph(), engine::load_rule_dir(weave::default_rules_dir(), schema()),
                     weave::weave_actions(stc), {});
  CHECK_THROWS_WITH_AS(eng.check_after([](const engine::Graph&) { return std::string(); }, {"cross", "nosuch"}),
                       "no rule 'nosuch' is loaded to check", std::invalid_argument);
}
