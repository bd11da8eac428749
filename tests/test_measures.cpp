// Measures: integers the domain computes from a match's elements (here the
// weave's geometric ones, src/weave/measures.hpp), usable in any expression
// of a rule. Their values, how a guard on one changes what a rule applies,
// what re-queues a match that reads one, and the errors of misusing one.
#include <doctest/doctest.h>

#include <algorithm>

#include <fmt/format.h>

#include "engine/engine.hpp"
#include "engine/rule_parser.hpp"
#include "src/check/edge_valence.hpp"
#include "src/check/validity.hpp"
#include "src/stc/primal.hpp"
#include "engine/rule_compiler.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/weave/measures.hpp"
#include "src/weave/weave.hpp"
#include "tests/rule_errors.hpp"

using namespace loom;

namespace {
const engine::Schema& schema() { return *stc::StcSchema::get().schema; }

/// The node of `stc` at `at` (no_element if none).
engine::Id node_at(const stc::Stc& stc, const Vec3& at) {
  const engine::Graph& g = stc.graph();
  for (engine::Id e = 0; e < g.id_bound(); ++e)
    if (g.alive(e) && g.kind(e) == stc.ids().node && stc.position(e) && norm(*stc.position(e) - at) < 1e-12) return e;
  return engine::no_element;
}

/// The front face of `stc` whose corners' mean is `at` (no_element if none).
engine::Id face_at(const stc::Stc& stc, const Vec3& at) {
  const engine::Graph& g = stc.graph();
  for (engine::Id e = 0; e < g.id_bound(); ++e) {
    if (!g.alive(e) || g.kind(e) != stc.ids().face) continue;
    Vec3 c{0, 0, 0};
    for (unsigned i = 0; i < 4; ++i) c = c + 0.25 * *stc.position(stc.face_node(e, i));
    if (norm(c - at) < 1e-12) return e;
  }
  return engine::no_element;
}

std::int64_t measure(const engine::Actions& actions, const stc::Stc& stc, const std::string& name,
                     std::vector<engine::Id> args) {
  const auto* entry = actions.find_measure(name);
  REQUIRE(entry != nullptr);
  REQUIRE(std::find(args.begin(), args.end(), engine::no_element) == args.end());
  return entry->measure(stc.graph(), args);
}

/// Applications of `rule_text` on the unit box until none applies.
std::size_t applications(const std::string& rule_text, stc::Stc& stc) {
  engine::Engine eng(stc.graph(), engine::compile_rules(rule_text, "probe.rule", schema()), weave::weave_actions(stc));
  while (eng.step()) {
  }
  return eng.counters().steps;
}

// A node of each boundary quad, with the quad's nodes before and after it.
const std::string corner_match = R"(
    v: node where boundary == 1
    f: face where self.cell[0] == none
    a, b: node
    f.node[i] == v
    f.node[i+1] == a
    f.node[i+3] == b
)";
}  // namespace

TEST_CASE("the geometric measures on the unit box") {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  engine::Actions actions;
  weave::add_geometric_measures(actions, stc);
  const engine::Id o = node_at(stc, {0, 0, 0}), x = node_at(stc, {1, 0, 0}), y = node_at(stc, {0, 1, 0}),
                   z = node_at(stc, {0, 0, 1}), xy = node_at(stc, {1, 1, 0}), yz = node_at(stc, {0, 1, 1}),
                   zx = node_at(stc, {1, 0, 1});
  CHECK(measure(actions, stc, "corner_sj", {o, x, y, z}) == 1000);
  CHECK(measure(actions, stc, "corner_sj", {o, y, x, z}) == -1000);
  CHECK(measure(actions, stc, "corner_sj", {o, x, xy, z}) == 707);  // sin 45 degrees
  CHECK(measure(actions, stc, "hex_sj", {o, x, y, z, xy, yz, zx}) == 1000);
  CHECK(measure(actions, stc, "hex_sj", {o, x, y, z, yz, xy, zx}) < 0);  // face corners swapped: folded
  CHECK(measure(actions, stc, "angle", {x, o, y}) == 90);
  CHECK(measure(actions, stc, "angle", {x, o, xy}) == 45);
  CHECK(measure(actions, stc, "angle", {x, o, x}) == 0);
  CHECK(measure(actions, stc, "gap", {o, x, y}) == 1414);
  CHECK(measure(actions, stc, "gap", {o, x, x}) == 0);
  const engine::Id bottom = face_at(stc, {0.5, 0.5, 0}), top = face_at(stc, {0.5, 0.5, 1}), side = face_at(stc, {0.5, 0, 0.5});
  CHECK(measure(actions, stc, "facing", {bottom, top}) == 0);
  CHECK(measure(actions, stc, "facing", {bottom, side}) == 90);
  CHECK(measure(actions, stc, "facing", {bottom, bottom}) == 180);
  CHECK(measure(actions, stc, "distance", {bottom, top}) == 1000);
  CHECK(measure(actions, stc, "distance", {bottom, side}) == 707);
  // The box's front faces run counter-clockwise seen from outside: at edge
  // o-x the face o -> x -> zx (on y = 0) and the face x -> o -> y (on z = 0).
  CHECK(measure(actions, stc, "dihedral", {o, x, zx, y}) == 90);
  // A region whose faces at o-x are one plane (z = 0 and the face under it
  // folded flat) is 180; one that wraps around the edge is reflex.
  stc.place(zx, {1, -1, 0});
  CHECK(measure(actions, stc, "dihedral", {o, x, zx, y}) == 180);
  stc.place(zx, {1, 0, -1});
  CHECK(measure(actions, stc, "dihedral", {o, x, zx, y}) == 270);
}

TEST_CASE("a guard on a measure decides where a rule applies, and an order on one which match comes first") {
  auto mark = [](const std::string& comparison) {
    return "rule mark {\n match {" + corner_match + "    if angle(a, v, b) " + comparison + " 90\n  }\n  rewrite { v.boundary = 3 }\n}\n";
  };
  stc::Stc box = stc::build_from_surface(gen::box(1, 1, 1));
  CHECK(applications(mark("=="), box) == 8);
  stc::Stc box2 = stc::build_from_surface(gen::box(1, 1, 1));
  CHECK(applications(mark("!="), box2) == 0);

  // Pull one corner of a 2x1x1 box outwards: its quads' angles there shrink
  // (to 50 degrees), so a rule ordered by the angle marks that corner first.
  stc::Stc long_box = stc::build_from_surface(gen::box(2, 1, 1));
  const engine::Id far = node_at(long_box, {2, 1, 1});
  REQUIRE(far != engine::no_element);
  long_box.place(far, {2.5, 1.5, 1.5});
  auto rules = engine::compile_rules("rule first {\n match {" + corner_match + "  }\n  order angle(a, v, b)\n  rewrite { v.boundary = 3 }\n}\n",
                                     "first.rule", schema());
  engine::Engine eng(long_box.graph(), rules, weave::weave_actions(long_box));
  engine::Application applied;
  REQUIRE(eng.step(&applied));
  CHECK(applied.matched.elements[0] == far);
}

TEST_CASE("a match that reads a measure is re-tried when a position it reads moves") {
  // `spread` applies only where a quad's corner angle is wide; `pull` makes
  // one so by moving a node in its quad's plane (which opens the angle at the
  // next corner to 180 degrees). Nothing changes but a position, so only the
  // measure's sensitivity re-queues `spread`.
  const std::string rules_text = "rule pull {\n match {" + corner_match + "  }\n  rewrite { call place_hex_corner(v, a, v, v, b) }\n}\n"
                                 "rule spread {\n priority 1\n match {" + corner_match +
                                 "    if angle(a, v, b) > 100\n  }\n  rewrite { v.boundary = 4 }\n}\n";
  auto rules = engine::compile_rules(rules_text, "moves.rule", schema());
  const engine::Rule& spread = rules[0].name == "spread" ? rules[0] : rules[1];
  for (const char* name : {"a", "b", "v"}) {
    auto var = std::find_if(spread.vars.begin(), spread.vars.end(), [&](const engine::Variable& x) { return x.name == name; });
    REQUIRE(var != spread.vars.end());
    CHECK(std::find(var->attrs.begin(), var->attrs.end(), stc::StcSchema::get().node_point) != var->attrs.end());
  }

  stc::Stc box = stc::build_from_surface(gen::box(1, 1, 1));
  engine::Engine eng(box.graph(), rules, weave::weave_actions(box));
  engine::Application first;
  REQUIRE(eng.step(&first));
  CHECK(first.rule->name == "pull");
  engine::Application second;
  REQUIRE(eng.step(&second));
  CHECK(second.rule->name == "spread");
}

TEST_CASE("a rollback puts back the positions the rewrite moved") {
  stc::Stc box = stc::build_from_surface(gen::box(1, 1, 1));
  const std::string rule = "rule pull {\n match {" + corner_match + "  }\n  rewrite {\n v.boundary = 2\n call place_hex_corner(a, v, a, a, b)\n }\n}\n";
  engine::Engine eng(box.graph(), engine::compile_rules(rule, "pull.rule", schema()), weave::weave_actions(box));
  std::vector<Vec3> before;
  for (engine::Id e = 0; e < box.graph().id_bound(); ++e)
    if (box.graph().alive(e) && box.graph().kind(e) == box.ids().node) before.push_back(*box.position(e));
  const auto mark = eng.mark();
  engine::Application applied;
  REQUIRE(eng.step(&applied));
  std::size_t changed = 0, k = 0;
  for (engine::Id e = 0; e < box.graph().id_bound(); ++e)
    if (box.graph().alive(e) && box.graph().kind(e) == box.ids().node) changed += norm(*box.position(e) - before[k++]) > 0;
  CHECK(changed == 1);
  eng.undo(mark);
  k = 0;
  for (engine::Id e = 0; e < box.graph().id_bound(); ++e)
    if (box.graph().alive(e) && box.graph().kind(e) == box.ids().node) CHECK(norm(*box.position(e) - before[k++]) == 0);
}

TEST_CASE("a misused measure is one error line with its place") {
  const std::string head = "rule r {\n match {\n v: node\n f: face\n f.node[0] == v\n";
  CHECK(test::compile_error(head + " if angle(v, v, n) > 0\n }\n rewrite { v.boundary = 2 } }") ==
        "bad.rule:6:17: unknown variable 'n'");
  CHECK(test::compile_error(head + " if angle(v, 1, v) > 0\n }\n rewrite { v.boundary = 2 } }").rfind("bad.rule:6:14: expected a variable", 0) == 0);
  CHECK(test::compile_error(head + " if v.boundary == 1\n }\n rewrite {\n new n: node\n v.boundary = angle(v, n, v) } }") ==
        "bad.rule:10:24: measure 'angle' cannot read 'n', which the rewrite makes");
  std::string many = "angle(v";
  for (int i = 0; i < 16; ++i) many += ", v";
  CHECK(test::compile_error(head + " if " + many + ") > 0\n }\n rewrite { v.boundary = 2 } }") ==
        "bad.rule:6:5: measure 'angle' is given 17 arguments; at most 16 are allowed");

  stc::Stc box = stc::build_from_surface(gen::box(1, 1, 1));
  auto engine_error = [&](const std::string& condition) -> std::string {
    try {
      auto rules = engine::compile_rules(head + " if " + condition + "\n }\n rewrite { v.boundary = 2 } }", "bad.rule", schema());
      engine::Engine eng(box.graph(), rules, weave::weave_actions(box));
      eng.step();
    } catch (const engine::RuleError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(engine_error("angel(v, v, v) > 0") ==
        "bad.rule:6:5: expected a known measure, found 'angel' (known: angle, corner_sj, dihedral, distance, facing, gap, hex_sj)");
  CHECK(engine_error("angle(v, v) > 0") == "bad.rule:6:5: measure 'angle' takes 3 arguments (node a, node v, node b), found 2");
  CHECK(engine_error("angle(v, f, v) > 0") == "bad.rule:6:5: argument 2 of measure 'angle' (v) must be a node, found 'f', a face");
  CHECK(engine_error("angle(v, v, v) == 0") == "");

  // A matcher with no engine to bind the domain's measures says so.
  auto rules = engine::compile_rules(head + " if angle(v, v, v) == 0\n }\n rewrite { v.boundary = 2 } }", "bad.rule", schema());
  engine::Matcher matcher(box.graph());
  CHECK_THROWS_WITH_AS(matcher.each(rules[0], [](const engine::Match&) { return true; }),
                       "bad.rule:6:5: rule 'r': measure 'angle' can only be evaluated by an engine that has the domain's measures",
                       engine::RuleError);

  // An element the rewrite deleted before the statement that measures it.
  {
    stc::Stc doomed = stc::build_from_surface(gen::box(1, 1, 1));
    auto r = engine::compile_rules("rule d {\n match {" + corner_match + " }\n rewrite {\n delete v\n a.boundary = angle(a, v, b) } }",
                                   "bad.rule", schema());
    engine::Engine eng(doomed.graph(), r, weave::weave_actions(doomed));
    CHECK_THROWS_WITH_AS(eng.step(), "bad.rule:12:15: rule 'd': measure 'angle' reads 'v', which is no longer in the graph",
                         engine::RuleError);
  }
  // A node without a position yet: the measure's own error, at its call.
  stc::Stc lone;
  const engine::Id n = lone.graph().add(lone.ids().node);
  const engine::Id f = lone.graph().add(lone.ids().face);
  lone.graph().link(f, lone.ids().face_node, 0, n);
  try {
    auto r = engine::compile_rules(head + " if angle(v, v, v) == 0\n }\n rewrite { v.boundary = 2 } }", "bad.rule", schema());
    engine::Engine eng(lone.graph(), r, weave::weave_actions(lone));
    eng.step();
    FAIL("expected a RuleError");
  } catch (const engine::RuleError& e) {
    CHECK(std::string(e.what()) == fmt::format("bad.rule:6:5: rule 'r': measure 'angle' failed: node {} has no position yet", n));
  }
}

TEST_CASE("the weave's strategy measures: inverted and irregular hexes of the state, as the mesh counts them") {
  const auto rules = engine::load_rule_dir(weave::default_rules_dir(), schema());
  // randquad 20 seed 1: a sphere the weave closes alone, irregularly.
  std::vector<std::int64_t> irregular;
  for (const QuadSurface& surface : {gen::box(2, 2, 2), gen::cylinder(4, 2), gen::randquad(20, 1)}) {
    stc::Stc stc = stc::build_from_surface(surface);
    REQUIRE(weave::weave(stc, rules, {}).closed);
    const HexMesh mesh = stc::to_hex_mesh(stc);
    std::int64_t off = 0;
    for (const auto& [valence, edges] : interior_valence_histogram(mesh))
      off += static_cast<std::int64_t>(edges) * std::abs(static_cast<std::int64_t>(valence) - 4);
    CHECK(weave::irregular_edges(stc) == off);
    irregular.push_back(off);
    std::size_t inverted = 0;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) inverted += !(scaled_jacobian(mesh, h) > 0);
    CHECK(weave::inverted_hexes(stc) == static_cast<std::int64_t>(inverted));
  }
  CHECK(irregular == std::vector<std::int64_t>{0, 0, irregular[2]});
  CHECK(irregular[2] > 0);

  // A node pushed through the hexes round it inverts them.
  stc::Stc box = stc::build_from_surface(gen::box(2, 2, 2));
  REQUIRE(weave::weave(box, rules, {}).closed);
  CHECK(weave::inverted_hexes(box) == 0);
  const engine::Id corner = node_at(box, {0, 0, 0});
  REQUIRE(corner != engine::no_element);
  box.place(corner, {1.5, 1.5, 1.5});
  CHECK(weave::inverted_hexes(box) > 0);
}
