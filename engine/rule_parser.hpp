#pragma once
// Parsing rule files. A file holds one or more `rule NAME { ... }` blocks;
// docs/rules.md gives the grammar. Errors name file:line:column, what was
// expected and what was found.
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/rule_ast.hpp"

namespace loom::engine {

class RuleError : public std::runtime_error {
public:
  RuleError(const std::string& file, ast::Pos pos, const std::string& what);
  std::string file;
  ast::Pos pos;
};

/// Parses the text of one rule file; `file` names it in errors.
std::vector<ast::Rule> parse_rules(const std::string& text, const std::string& file);

}  // namespace loom::engine
