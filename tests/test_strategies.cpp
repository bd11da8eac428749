// Strategies as data: the grammar and its errors, what each node does on a
// real weave, and `loom weave --strategy FILE`.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "engine/strategy_run.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::run_cli;
using loom::test::ScratchDir;

namespace {

std::string parse_error(const std::string& text) {
  try {
    engine::Strategy::parse_text(text, "s.strategy");
  } catch (const engine::RuleError& e) {
    return e.what();
  }
  return "";
}

std::vector<engine::Rule> shipped_rules() {
  return engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
}

/// An engine over a fresh STC of `surface` with the shipped rules, and the
/// weave's measure `front` (whiskers left).
struct Bench {
  explicit Bench(const QuadSurface& surface)
      : stc(stc::build_from_surface(surface)), eng(stc.graph(), shipped_rules(), weave::weave_actions(stc)) {
    domain.measures["front"] = [this] { return static_cast<std::int64_t>(stc.whiskers()); };
  }
  engine::StrategyOutcome run(const std::string& text) {
    auto s = engine::Strategy::parse_text(text, "t.strategy");
    engine::check_strategy(s, eng.rules(), {"front"});
    return engine::run_strategy(eng, s, domain);
  }
  stc::Stc stc;
  engine::Engine eng;
  engine::StrategyDomain domain;
};

}  // namespace

TEST_CASE("the shipped strategies parse into their phases") {
  const auto s = weave::default_strategy();
  REQUIRE(s.phases.size() == 2);
  CHECK(s.phases[0].name == "weave");
  CHECK(s.phases[1].name == "repair");
  const auto& bt = s.phases[0].body.at(0);
  CHECK(bt.op == engine::StrategyNode::Op::backtrack);
  CHECK((bt.goal == "front" && bt.window == 64 && bt.branching == 3 && bt.max_backtracks == 200));
  CHECK((bt.body.at(0).all && bt.body.at(0).rules == std::vector<std::string>{"pillow_improper"}));
  CHECK_FALSE(s.random());
  CHECK(s.with_random_picks().random());
  const auto plain =
      engine::Strategy::parse((weave::default_rules_dir() / "strategies" / "no_backtracking.strategy").string());
  CHECK(plain.phases.at(0).body.at(0).op == engine::StrategyNode::Op::repeat);

  // Backtracking taken out of the default is the shipped no_backtracking
  // file, and of any rule set's strategy leaves no backtrack node.
  const auto unwound = s.without_backtracking();
  REQUIRE(unwound.phases.size() == plain.phases.size());
  for (std::size_t p = 0; p < plain.phases.size(); ++p) {
    std::vector<std::pair<engine::StrategyNode::Op, std::vector<std::string>>> a, b;
    each_node(unwound.phases[p].body, [&](const engine::StrategyNode& n) { a.push_back({n.op, n.rules}); });
    each_node(plain.phases[p].body, [&](const engine::StrategyNode& n) { b.push_back({n.op, n.rules}); });
    CHECK(a == b);
  }
  CHECK(unwound.name().ends_with(" (no backtracking)"));
  for (const auto& spec : {"priority", "random", "sequence:seam,cross"}) {
    bool backtracks = false;
    for (const auto& phase : weave::strategy_named(spec).without_backtracking().phases)
      each_node(phase.body, [&](const engine::StrategyNode& n) { backtracks |= n.op == engine::StrategyNode::Op::backtrack; });
    CHECK_FALSE_MESSAGE(backtracks, spec);
  }
}

TEST_CASE("a broken strategy is refused with file:line:column and what was expected") {
  CHECK(parse_error("phase p { apply }") == "s.strategy:1:17: expected a rule name or 'all', found '}'");
  CHECK(parse_error("phase p {\n  backtrack { apply all }\n}") ==
        "s.strategy:2:15: backtrack needs 'goal MEASURE' first (the goal is that the measure reaches 0), found 'apply'");
  CHECK(parse_error("phase p { backtrack { goal front repeat { apply all } } }") ==
        "s.strategy:1:34: backtrack takes one 'apply' (its alternatives are that apply's matches), found 'repeat'");
  CHECK(parse_error("phase p { }") == "s.strategy:1:11: an empty block does nothing; write a node in it, found '}'");
  CHECK(parse_error("seed x") == "s.strategy:1:6: expected a seed (a non-negative integer), found 'x'");
  CHECK(parse_error("# nothing\n") == "s.strategy: a strategy needs at least one 'phase NAME { ... }', found 'end of file'");
  CHECK(parse_error("phase p { apply all ! }") ==
        "s.strategy:1:21: unexpected character '!'; a strategy holds words, numbers and braces");
  CHECK(parse_error("phase p { frobnicate }") ==
        "s.strategy:1:11: expected 'apply', 'repeat', 'try', 'backtrack', 'search', 'beam', 'when' or '}', found 'frobnicate'");
  std::string deep = "phase p ";
  for (int i = 0; i < 300; ++i) deep += "{ repeat ";
  CHECK(parse_error(deep).find("blocks nested more than 100 deep") != std::string::npos);

  Bench b(gen::box(1, 1, 1));
  auto checked = [&](const std::string& text) -> std::string {
    try {
      engine::check_strategy(engine::Strategy::parse_text(text, "c.strategy"), b.eng.rules(), {"front"});
    } catch (const engine::RuleError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(checked("phase p { apply cross nosuch }") == "c.strategy:1:11: no rule 'nosuch' is loaded; see 'loom rules list'");
  CHECK(checked("phase p { when volume }") == "c.strategy:1:11: no measure 'volume' to make a goal of; this domain has: front");
  CHECK(checked("phase p { apply all except cross }").empty());
}

TEST_CASE("phases run in order; repeat applies to normal form; a rule of a later phase waits for it") {
  Bench b(gen::box(2, 2, 2));
  auto out = b.run("phase first { repeat { apply seam } }\nphase second { repeat { apply priority all except pillow_improper } }");
  REQUIRE(out.phases.size() == 2);
  CHECK(out.phases[0].name == "first");
  CHECK(out.phases[0].steps == 0);  // no seam before a cross
  CHECK(out.phases[1].steps > 0);
  CHECK(b.stc.whiskers() == 0);
  CHECK(b.stc.hexes() == 8);
  CHECK(b.eng.applications().count("pillow_improper") == 0);
}

TEST_CASE("try undoes a block that fails and runs its else; when gates a block on a measure") {
  Bench b(gen::box(1, 1, 1));
  const std::size_t elements = b.stc.graph().size();
  // One cross, then `when front` fails (whiskers are left): the cross is undone.
  auto out = b.run("phase p { try { apply cross  when front } }");
  CHECK(out.phases[0].steps == 1);
  CHECK(b.stc.hexes() == 0);
  CHECK(b.stc.graph().size() == elements);
  CHECK(b.eng.counters().undos >= 1);

  b.run("phase p { try { apply cross  when front } else { apply cross } }");
  CHECK(b.stc.hexes() == 1);

  out = b.run("phase p { when front  apply cross }");
  CHECK(out.phases[0].steps == 0);
  CHECK(b.stc.hexes() == 1);
}

TEST_CASE("a strategy's step bound stops it, and says so") {
  Bench b(gen::box(3, 3, 3));
  b.domain.max_steps = 5;
  auto out = b.run("phase p { repeat { apply priority all except pillow_improper } }");
  CHECK(out.step_limit_hit);
  CHECK(b.eng.counters().steps == 5);
}

TEST_CASE("loom weave runs a strategy file, reports its phases, and refuses a broken one with exit 2") {
  ScratchDir dir("strategies");
  REQUIRE(run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  const std::string plain = (weave::default_rules_dir() / "strategies" / "no_backtracking.strategy").string();
  auto r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "a.vtk").string() + " --strategy " + plain +
                   " --report " + (dir / "a.json").string());
  REQUIRE(r.status == 0);
  std::ifstream in(dir / "a.json");
  auto j = nlohmann::json::parse(in);
  CHECK(j["strategy"] == plain);
  REQUIRE(j["phases"].size() == 2);
  CHECK(j["phases"][0]["name"] == "weave");
  CHECK(j["phases"][0]["steps"].get<int>() > 0);
  CHECK(j["phases"][1]["name"] == "repair");
  CHECK(j["hexes"] == 8);
  CHECK(j["woven_attempt"] == 1);
  CHECK(j["prefer"] == "quality");

  // The weave's measures as a beam's goal and cost, through the CLI: it weaves the box alone.
  {
    std::ofstream beam(dir / "beam.strategy");
    beam << "phase weave { beam { goal front cost inverted width 2 depth 100 branching 2 max 100000\n"
            "  apply priority all except pillow_improper } }\n";
  }
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "c.vtk").string() + " --closure none --strategy " +
              (dir / "beam.strategy").string() + " --report " + (dir / "c.json").string());
  REQUIRE_MESSAGE(r.status == 0, r.err);
  j = nlohmann::json::parse(std::ifstream(dir / "c.json"));
  CHECK(j["made_by"] == "woven");
  CHECK(j["hexes"] == 8);
  CHECK(j["phases"][0]["searched"].get<int>() > 0);

  {
    std::ofstream bad(dir / "bad.strategy");
    bad << "phase weave {\n  apply priority all except nosuch\n}\n";
  }
  r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "b.vtk").string() + " --strategy " +
              (dir / "bad.strategy").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("bad.strategy:2:3: no rule 'nosuch' is loaded") != std::string::npos);
  CHECK(r.err.find("docs/strategies.md") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "b.vtk"));
}

TEST_CASE("search: the fewest applications that reach the goal, the domain seeing only those; else nothing changes") {
  CHECK(parse_error("phase p { search { apply all } }") ==
        "s.strategy:1:20: search needs 'goal MEASURE' first (the goal is that the measure reaches 0), found 'apply'");
  CHECK(parse_error("phase p { search { goal front depth 0 apply all } }") ==
        "s.strategy:1:37: expected a depth of at least 1 (with 0 a search tries nothing), found '0'");
  CHECK(parse_error("phase p { search { goal front depth 999999999999 apply all } }") ==
        "s.strategy:1:11: a search deeper than 1000 levels; lower its depth");
  CHECK(parse_error("phase p { search { goal front repeat { apply all } } }") ==
        "s.strategy:1:31: search takes one 'apply' (its branches are that apply's matches), found 'repeat'");
  const auto defaults = engine::Strategy::parse_text("phase p { search { goal front apply all } }", "d.strategy");
  const auto& node = defaults.phases.at(0).body.at(0);
  CHECK((node.op == engine::StrategyNode::Op::search && node.depth == 4 && node.branching == 3 &&
         node.max_tried == 10'000));

  // How many applications the plain weave of a 1x1x2 box takes, and what a
  // search allowed one fewer, or that many, finds.
  Bench greedy(gen::box(1, 1, 2));
  greedy.run("phase p { repeat { apply all except pillow_improper } }");
  REQUIRE(greedy.stc.whiskers() == 0);
  const std::size_t plain = greedy.eng.counters().steps;
  REQUIRE(plain >= 2);

  const std::string rules = " branching 6 max 100000 apply all except pillow_improper } }";
  Bench shallow(gen::box(1, 1, 2));
  const std::size_t elements = shallow.stc.graph().size();
  std::size_t seen = 0;
  shallow.domain.after_step = [&](const engine::Application&) { ++seen; };
  auto out = shallow.run(fmt::format("phase p {{ search {{ goal front depth {}", plain - 1) + rules);
  CHECK(shallow.stc.whiskers() > 0);
  CHECK(shallow.stc.graph().size() == elements);
  CHECK(shallow.stc.hexes() == 0);
  CHECK(seen == 0);
  CHECK(out.phases[0].searched > 0);

  auto trace = [&](std::vector<std::string>& lines) {
    Bench b(gen::box(1, 1, 2));
    b.domain.after_step = [&](const engine::Application& a) {
      lines.push_back(fmt::format("{} {}", a.rule->name, fmt::join(a.matched.elements, ",")));
      CHECK(b.stc.check_invariants().empty());
    };
    auto o = b.run(fmt::format("phase p {{ search {{ goal front depth {}", plain) + rules);
    CHECK(b.stc.whiskers() == 0);
    CHECK(b.stc.hexes() == greedy.stc.hexes());
    CHECK(o.phases[0].searched >= lines.size());
    return o;
  };
  std::vector<std::string> first, second;
  trace(first);
  trace(second);
  CHECK(first.size() == plain);  // none shorter: the search one shorter failed
  CHECK(first == second);
}

TEST_CASE("a broken default strategy in the rule directory is bad input: exit 2 naming its line") {
  // It is read as the options are made, before the command could catch it:
  // it used to end as an internal error with status 1.
  ScratchDir dir("broken-default");
  std::filesystem::copy(weave::default_rules_dir(), dir / "rules", std::filesystem::copy_options::recursive);
  {
    std::ofstream broken(dir / "rules" / "strategies" / "default.strategy", std::ios::trunc);
    broken << "phase p { frob }\n";
  }
  REQUIRE(run_cli("gen box 1 1 1 -o " + (dir / "box.obj").string()).status == 0);
  ::setenv("LOOM_RULES", (dir / "rules").c_str(), 1);
  const auto r = run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "b.vtk").string());
  ::unsetenv("LOOM_RULES");
  CHECK(r.status == 2);
  CHECK(r.err.find("default.strategy:1:11: expected 'apply'") != std::string::npos);
  CHECK(r.err.find("internal error") == std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "b.vtk"));
}

TEST_CASE("the domain is told what a failed try undoes, newest first") {
  Bench b(gen::box(2, 2, 2));
  std::vector<std::size_t> shown, undone;
  b.domain.after_step = [&](const engine::Application& a) { shown.push_back(a.step); };
  b.domain.after_undo = [&](std::size_t step) { undone.push_back(step); };
  b.run("phase p { apply cross  try { apply cross  apply cross  when front } }");
  CHECK(shown == std::vector<std::size_t>{1, 2, 3});
  CHECK(undone == std::vector<std::size_t>{3, 2});
  CHECK(b.stc.hexes() == 1);
}

TEST_CASE("what a backtracking weave shows and does not undo, applied again in order, is the same weave") {
  // randquad 16 s1 backtracks about a hundred times under the default strategy.
  const QuadSurface surface = gen::randquad(16, 1);
  Bench woven(surface);
  std::vector<std::pair<std::size_t, engine::Match>> kept;
  std::size_t undos = 0;
  woven.domain.after_step = [&](const engine::Application& a) { kept.emplace_back(a.step, a.matched); };
  woven.domain.after_undo = [&](std::size_t step) {
    REQUIRE(!kept.empty());
    CHECK(kept.back().first == step);  // newest first, and only what was shown
    kept.pop_back();
    ++undos;
  };
  const auto default_strategy = weave::default_strategy();
  engine::check_strategy(default_strategy, woven.eng.rules(), {"front"});
  engine::run_strategy(woven.eng, default_strategy, woven.domain);
  REQUIRE(undos > 10);
  REQUIRE(woven.stc.hexes() > 0);

  Bench again(surface);
  for (auto& [step, match] : kept) again.eng.apply(match);
  CHECK(again.stc.hexes() == woven.stc.hexes());
  CHECK(again.stc.whiskers() == woven.stc.whiskers());
  CHECK(again.stc.graph().size() == woven.stc.graph().size());
  const HexMesh a = stc::woven_hexes(again.stc), w = stc::woven_hexes(woven.stc);
  CHECK(a.hexes == w.hexes);
}
