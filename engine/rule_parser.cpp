// A recursive-descent parser for rule files. Statements need no separator
// (each starts with a keyword or a name); `;` may be used and is ignored.
#include "engine/rule_parser.hpp"
#include "engine/rule_lexer.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace loom::engine {

RuleError::RuleError(const std::string& f, ast::Pos p, const std::string& what)
    : std::runtime_error(p.line > 0 ? fmt::format("{}:{}:{}: {}", f, p.line, p.column, what)
                                    : fmt::format("{}: {}", f, what)),
      file(f),
      pos(p) {}

namespace {

using ast::Expr;
using ast::Pos;

class Parser {
public:
  Parser(std::vector<Token> tokens, std::string file) : tokens_(std::move(tokens)), file_(std::move(file)) {}

  std::vector<ast::Rule> rules() {
    std::vector<ast::Rule> out;
    while (peek().kind != Token::Kind::end) {
      expect_word("rule");
      out.push_back(rule());
    }
    if (out.empty()) fail(peek(), "expected 'rule'");
    return out;
  }

private:
  const Token& peek(std::size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  Token next() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }
  bool is(const char* text, std::size_t ahead = 0) const {
    const Token& t = peek(ahead);
    return t.kind != Token::Kind::end && t.kind != Token::Kind::number && t.text == text;
  }
  bool accept(const char* text) {
    if (!is(text)) return false;
    next();
    return true;
  }
  // Deep nesting would overflow the stack, here and in every pass that later
  // walks the tree recursively; real rules nest a few levels.
  static constexpr int max_nesting = 200;
  [[noreturn]] void fail_nesting(const Token& t) const {
    throw RuleError(file_, t.pos,
                    fmt::format("nesting is too deep: more than {} levels of parentheses, operators or 'not' blocks",
                                max_nesting));
  }
  // Counts one level of parser recursion for its lifetime.
  class Nested {
  public:
    explicit Nested(Parser& parser) : parser_(parser) {
      if (parser_.nesting_ == max_nesting) parser_.fail_nesting(parser_.peek());
      ++parser_.nesting_;
    }
    ~Nested() { --parser_.nesting_; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

  private:
    Parser& parser_;
  };
  // Sets e's height from its operands; an operator chain (1+1+...+1) is as deep
  // as it is long even without parentheses.
  void set_height(Expr& e, const Pos& pos) const {
    e.height = 1;
    for (const Expr& a : e.args) e.height = std::max(e.height, a.height + 1);
    if (e.height > max_nesting) fail_nesting(Token{Token::Kind::symbol, "", pos});
  }
  [[noreturn]] void fail(const Token& t, const std::string& expected) const {
    throw RuleError(file_, t.pos, fmt::format("{}, found {}", expected, describe(t)));
  }
  void expect(const char* symbol) {
    if (!accept(symbol)) fail(peek(), fmt::format("expected '{}'", symbol));
  }
  void expect_word(const char* word) {
    if (!accept(word)) fail(peek(), fmt::format("expected '{}'", word));
  }
  std::string name(const char* what = "a name") {
    if (peek().kind != Token::Kind::identifier || peek().text == "_") fail(peek(), fmt::format("expected {}", what));
    return next().text;
  }
  std::int64_t integer() {
    bool negative = accept("-");
    if (peek().kind != Token::Kind::number) fail(peek(), "expected a number");
    std::int64_t v = std::stoll(next().text);
    return negative ? -v : v;
  }

  ast::Rule rule() {
    ast::Rule r;
    r.pos = peek().pos;
    r.file = file_;
    r.name = name("a rule name");
    expect("{");
    bool seen_match = false;
    while (!accept("}")) {
      const Token& t = peek();
      if (accept("priority")) r.priority = integer();
      else if (accept("order")) r.order = expr();
      else if (accept("anchor")) r.anchor = name("an anchor variable");
      else if (accept("match")) {
        expect("{");
        r.pattern = pattern();
        seen_match = true;
      } else if (accept("rewrite")) {
        // A rule that only matches leaves `rewrite` out; an empty block is an
        // unfinished rule, which would be applied to no effect.
        const Pos at = t.pos;
        const std::size_t before = r.rewrite.size();
        expect("{");
        while (!accept("}")) statement(r.rewrite);
        if (r.rewrite.size() == before)
          throw RuleError(file_, at,
                          fmt::format("rule '{}' has an empty 'rewrite' block; write its statements, or leave the "
                                      "block out for a rule that only matches",
                                      r.name));
      } else if (!accept(";")) {
        fail(t, "expected 'priority', 'order', 'anchor', 'match', 'rewrite' or '}'");
      }
    }
    if (!seen_match) fail(previous(), fmt::format("rule '{}' has no 'match' block; expected 'match'", r.name));
    return r;
  }
  const Token& previous() const { return tokens_[pos_ > 0 ? pos_ - 1 : 0]; }

  ast::Pattern pattern() {
    Nested nested(*this);
    ast::Pattern p;
    p.pos = peek().pos;
    while (!accept("}")) {
      const Token& t = peek();
      if (accept(";")) continue;
      if (accept("not")) {
        expect("{");
        p.negatives.push_back(pattern());
      } else if (accept("if")) {
        p.conditions.push_back(expr());
      } else if (accept("count")) {
        p.counts.push_back(count(t.pos));
      } else if (t.text == "test" && t.kind == Token::Kind::identifier && is("(", 2)) {
        next();
        p.tests.push_back(call(t.pos, "a test name"));
      } else if (accept("hom")) {
        expect("(");
        std::vector<std::string> names{name()};
        while (accept(",")) names.push_back(name());
        expect(")");
        p.may_be_equal.push_back(std::move(names));
      } else if (t.kind == Token::Kind::identifier && (is(",", 1) || is(":", 1))) {
        ast::Declaration d;
        d.pos = t.pos;
        d.names.push_back(name());
        while (accept(",")) d.names.push_back(name());
        expect(":");
        d.kind = name("a kind");
        if (accept("where")) d.where = expr();
        p.declarations.push_back(std::move(d));
      } else if (t.kind == Token::Kind::identifier && is(".", 1)) {
        ast::Incidence inc;
        inc.pos = t.pos;
        inc.owner = name();
        expect(".");
        inc.port = name("a port");
        if (accept("[")) {
          inc.index = index(true);
          inc.indexed = true;
          expect("]");
        }
        expect("==");
        if (!accept("none")) inc.target = name("a variable or 'none'");
        p.incidences.push_back(std::move(inc));
      } else {
        fail(t, "expected a declaration 'x: kind', an incidence 'x.port[i] == y', 'if', 'count', 'test', 'hom', 'not' or '}'");
      }
    }
    return p;
  }

  /// `NAME(a, b, ...)` after `call` or `test`.
  ast::Statement call(Pos pos, const char* what) {
    ast::Statement s;
    s.op = ast::Statement::Op::call;
    s.pos = pos;
    s.kind = name(what);
    expect("(");
    if (!accept(")")) {
      s.names.push_back(name());
      while (accept(",")) s.names.push_back(name());
      expect(")");
    }
    return s;
  }

  ast::Count count(Pos pos) {
    ast::Count c;
    c.pos = pos;
    expect("(");
    c.kind = name("a kind");
    expect(".");
    c.port = name("a port");
    expect("->");
    c.target = name("a variable");
    if (accept("where")) c.where = expr();
    expect(")");
    const Token& t = peek();
    static const std::pair<const char*, Expr::Op> ops[] = {{"==", Expr::Op::eq}, {"!=", Expr::Op::ne}, {"<=", Expr::Op::le},
                                                          {">=", Expr::Op::ge}, {"<", Expr::Op::lt},  {">", Expr::Op::gt}};
    bool found = false;
    for (auto& [text, op] : ops)
      if (!found && accept(text)) c.comparison = op, found = true;
    if (!found) fail(t, "expected a comparison after count(...)");
    c.bound = integer();
    return c;
  }

  ast::Index index(bool allow_any) {
    ast::Index ix;
    if (peek().kind == Token::Kind::number || is("-")) {
      ix.offset = static_cast<int>(integer());
      return ix;
    }
    if (accept("_")) {
      if (!allow_any) fail(previous(), "expected an index ('_' is only allowed in a match)");
      ix.kind = ast::Index::Kind::any;
      return ix;
    }
    ix.kind = ast::Index::Kind::variable;
    ix.variable = name("an index");
    if (accept("+")) ix.offset = static_cast<int>(integer());
    else if (accept("-")) ix.offset = -static_cast<int>(integer());
    return ix;
  }

  void statement(std::vector<ast::Statement>& out) {
    ast::Statement s;
    const Token& t = peek();
    s.pos = t.pos;
    if (accept(";")) return;
    if (accept("new")) {
      s.op = ast::Statement::Op::create;
      s.names.push_back(name());
      while (accept(",")) s.names.push_back(name());
      expect(":");
      s.kind = name("a kind");
    } else if (accept("delete")) {
      s.op = ast::Statement::Op::remove;
      s.names.push_back(name());
    } else if (accept("merge")) {
      s.op = ast::Statement::Op::merge;
      s.values.push_back(primary());
      expect_word("into");
      s.values.push_back(primary());
    } else if (accept("identify")) {
      s.op = ast::Statement::Op::identify;
      s.values.push_back(primary());
      expect(",");
      s.values.push_back(primary());
      if (accept("prefer")) s.kind = name("an attribute");
    } else if (accept("call")) {
      s = call(t.pos, "an action name");
    } else if (t.kind == Token::Kind::identifier && is(".", 1)) {
      s.target = name();
      expect(".");
      s.member = name("a port or attribute");
      bool indexed = false;
      if (accept("[")) {
        s.index = index(false);
        expect("]");
        indexed = true;
      }
      expect("=");
      if (!indexed && accept("[")) {
        s.op = ast::Statement::Op::set_port_list;
        s.values.push_back(expr());
        while (accept(",")) s.values.push_back(expr());
        expect("]");
      } else {
        s.op = indexed ? ast::Statement::Op::set_port : ast::Statement::Op::set_attribute;
        s.values.push_back(expr());
      }
    } else {
      fail(t, "expected 'new', 'delete', 'merge', 'identify', 'call', 'x.member = ...' or '}'");
    }
    out.push_back(std::move(s));
  }

  // --- expressions, loosest first ---------------------------------------
  Expr expr() {
    Nested nested(*this);
    return disjunction();
  }
  Expr binary(Expr::Op op, Expr a, Expr b, Pos pos) {
    Expr e;
    e.op = op;
    e.pos = pos;
    e.args.push_back(std::move(a));
    e.args.push_back(std::move(b));
    set_height(e, pos);
    return e;
  }
  Expr disjunction() {
    Expr e = conjunction();
    while (is("or")) {
      Pos p = next().pos;
      e = binary(Expr::Op::either, std::move(e), conjunction(), p);
    }
    return e;
  }
  Expr conjunction() {
    Expr e = negation();
    while (is("and")) {
      Pos p = next().pos;
      e = binary(Expr::Op::both, std::move(e), negation(), p);
    }
    return e;
  }
  Expr negation() {
    if (is("not") && !is("{", 1)) {
      Nested nested(*this);
      Expr e;
      e.pos = next().pos;
      e.op = Expr::Op::negate;
      e.args.push_back(negation());
      set_height(e, e.pos);
      return e;
    }
    return comparison();
  }
  Expr comparison() {
    Expr e = additive();
    static const std::pair<const char*, Expr::Op> ops[] = {{"==", Expr::Op::eq}, {"!=", Expr::Op::ne}, {"<=", Expr::Op::le},
                                                          {">=", Expr::Op::ge}, {"<", Expr::Op::lt},  {">", Expr::Op::gt}};
    for (auto& [text, op] : ops)
      if (is(text)) {
        Pos p = next().pos;
        return binary(op, std::move(e), additive(), p);
      }
    return e;
  }
  Expr additive() {
    Expr e = multiplicative();
    while (is("+") || is("-")) {
      Token t = next();
      e = binary(t.text == "+" ? Expr::Op::add : Expr::Op::sub, std::move(e), multiplicative(), t.pos);
    }
    return e;
  }
  Expr multiplicative() {
    Expr e = unary();
    while (is("*")) {
      Pos p = next().pos;
      e = binary(Expr::Op::mul, std::move(e), unary(), p);
    }
    return e;
  }
  Expr unary() {
    if (is("-")) {
      Nested nested(*this);
      Expr e;
      e.pos = next().pos;
      e.op = Expr::Op::neg;
      e.args.push_back(unary());
      set_height(e, e.pos);
      return e;
    }
    return primary();
  }
  Expr primary() {
    Expr e;
    const Token& t = peek();
    e.pos = t.pos;
    if (t.kind == Token::Kind::number) {
      e.value = std::stoll(next().text);
      return e;
    }
    if (accept("(")) {
      e = expr();
      expect(")");
      return e;
    }
    if (accept("none")) {
      e.op = Expr::Op::none;
      return e;
    }
    if ((is("max") || is("min")) && is("(", 1)) {
      e.op = next().text == "max" ? Expr::Op::max : Expr::Op::min;
      expect("(");
      e.args.push_back(expr());
      while (accept(",")) e.args.push_back(expr());
      expect(")");
      set_height(e, e.pos);
      return e;
    }
    if (t.kind != Token::Kind::identifier) fail(t, "expected a number, a name, 'none', 'max(...)', 'min(...)' or '('");
    if (is("(", 1)) {
      e.op = Expr::Op::call;
      e.name = name();
      expect("(");
      do {
        Expr a;
        a.pos = peek().pos;
        a.op = Expr::Op::name;
        a.name = name("a variable");
        e.args.push_back(std::move(a));
      } while (accept(","));
      expect(")");
      set_height(e, e.pos);
      return e;
    }
    e.op = Expr::Op::name;
    e.name = name();
    if (accept(".")) {
      e.op = Expr::Op::attribute;
      e.member = name("a port or attribute");
      if (accept("[")) {
        e.op = Expr::Op::port;
        e.index = index(false);
        expect("]");
      }
    }
    return e;
  }

  std::vector<Token> tokens_;
  std::string file_;
  std::size_t pos_ = 0;
  int nesting_ = 0;
};

}  // namespace

std::vector<ast::Rule> parse_rules(const std::string& text, const std::string& file) {
  return Parser(tokenize(text, file), file).rules();
}

}  // namespace loom::engine
