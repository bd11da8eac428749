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
      case PlanOp::Kind::filter: out << "filter    a condition"; break;
      case PlanOp::Kind::count:
        out << fmt::format("count     {}s with .{} -> {} (compared with {})", s.kind(op.count_kind).name,
                           s.port(op.port).name, var(op.target), op.bound);
        break;
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
