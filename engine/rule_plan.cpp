#include "engine/rule_plan.hpp"

#include <algorithm>
#include <functional>

namespace loom::engine {

/// A condition `x.port[i] == y` or `x.port[i] == none` is a plain slot check,
/// cheaper than evaluating an expression; anything else stays a filter.
PlanOp filter_op(const CExpr& e) {
  PlanOp op;
  if (e.op == CExpr::Op::eq && e.args.size() == 2) {
    const CExpr *slot = &e.args[0], *other = &e.args[1];
    if (other->op == CExpr::Op::port) std::swap(slot, other);
    if (slot->op == CExpr::Op::port && (other->op == CExpr::Op::none || other->op == CExpr::Op::element)) {
      op.kind = PlanOp::Kind::check;
      op.owner = slot->var;
      op.port = slot->port;
      op.index.kind = slot->index_var >= 0 ? CIndex::Kind::variable : CIndex::Kind::fixed;
      op.index.variable = slot->index_var;
      op.index.offset = slot->offset;
      op.target = other->op == CExpr::Op::none ? -1 : other->var;
      return op;
    }
  }
  op.kind = PlanOp::Kind::filter;
  op.expr = e;
  return op;
}

namespace {
PlanOp edge_op(PlanOp::Kind kind, const PlanIncidence& inc) {
  PlanOp op;
  op.kind = kind;
  op.owner = inc.owner;
  op.target = inc.target;
  op.port = inc.port;
  op.index = inc.index;
  return op;
}

}  // namespace

bool PlanBuilder::all_bound(const std::vector<int>& vars, const std::vector<int>& ivars) const {
  return std::all_of(vars.begin(), vars.end(), [&](int v) { return bound[v]; }) &&
         std::all_of(ivars.begin(), ivars.end(), [&](int v) { return index_bound[v]; });
}

void PlanBuilder::bind_index(const CIndex& ix) {
  if (ix.kind == CIndex::Kind::variable) index_bound[ix.variable] = true;
}

/// Greedy search plan: emit every check that is ready, then extend by the
/// cheapest incidence (an out-slot lookup before an incoming scan), else scan.
bool PlanBuilder::build(std::vector<PlanOp>& ops, std::vector<PlanIncidence>& incs, std::vector<PlanFilter>& filters,
                      std::vector<PlanCount>& counts, int scope) {
  auto emit_ready = [&] {
    for (bool progress = true; progress;) {
      progress = false;
      for (auto& inc : incs)
        if (!inc.used && bound[inc.owner] && (inc.target < 0 || bound[inc.target])) {
          ops.push_back(edge_op(PlanOp::Kind::check, inc));
          bind_index(inc.index);
          inc.used = progress = true;
        }
      for (auto& f : filters)
        if (!f.used && all_bound(f.vars, f.index_vars)) {
          ops.push_back(filter_op(f.expr));
          f.used = progress = true;
        }
      for (auto& c : counts)
        if (!c.used && all_bound(c.vars, {})) {
          ops.push_back(c.op);
          c.used = progress = true;
        }
    }
  };
  auto in_scope = [&](int v) { return rule.vars[v].nac == scope; };
  emit_ready();
  for (;;) {
    int best = -1, best_cost = 1 << 30;
    for (std::size_t i = 0; i < incs.size(); ++i) {
      const PlanIncidence& inc = incs[i];
      if (inc.used || inc.target < 0) continue;
      int cost;
      if (bound[inc.owner] && !bound[inc.target]) {
        bool index_known = inc.index.kind == CIndex::Kind::fixed ||
                           (inc.index.kind == CIndex::Kind::variable && index_bound[inc.index.variable]);
        cost = index_known ? 1 : schema.port(inc.port).arity;
      } else if (!bound[inc.owner] && bound[inc.target]) {
        cost = 8;
      } else {
        continue;
      }
      if (cost < best_cost) best = static_cast<int>(i), best_cost = cost;
    }
    if (best >= 0) {
      PlanIncidence& inc = incs[best];
      PlanOp op = edge_op(bound[inc.owner] ? PlanOp::Kind::lookup : PlanOp::Kind::incoming, inc);
      int child = op.kind == PlanOp::Kind::lookup ? inc.target : inc.owner;
      int parent = op.kind == PlanOp::Kind::lookup ? inc.owner : inc.target;
      rule.vars[child].parent = parent;
      rule.vars[child].via = op.kind == PlanOp::Kind::lookup ? Variable::Via::lookup : Variable::Via::incoming;
      rule.vars[child].via_port = inc.port;
      bound[child] = true;
      bind_index(inc.index);
      inc.used = true;
      ops.push_back(op);
      emit_ready();
      continue;
    }
    int unbound = -1;
    for (std::size_t v = 0; v < rule.vars.size() && unbound < 0; ++v)
      if (in_scope(static_cast<int>(v)) && !bound[v] && !rule.vars[v].created) unbound = static_cast<int>(v);
    if (unbound < 0) break;
    PlanOp op;
    op.kind = PlanOp::Kind::scan;
    op.target = unbound;
    rule.vars[unbound].via = Variable::Via::scan;
    rule.global = true;
    bound[unbound] = true;
    ops.push_back(op);
    emit_ready();
  }
  return std::all_of(filters.begin(), filters.end(), [](const PlanFilter& f) { return f.used; });
}

void record_distinctness(Rule& rule) {
  rule.distinct.assign(rule.vars.size(), {});
  for (std::size_t v = 0; v < rule.vars.size(); ++v)
    for (std::size_t u = 0; u < rule.vars.size(); ++u) {
      const Variable &a = rule.vars[v], &b = rule.vars[u];
      if (u == v || a.kind != b.kind || a.created || b.created || a.nac == -2 || b.nac == -2) continue;
      bool same_scope = a.nac == b.nac || a.nac == -1 || b.nac == -1;
      if (same_scope && !rule.may_be_equal[u][v]) rule.distinct[v].push_back(static_cast<int>(u));
    }
}

void record_sensitivity(Rule& rule) {
  auto note = [](std::vector<std::uint16_t>& v, std::uint16_t x) {
    if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
  };
  std::vector<const std::vector<PlanOp>*> plans{&rule.plan};
  for (const auto& n : rule.negatives) plans.push_back(&n.ops);
  std::function<void(const CExpr&)> reads = [&](const CExpr& e) {
    if (e.op == CExpr::Op::attribute) note(rule.vars[e.var].attrs, e.attr);
    if (e.op == CExpr::Op::port) note(rule.vars[e.var].out_ports, e.port);
    for (const auto& a : e.args) reads(a);
  };
  for (const auto* ops : plans)
    for (const PlanOp& op : *ops) {
      if (op.kind == PlanOp::Kind::lookup || op.kind == PlanOp::Kind::incoming || op.kind == PlanOp::Kind::check)
        note(rule.vars[op.owner].out_ports, op.port);
      if (op.kind == PlanOp::Kind::incoming && rule.vars[op.owner].nac >= 0)
        note(rule.vars[op.target].negative_in_ports, op.port);
      if (op.kind == PlanOp::Kind::count) note(rule.vars[op.target].in_ports, op.port);
      if (op.expr) reads(*op.expr);
    }
  if (rule.order) reads(*rule.order);
  for (Variable& v : rule.vars)
    std::erase_if(v.negative_in_ports, [&](PortId p) { return std::count(v.in_ports.begin(), v.in_ports.end(), p) > 0; });
}

}  // namespace loom::engine
