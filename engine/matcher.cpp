#include "engine/matcher.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "engine/rule_arithmetic.hpp"

namespace loom::engine {

namespace {

/// The slot a raw index names: wrapped on cyclic ports, -1 when out of range.
int slot_of(const PortSpec& p, long raw) {
  if (p.order == PortOrder::cyclic) return static_cast<int>(((raw % p.arity) + p.arity) % p.arity);
  return raw >= 0 && raw < p.arity ? static_cast<int>(raw) : -1;
}

}  // namespace

std::int64_t Matcher::evaluate(const CExpr& e, const Match& m) const {
  using Op = CExpr::Op;
  auto arg = [&](std::size_t i) { return evaluate(e.args[i], m); };
  switch (e.op) {
    case Op::literal: return e.value;
    case Op::none: return no_element;
    case Op::element: return m.elements[e.var];
    case Op::index: return m.indices[e.index_var] + e.offset;
    case Op::attribute: {
      Id el = m.elements[e.var];
      return el == no_element ? 0 : g_.get(el, e.attr);
    }
    case Op::port: {
      Id el = m.elements[e.var];
      if (el == no_element) return no_element;
      const PortSpec& p = g_.schema().port(e.port);
      int s = slot_of(p, (e.index_var >= 0 ? m.indices[e.index_var] : 0) + e.offset);
      return s < 0 ? no_element : g_.at(el, e.port, static_cast<unsigned>(s));
    }
    case Op::measure: return measure(e, m);
    default: return apply_operator(*m.rule, e, arg);
  }
}

std::int64_t Matcher::measure(const CExpr& e, const Match& m) const {
  const Rule& rule = *m.rule;
  const RewriteOp& call = rule.measures[static_cast<std::size_t>(e.value)];
  if (rule.measure_fns.size() != rule.measures.size())
    throw RuleError(rule.file, call.pos,
                    fmt::format("rule '{}': measure '{}' can only be evaluated by an engine that has the domain's measures",
                                rule.name, call.action));
  std::array<Id, max_measure_args> args{};
  for (std::size_t i = 0; i < call.args.size(); ++i) {
    args[i] = m.elements[call.args[i]];
    // A rewrite may have deleted it (`delete x`, then a statement measuring x).
    if (args[i] == no_element || !g_.alive(args[i]))
      throw RuleError(rule.file, call.pos,
                      fmt::format("rule '{}': measure '{}' reads '{}', which is no longer in the graph", rule.name,
                                  call.action, rule.vars[static_cast<std::size_t>(call.args[i])].name));
  }
  try {
    return rule.measure_fns[static_cast<std::size_t>(e.value)](g_, std::span<const Id>(args.data(), call.args.size()));
  } catch (const RuleError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& x) {
    throw RuleError(rule.file, call.pos, fmt::format("rule '{}': measure '{}' failed: {}", rule.name, call.action, x.what()));
  }
}

/// A backtracking walk of a plan. `done` is called at each complete match and
/// returns true to stop; step() returns true once stopped.
struct Matcher::Search {
  const Matcher& matcher;
  const Graph& g;
  const Rule& rule;
  Match& m;

  using Done = std::function<bool()>;

  bool bind(int v, Id e) {
    const Variable& var = rule.vars[v];
    if (e == no_element || !g.alive(e) || g.kind(e) != var.kind) return false;
    for (int u : rule.distinct[v])
      if (m.elements[u] == e) return false;
    m.elements[v] = e;
    return true;
  }

  /// Calls `each(slot)` for every slot the index may name, binding an unbound
  /// index variable for the duration; returns true once stopped.
  template <class Each>
  bool slots(const PortSpec& p, const CIndex& ix, Each&& each) {
    if (ix.kind == CIndex::Kind::fixed) return each(ix.offset);
    if (ix.kind == CIndex::Kind::any) {
      for (int s = 0; s < p.arity; ++s)
        if (each(s)) return true;
      return false;
    }
    int& iv = m.indices[ix.variable];
    if (iv != -1) {
      int s = slot_of(p, iv + ix.offset);
      return s >= 0 && each(s);
    }
    for (int s = 0; s < p.arity; ++s) {
      iv = s - ix.offset;
      if (p.order == PortOrder::cyclic) iv = slot_of(p, iv);
      bool stop = each(s);
      iv = -1;
      if (stop) return true;
    }
    return false;
  }

  /// Whether slot `s` may be named by the index (binding it if unbound).
  bool index_accepts(const PortSpec& p, const CIndex& ix, int s, bool& bound_here) {
    bound_here = false;
    if (ix.kind == CIndex::Kind::any) return true;
    if (ix.kind == CIndex::Kind::fixed) return s == ix.offset;
    int& iv = m.indices[ix.variable];
    if (iv != -1) return slot_of(p, iv + ix.offset) == s;
    iv = p.order == PortOrder::cyclic ? slot_of(p, s - ix.offset) : s - ix.offset;
    bound_here = true;
    return true;
  }

  bool step(const std::vector<PlanOp>& ops, std::size_t k, const Done& done) {
    if (k == ops.size()) return done();
    const PlanOp& op = ops[k];
    switch (op.kind) {
      case PlanOp::Kind::lookup: {
        const PortSpec& p = g.schema().port(op.port);
        Id owner = m.elements[op.owner];
        return slots(p, op.index, [&](int s) {
          if (!bind(op.target, g.at(owner, op.port, static_cast<unsigned>(s)))) return false;
          bool stop = step(ops, k + 1, done);
          m.elements[op.target] = no_element;
          return stop;
        });
      }
      case PlanOp::Kind::incoming: {
        const PortSpec& p = g.schema().port(op.port);
        for (SlotId s : g.incoming(m.elements[op.target])) {
          if (g.slot_port(s) != op.port) continue;
          bool bound_here = false;
          if (!index_accepts(p, op.index, static_cast<int>(g.slot_index(s)), bound_here)) continue;
          bool stop = false;
          if (bind(op.owner, g.slot_owner(s))) {
            stop = step(ops, k + 1, done);
            m.elements[op.owner] = no_element;
          }
          if (bound_here) m.indices[op.index.variable] = -1;
          if (stop) return true;
        }
        return false;
      }
      case PlanOp::Kind::scan: {
        for (Id e : g.members(rule.vars[op.target].kind)) {
          if (!bind(op.target, e)) continue;
          bool stop = step(ops, k + 1, done);
          m.elements[op.target] = no_element;
          if (stop) return true;
        }
        return false;
      }
      case PlanOp::Kind::check: {
        const PortSpec& p = g.schema().port(op.port);
        Id owner = m.elements[op.owner];
        Id want = op.target < 0 ? no_element : m.elements[op.target];
        return slots(p, op.index, [&](int s) {
          return g.at(owner, op.port, static_cast<unsigned>(s)) == want && step(ops, k + 1, done);
        });
      }
      case PlanOp::Kind::filter:
        return matcher.evaluate(*op.expr, m) != 0 && step(ops, k + 1, done);
      case PlanOp::Kind::count: {
        std::int64_t counted = 0;
        const Id target = m.elements[op.target];
        const unsigned arity = g.schema().port(op.port).arity;
        for (SlotId in : g.incoming(target)) {
          if (g.slot_port(in) != op.port) continue;
          Id o = g.slot_owner(in);
          // Distinct owners: an owner holding the target in several slots is
          // counted at the first of them only (the ring can be long: a scan of
          // it per entry made this quadratic).
          const unsigned here = g.slot_index(in);
          bool again = false;
          for (unsigned before = 0; before < here && before < arity && !again; ++before)
            again = g.at(o, op.port, before) == target;
          if (again) continue;
          if (op.count_empty_slot >= 0) {
            counted += g.at(o, op.count_empty_port, static_cast<unsigned>(op.count_empty_slot)) == no_element;
            continue;
          }
          m.elements[op.owner] = o;
          counted += !op.expr || matcher.evaluate(*op.expr, m) != 0;
          m.elements[op.owner] = no_element;
        }
        return compare(op.comparison, counted, op.bound) && step(ops, k + 1, done);
      }
      case PlanOp::Kind::negative: {
        bool exists = step(rule.negatives[op.nac].ops, 0, [] { return true; });
        return !exists && step(ops, k + 1, done);
      }
    }
    return false;
  }
};

void Matcher::each_at(const Rule& rule, Id anchor, const std::function<bool(const Match&)>& visit) const {
  Match& m = scratch_;  // reused: no allocation per search
  m.rule = &rule;
  m.elements.assign(rule.vars.size(), no_element);
  m.indices.assign(rule.index_vars.size(), -1);
  Search search{*this, g_, rule, m};
  if (!search.bind(rule.anchor, anchor)) return;
  search.step(rule.plan, 0, [&] { return !visit(m); });
}

bool Matcher::first_at(const Rule& rule, Id anchor, Match& out) const {
  bool found = false;
  each_at(rule, anchor, [&](const Match& m) {
    out = m;
    found = true;
    return false;
  });
  return found;
}

void Matcher::each(const Rule& rule, const std::function<bool(const Match&)>& visit) const {
  bool go = true;
  for (Id a : g_.members(rule.vars[rule.anchor].kind)) {
    each_at(rule, a, [&](const Match& m) { return go = visit(m); });
    if (!go) return;
  }
}

}  // namespace loom::engine
