// `loom rules explain`: a compiled rule's search plan, one operation a line.
#include <sstream>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"

namespace loom::engine {

namespace {

std::string index_text(const Rule& r, const CIndex& ix) {
  switch (ix.kind) {
    case CIndex::Kind::fixed: return std::to_string(ix.offset);
    case CIndex::Kind::any: return "_";
    case CIndex::Kind::variable:
      return ix.offset == 0 ? r.index_vars[ix.variable]
                            : fmt::format("{}{:+}", r.index_vars[ix.variable], ix.offset);
  }
  return "?";
}

std::string expr_text(const Rule& r, const Schema& s, const CExpr& e) {
  using Op = CExpr::Op;
  auto arg = [&](std::size_t i) { return expr_text(r, s, e.args[i]); };
  auto index = [&] {
    if (e.index_var < 0) return std::to_string(e.offset);
    return e.offset == 0 ? r.index_vars[e.index_var] : fmt::format("{}{:+}", r.index_vars[e.index_var], e.offset);
  };
  static const std::pair<Op, const char*> binary[] = {{Op::add, "+"}, {Op::sub, "-"}, {Op::mul, "*"},  {Op::eq, "=="},
                                                      {Op::ne, "!="}, {Op::lt, "<"},  {Op::le, "<="}, {Op::gt, ">"},
                                                      {Op::ge, ">="}, {Op::both, "and"}, {Op::either, "or"}};
  for (auto [op, text] : binary)
    if (e.op == op) return fmt::format("({} {} {})", arg(0), text, arg(1));
  switch (e.op) {
    case Op::literal: return std::to_string(e.value);
    case Op::none: return "none";
    case Op::element: return r.vars[e.var].name;
    case Op::index: return r.index_vars[e.index_var];
    case Op::attribute: return fmt::format("{}.{}", r.vars[e.var].name, s.attribute(e.attr).name);
    case Op::port: return fmt::format("{}.{}[{}]", r.vars[e.var].name, s.port(e.port).name, index());
    case Op::neg: return "-" + arg(0);
    case Op::negate: return "not " + arg(0);
    case Op::max:
    case Op::min:
    case Op::measure: {
      std::string t = e.op == Op::max ? "max(" : e.op == Op::min ? "min(" : r.measures[static_cast<std::size_t>(e.value)].action + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i) t += (i ? ", " : "") + arg(i);
      return t + ")";
    }
    default: return "?";
  }
}

void explain_ops(std::ostringstream& out, const Rule& r, const Schema& s, const std::vector<PlanOp>& ops, int depth) {
  std::string pad(2 * static_cast<std::size_t>(depth), ' ');
  auto var = [&](int v) { return v < 0 ? std::string("none") : r.vars[v].name; };
  auto slot = [&](const PlanOp& op) {
    return fmt::format("{}.{}[{}]", var(op.owner), s.port(op.port).name, index_text(r, op.index));
  };
  int n = 0;
  for (const PlanOp& op : ops) {
    out << pad << fmt::format("{:2}. ", ++n);
    switch (op.kind) {
      case PlanOp::Kind::lookup: out << fmt::format("lookup    {} := {}", var(op.target), slot(op)); break;
      case PlanOp::Kind::incoming:
        out << fmt::format("incoming  {} := a {} with {} == {}", var(op.owner), s.kind(r.vars[op.owner].kind).name,
                           slot(op), var(op.target));
        break;
      case PlanOp::Kind::scan:
        out << fmt::format("scan      {} := every {} (unanchored)", var(op.target), s.kind(r.vars[op.target].kind).name);
        break;
      case PlanOp::Kind::check: out << fmt::format("check     {} == {}", slot(op), var(op.target)); break;
      case PlanOp::Kind::filter: out << "filter    " << expr_text(r, s, *op.expr); break;
      case PlanOp::Kind::count: {
        static const char* cmp[] = {"==", "!=", "<", "<=", ">", ">="};
        int c = static_cast<int>(op.comparison) - static_cast<int>(CExpr::Op::eq);
        out << fmt::format("count     {}s with .{} -> {}{} {} {}", s.kind(op.count_kind).name, s.port(op.port).name,
                           var(op.target),
                           op.expr ? " where " + expr_text(r, s, *op.expr)
                           : op.count_empty_slot >= 0
                               ? fmt::format(" where self.{}[{}] == none", s.port(op.count_empty_port).name, op.count_empty_slot)
                               : "",
                           cmp[c], op.bound);
        break;
      }
      case PlanOp::Kind::negative:
        out << "negative  no match of:\n";
        explain_ops(out, r, s, r.negatives[op.nac].ops, depth + 2);
        continue;
    }
    out << "\n";
  }
}

}  // namespace

std::string explain(const Rule& rule, const Schema& schema) {
  std::ostringstream out;
  out << fmt::format("rule {} (priority {}, {}) anchored at {}: {}\n", rule.name, rule.priority, rule.file,
                     rule.vars[rule.anchor].name, schema.kind(rule.vars[rule.anchor].kind).name);
  explain_ops(out, rule, schema, rule.plan, 1);
  if (rule.global) out << "  note: part of the pattern is not connected to the anchor; every step rescans it\n";
  return out.str();
}

}  // namespace loom::engine
