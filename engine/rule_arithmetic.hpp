#pragma once
// The operators of rule expressions, shared by the matcher (at run time) and the
// compiler (which folds operators on constants at load). Arithmetic is checked:
// a result that does not fit in 64 bits is a RuleError at the operator, naming
// the rule, never a silent wrap (signed overflow is undefined behaviour).
#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "engine/rule.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

[[noreturn, gnu::cold]] inline void fail_overflow(const Rule& rule, const CExpr& e, std::int64_t a,
                                                  std::int64_t b) {
  const char* symbol = e.op == CExpr::Op::add ? "+" : e.op == CExpr::Op::mul ? "*" : "-";
  std::string operation = e.op == CExpr::Op::neg ? fmt::format("-({})", a) : fmt::format("{} {} {}", a, symbol, b);
  throw RuleError(rule.file, e.pos,
                  fmt::format("rule '{}': {} overflows 64-bit integers", rule.name, operation));
}

inline bool compare(CExpr::Op op, std::int64_t a, std::int64_t b) {
  switch (op) {
    case CExpr::Op::eq: return a == b;
    case CExpr::Op::ne: return a != b;
    case CExpr::Op::lt: return a < b;
    case CExpr::Op::le: return a <= b;
    case CExpr::Op::gt: return a > b;
    default: return a >= b;
  }
}

/// Applies the operator `e.op` (not a leaf) to the values `arg(i)` of its
/// operands; `and` and `or` evaluate their second operand only when needed.
template <class Arg>
std::int64_t apply_operator(const Rule& rule, const CExpr& e, Arg&& arg) {
  using Op = CExpr::Op;
  std::int64_t result = 0;
  switch (e.op) {
    case Op::add: {
      std::int64_t a = arg(0), b = arg(1);
      if (__builtin_add_overflow(a, b, &result)) fail_overflow(rule, e, a, b);
      return result;
    }
    case Op::sub: {
      std::int64_t a = arg(0), b = arg(1);
      if (__builtin_sub_overflow(a, b, &result)) fail_overflow(rule, e, a, b);
      return result;
    }
    case Op::mul: {
      std::int64_t a = arg(0), b = arg(1);
      if (__builtin_mul_overflow(a, b, &result)) fail_overflow(rule, e, a, b);
      return result;
    }
    case Op::neg: {
      std::int64_t a = arg(0);
      if (__builtin_sub_overflow(std::int64_t{0}, a, &result)) fail_overflow(rule, e, a, 0);
      return result;
    }
    case Op::max:
    case Op::min: {
      std::int64_t v = arg(0);
      for (std::size_t i = 1; i < e.args.size(); ++i) v = e.op == Op::max ? std::max(v, arg(i)) : std::min(v, arg(i));
      return v;
    }
    case Op::both: return arg(0) && arg(1);
    case Op::either: return arg(0) || arg(1);
    case Op::negate: return !arg(0);
    default: return compare(e.op, arg(0), arg(1));
  }
}

}  // namespace loom::engine
