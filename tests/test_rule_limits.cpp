// Rule files that are well-formed but abusive or clearly mistaken are refused at
// load time with file:line:column, never a crash (issue 15).
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/stc/stc.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

const engine::Schema& schema() { return *stc::StcSchema::get().schema; }

std::string compile_error(const std::string& text) {
  try {
    engine::compile_rules(text, "bad.rule", schema());
  } catch (const engine::RuleError& e) {
    return e.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string repeated(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

std::string rule_with_order(const std::string& order) {
  return "rule deep {\n  order " + order + "\n  match {\n    u: node\n  }\n  rewrite {\n    u.boundary = 1\n  }\n}\n";
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
        "(no error)");
}

TEST_CASE("loom rules list on a deeply nested rule file exits 2 with one line") {
  test::ScratchDir dir("rule-limits");
  std::ofstream(dir / "deep.rule") << rule_with_order(repeated("(", 3000) + "1" + repeated(")", 3000));
  auto r = test::run_cli("rules list " + (dir / "deep.rule").string());
  CHECK(r.status == 2);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(contains(r.err, "deep.rule:2:209: nesting is too deep"));
}
