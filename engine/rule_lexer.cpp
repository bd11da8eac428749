#include "engine/rule_lexer.hpp"

#include <cctype>

#include <fmt/format.h>

#include "engine/quoted.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

std::string describe(const Token& t) {
  switch (t.kind) {
    case Token::Kind::end: return "end of file";
    case Token::Kind::number: return "number " + t.text;
    case Token::Kind::identifier: return quoted(t.text);
    case Token::Kind::symbol: return quoted(t.text);
  }
  return t.text;
}

std::vector<Token> tokenize(const std::string& text, const std::string& file) {
  std::vector<Token> out;
  int line = 1, column = 1;
  std::size_t i = 0;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k, ++i) {
      if (text[i] == '\n') ++line, column = 1;
      else ++column;
    }
  };
  while (i < text.size()) {
    char c = text[i];
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') advance(1);
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      advance(1);
      continue;
    }
    Token t;
    t.pos = {line, column};
    std::size_t start = i;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) advance(1);
      t.kind = Token::Kind::identifier;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) advance(1);
      t.kind = Token::Kind::number;
      if (i - start > 9) throw RuleError(file, t.pos, "number too large");
    } else {
      static const char* pairs[] = {"==", "!=", "<=", ">=", "->"};
      t.kind = Token::Kind::symbol;
      bool two = false;
      for (const char* p : pairs)
        if (text.compare(i, 2, p) == 0) two = true;
      if (!two && std::string("{}()[],:;.=<>+-*").find(c) == std::string::npos)
        throw RuleError(file, t.pos, fmt::format("unexpected character '{}'", printable(std::string(1, c))));
      advance(two ? 2 : 1);
    }
    t.text = text.substr(start, i - start);
    out.push_back(std::move(t));
  }
  out.push_back(Token{Token::Kind::end, "", {line, column}});
  return out;
}

}  // namespace loom::engine
