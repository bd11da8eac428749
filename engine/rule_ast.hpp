#pragma once
// The syntax tree of a rule file, as parsed (docs/rules.md has the grammar).
// Names are resolved against a Schema later, by the compiler.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace loom::engine::ast {

struct Pos {
  int line = 0, column = 0;
};

/// A slot index: `3`, `i`, `i+2`, `i-1`, or `_` (any slot).
struct Index {
  enum class Kind { fixed, variable, any } kind = Kind::fixed;
  std::string variable;
  int offset = 0;  ///< the literal, or the offset added to the variable
};

struct Expr {
  enum class Op {
    literal,   ///< value
    none,      ///< the empty element
    name,      ///< an element variable, an index variable, or an attribute of `self`
    attribute, ///< name.member
    port,      ///< name.member[index]
    call,      ///< name(a, b, ...): a measure the domain registered; args are names
    add, sub, mul, neg, max, min,
    eq, ne, lt, le, gt, ge, both, either, negate
  };
  Op op = Op::literal;
  std::int64_t value = 0;
  std::string name, member;
  Index index;
  std::vector<Expr> args;
  Pos pos;
  int height = 1;  ///< nodes on the longest path down to a leaf (the parser bounds it)
};

/// `a, b: kind where EXPR`
struct Declaration {
  std::vector<std::string> names;
  std::string kind;
  std::optional<Expr> where;
  Pos pos;
};

/// `x.port[index] == y` (or `== none`)
struct Incidence {
  std::string owner, port;
  Index index;
  bool indexed = false;  ///< written with [...]
  std::optional<std::string> target;  ///< nullopt: the slot must be empty
  Pos pos;
};

/// `count(kind.port -> target where EXPR) OP n`
struct Count {
  std::string kind, port, target;
  std::optional<Expr> where;
  Expr::Op comparison = Expr::Op::eq;
  std::int64_t bound = 0;
  Pos pos;
};

struct Statement {
  enum class Op { create, set_port, set_port_list, set_attribute, remove, merge, identify, call };
  Op op = Op::create;
  std::vector<std::string> names;  ///< create: new names; call: args
  std::string kind;                ///< create: kind; call: action name; identify: prefer attribute
  std::string target, member;      ///< set_*: element variable and port/attribute
  Index index;
  std::vector<Expr> values;        ///< set_port: 1; set_port_list: arity; set_attribute: 1;
                                   ///< merge: {from, into}; identify: {a, b}
  Pos pos;
};

struct Pattern {
  std::vector<Declaration> declarations;
  std::vector<Incidence> incidences;
  std::vector<Expr> conditions;          ///< `if EXPR`
  std::vector<Count> counts;
  std::vector<std::vector<std::string>> may_be_equal;  ///< `hom(a, b, ...)`
  std::vector<Statement> tests;          ///< `test NAME(a, b)`: calls (kind: name, names: args)
  std::vector<Pattern> negatives;        ///< `not { ... }`
  Pos pos;
};

struct Rule {
  std::string name, file;
  std::int64_t priority = 0;
  std::optional<Expr> order;
  std::optional<std::string> anchor;
  Pattern pattern;
  std::vector<Statement> rewrite;
  Pos pos;
};

}  // namespace loom::engine::ast
