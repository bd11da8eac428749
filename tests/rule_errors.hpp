#pragma once
// For the rule-file suites: what compiling a rule text against the STC schema
// throws, as one line ("" when it compiles).
#include <string>

#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/stc/stc.hpp"

namespace loom::test {

inline std::string compile_error(const std::string& text, const std::string& file = "bad.rule") {
  try {
    engine::compile_rules(text, file, *stc::StcSchema::get().schema);
  } catch (const engine::RuleError& e) {
    return e.what();
  }
  return "";
}

}  // namespace loom::test
