// Rule files that are well-formed but abusive or clearly mistaken are refused at
// load time with file:line:column, never a crash (issue 15).
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/weave/weave.hpp"
#include "tests/rule_errors.hpp"
#include "tests/support.hpp"

using namespace loom;
using loom::test::compile_error;

namespace {

const engine::Schema& schema() { return *stc::StcSchema::get().schema; }


bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string repeated(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

std::string rule_with_order(const std::string& order, const std::string& rewrite = "u.boundary = 1") {
  return "rule deep {\n  order " + order + "\n  match {\n    u: node\n  }\n  rewrite {\n    " + rewrite + "\n  }\n}\n";
}

// What weaving a box with `text` as the only rule throws, if anything.
std::string weave_error(const std::string& text) {
  stc::Stc stc = stc::build_from_surface(gen::box(1, 1, 1));
  try {
    engine::Engine eng(stc.graph(), engine::compile_rules(text, "bad.rule", schema()), {}, {});
    while (eng.step()) {
    }
  } catch (const engine::RuleError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("nesting deeper than 200 levels is a RuleError at its position, not a stack overflow") {
  const std::string too_deep = "nesting is too deep: more than 200 levels";
  CHECK(contains(compile_error(rule_with_order(repeated("(", 3000) + "1" + repeated(")", 3000))),
                 "bad.rule:2:209: " + too_deep));
  CHECK(contains(compile_error(rule_with_order(repeated("-", 100000) + "1")), too_deep));
  CHECK(contains(compile_error(rule_with_order(repeated("not ", 100000) + "1")), too_deep));
  CHECK(contains(compile_error(rule_with_order("1" + repeated("+1", 300000))), too_deep));
  CHECK(contains(compile_error("rule deep { match { u: node\n" + repeated("not { ", 5000) + repeated("}", 5000) + "} }"),
                 too_deep));
  // What real rules write stays well inside the limit.
  CHECK(compile_error(rule_with_order(repeated("(", 50) + "1" + repeated("+1", 100) + repeated(")", 50))) ==
        "");
}

TEST_CASE("loom rules list on a deeply nested rule file exits 2 with one line") {
  test::ScratchDir dir("rule-limits");
  std::ofstream(dir / "deep.rule") << rule_with_order(repeated("(", 3000) + "1" + repeated(")", 3000));
  auto r = test::run_cli("rules list " + (dir / "deep.rule").string());
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(contains(r.err, "deep.rule:2:209: nesting is too deep"));
}

TEST_CASE("constant rule arithmetic that overflows 64 bits is refused at load, at the operator") {
  const std::string big = "999999999 * 999999999 * 999999999";
  CHECK(compile_error(rule_with_order(big)) ==
        "bad.rule:2:31: rule 'deep': 999999998000000001 * 999999999 overflows 64-bit integers");
  CHECK(compile_error(rule_with_order("1", "u.boundary = max(2, " + big + ")")) ==
        "bad.rule:7:47: rule 'deep': 999999998000000001 * 999999999 overflows 64-bit integers");
  CHECK(contains(compile_error(rule_with_order("-999999999 * 999999999 * 999999999 * 9 - 9")),
                 "rule 'deep': -999999998000000001 * 999999999 overflows 64-bit integers"));
  CHECK(compile_error(rule_with_order("999999999 * 999999999 * 9")) == "");  // fits
}

TEST_CASE("rule arithmetic that overflows while weaving is a RuleError naming the rule and the operator") {
  // Not constant: node.boundary is only known at run time (1 on the surface).
  const std::string big = "u.boundary * 999999999 * 999999999 * 999999999";
  CHECK(weave_error(rule_with_order(big)) ==
        "bad.rule:2:44: rule 'deep': 999999998000000001 * 999999999 overflows 64-bit integers");
  CHECK(weave_error(rule_with_order("1", "u.boundary = " + big)) ==
        "bad.rule:7:53: rule 'deep': 999999998000000001 * 999999999 overflows 64-bit integers");
  CHECK(weave_error("rule deep { match { u: node\n if -(u.boundary * 999999999 * 999999999 * 9) - u.boundary * "
                    "999999999 * 999999999 * 9 < 0 } }") ==
        "bad.rule:2:47: rule 'deep': -8999999982000000009 - 8999999982000000009 overflows 64-bit integers");
}

TEST_CASE("loom weave with a rule whose order overflows exits 2 with one line and writes nothing") {
  test::ScratchDir dir("rule-overflow");
  for (const auto& f : std::filesystem::directory_iterator(weave::default_rules_dir()))
    if (f.path().extension() == ".rule") std::filesystem::copy_file(f.path(), dir / f.path().filename().string());
  std::string cross = test::slurp(dir / "cross.rule");
  const std::string order = "order f1.layer + f2.layer + f3.layer";
  REQUIRE(cross.find(order) != std::string::npos);
  cross.replace(cross.find(order), order.size(), "order (f1.layer + 1) * 999999999 * 999999999 * 999999999");
  test::spit(dir / "cross.rule", cross);
  REQUIRE(test::run_cli("gen box 2 2 2 -o " + (dir / "box.obj").string()).status == 0);
  auto r = test::run_cli("weave " + (dir / "box.obj").string() + " -o " + (dir / "out.vtk").string() + " --rules " +
                         dir.path().string());
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(contains(r.err, "cross.rule:15:48: rule 'cross': 999999998000000001 * 999999999 overflows 64-bit integers"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.vtk"));
}

TEST_CASE("an empty rewrite block and merging an element into itself are refused at load") {
  CHECK(compile_error("rule r {\n  match { v: node }\n  rewrite { }\n}\n") ==
        "bad.rule:3:3: rule 'r' has an empty 'rewrite' block; write its statements, or leave the block out for a "
        "rule that only matches");
  CHECK(contains(compile_error("rule r { match { v: node } rewrite { v.boundary = 1 } rewrite { ; } }"),
                 "bad.rule:1:55: rule 'r' has an empty 'rewrite' block"));
  // A rule that only matches (no rewrite at all) is how patterns are matched and benchmarked.
  CHECK(compile_error("rule r { match { v: node } }") == "");

  const std::string merging = "rule seam2 {\n  match {\n    f: face\n    p12, q: node\n    f.node[0] == p12\n"
                              "    f.node[1] == q\n  }\n  rewrite {\n    ";
  CHECK(compile_error(merging + "merge p12 into p12\n  }\n}\n") ==
        "bad.rule:9:5: rule 'seam2': merging an element with itself does nothing; name two different elements");
  CHECK(compile_error(merging + "identify f.node[1], f.node[1]\n  }\n}\n") ==
        "bad.rule:9:5: rule 'seam2': identifying an element with itself does nothing; name two different elements");
  CHECK(compile_error(merging + "merge p12 into q\n  }\n}\n") == "");
  CHECK(compile_error(merging + "identify f.node[0], f.node[1]\n  }\n}\n") == "");

  test::ScratchDir dir("rule-mistakes");
  std::ofstream(dir / "self.rule") << merging + "merge p12 into p12\n  }\n}\n";
  auto r = test::run_cli("rules list " + (dir / "self.rule").string());
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(contains(r.err, "self.rule:9:5: rule 'seam2': merging an element with itself does nothing"));
}
