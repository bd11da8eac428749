#pragma once
// The words of a rule file: names, numbers and symbols, each with the line and
// column where it starts; `#` starts a comment to the end of the line.
#include <string>
#include <vector>

#include "engine/rule_ast.hpp"

namespace loom::engine {

struct Token {
  enum class Kind { identifier, number, symbol, end } kind = Kind::end;
  std::string text;
  ast::Pos pos;
};

/// The tokens of `text`, ending with one of kind `end`. Throws RuleError
/// (`file` at line:column) on a character no token starts with, and on a
/// number of more than 9 digits.
std::vector<Token> tokenize(const std::string& text, const std::string& file);

/// How an error message names a token: "end of file", "number 12", 'name'.
std::string describe(const Token& t);

}  // namespace loom::engine
