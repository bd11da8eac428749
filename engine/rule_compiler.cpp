#include "engine/rule_compiler.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "engine/rule_parser.hpp"

namespace loom::engine {

void CExpr::collect_vars(std::vector<int>& out) const {
  if (var >= 0) out.push_back(var);
  for (const CExpr& a : args) a.collect_vars(out);
}

namespace {

void collect_index_vars(const CExpr& e, std::vector<int>& out) {
  if (e.index_var >= 0) out.push_back(e.index_var);
  for (const CExpr& a : e.args) collect_index_vars(a, out);
}

struct Incidence {
  int owner, target;
  PortId port;
  CIndex index;
  bool used = false;
};

struct Filter {
  CExpr expr;
  std::vector<int> vars, index_vars;
  bool used = false;
};

struct PendingCount {
  PlanOp op;
  std::vector<int> vars;
  bool used = false;
};

class Compiler {
public:
  Compiler(const ast::Rule& rule, const Schema& schema) : ast_(rule), schema_(schema) {}

  Rule run() {
    r_.name = ast_.name;
    r_.file = ast_.file;
    r_.priority = ast_.priority;
    for (const auto& d : ast_.pattern.declarations) declare(d, -1);
    r_.pattern_vars = static_cast<int>(r_.vars.size());
    for (std::size_t k = 0; k < ast_.pattern.negatives.size(); ++k) {
      const ast::Pattern& nac = ast_.pattern.negatives[k];
      if (!nac.negatives.empty()) fail(nac.negatives.front().pos, "negative patterns cannot be nested");
      if (!nac.counts.empty()) fail(nac.counts.front().pos, "count(...) is only allowed in the main pattern");
      for (const auto& d : nac.declarations) declare(d, static_cast<int>(k));
    }
    for (const auto& s : ast_.rewrite)
      if (s.op == ast::Statement::Op::create)
        for (const auto& n : s.names) add_var(n, kind(s.kind, s.pos), -3, true, s.pos);
    if (r_.pattern_vars == 0) fail(ast_.pattern.pos, "the pattern declares no variable");

    r_.anchor = ast_.anchor ? var(*ast_.anchor, ast_.pos, -1) : 0;
    if (r_.anchor >= r_.pattern_vars) fail(ast_.pos, "the anchor must be a variable of the main pattern");
    r_.may_be_equal.assign(r_.vars.size() + ast_.pattern.counts.size(), std::vector<bool>(r_.vars.size() + ast_.pattern.counts.size(), false));
    auto allow = [&](const ast::Pattern& p, int scope) {
      for (const auto& group : p.may_be_equal)
        for (const auto& a : group)
          for (const auto& b : group) r_.may_be_equal[var(a, p.pos, scope)][var(b, p.pos, scope)] = true;
    };
    allow(ast_.pattern, -1);
    for (std::size_t k = 0; k < ast_.pattern.negatives.size(); ++k) allow(ast_.pattern.negatives[k], static_cast<int>(k));

    build_main_plan();
    for (std::size_t k = 0; k < ast_.pattern.negatives.size(); ++k) build_negative(static_cast<int>(k));
    if (ast_.order) r_.order = expr(*ast_.order, -1, -1, false);
    for (const auto& s : ast_.rewrite) statement(s);
    record_sensitivity();
    record_distinctness();
    return std::move(r_);
  }

private:
  [[noreturn]] void fail(ast::Pos pos, const std::string& what) const { throw RuleError(ast_.file, pos, what); }

  KindId kind(const std::string& name, ast::Pos pos) const {
    if (auto k = schema_.find_kind(name)) return *k;
    std::string known;
    for (std::size_t i = 0; i < schema_.kind_count(); ++i)
      known += (i ? ", " : "") + schema_.kind(static_cast<KindId>(i)).name;
    fail(pos, fmt::format("expected a kind ({}), found '{}'", known, name));
  }

  int add_var(const std::string& name, KindId k, int nac, bool created, ast::Pos pos) {
    for (const auto& v : r_.vars)
      if (v.name == name) fail(pos, fmt::format("variable '{}' is declared twice", name));
    Variable v;
    v.name = name;
    v.kind = k;
    v.nac = nac;
    v.created = created;
    r_.vars.push_back(std::move(v));
    return static_cast<int>(r_.vars.size() - 1);
  }

  void declare(const ast::Declaration& d, int nac) {
    for (const auto& n : d.names) {
      int v = add_var(n, kind(d.kind, d.pos), nac, false, d.pos);
      if (d.where) where_.push_back({v, &*d.where});
    }
  }

  /// A variable visible in `scope`: -1 main pattern, k >= 0 negative k (and
  /// the main pattern), -3 the rewrite (main pattern and created variables).
  int var(const std::string& name, ast::Pos pos, int scope) const {
    for (std::size_t i = 0; i < r_.vars.size(); ++i) {
      const Variable& v = r_.vars[i];
      if (v.name != name) continue;
      bool visible = v.nac == -1 || v.nac == scope || (scope == -3 && v.created);
      if (!visible) fail(pos, fmt::format("variable '{}' is not visible here", name));
      if (v.created && created_.count(static_cast<int>(i)) == 0)
        fail(pos, fmt::format("'{}' is used before its 'new'", name));
      return static_cast<int>(i);
    }
    fail(pos, fmt::format("unknown variable '{}'", name));
  }

  int index_var(const std::string& name, bool may_create) {
    for (std::size_t i = 0; i < r_.index_vars.size(); ++i)
      if (r_.index_vars[i] == name) return static_cast<int>(i);
    if (!may_create) return -1;
    r_.index_vars.push_back(name);
    return static_cast<int>(r_.index_vars.size() - 1);
  }

  PortId port(int v, const std::string& name, ast::Pos pos) const {
    if (auto p = schema_.find_port(r_.vars[v].kind, name)) return *p;
    fail(pos, fmt::format("{} has no port '{}'", article(schema_.kind(r_.vars[v].kind).name), name));
  }

  CIndex index(const ast::Index& ix, PortId p, bool explicit_index, ast::Pos pos, bool pattern) {
    const PortSpec& ps = schema_.port(p);
    CIndex c;
    if (!explicit_index) {
      if (ps.arity != 1) fail(pos, fmt::format("port '{}' has {} slots: give an index, e.g. {}[0] or {}[_]", ps.name, ps.arity, ps.name, ps.name));
      return c;
    }
    switch (ix.kind) {
      case ast::Index::Kind::fixed:
        if (ix.offset < 0 || ix.offset >= ps.arity) fail(pos, fmt::format("index {} is out of range for port '{}' ({} slots)", ix.offset, ps.name, ps.arity));
        c.offset = ix.offset;
        return c;
      case ast::Index::Kind::any: c.kind = CIndex::Kind::any; return c;
      case ast::Index::Kind::variable:
        c.kind = CIndex::Kind::variable;
        c.variable = index_var(ix.variable, pattern);
        if (c.variable < 0) fail(pos, fmt::format("unknown index '{}' (indices are bound in the match)", ix.variable));
        c.offset = ix.offset;
        return c;
    }
    return c;
  }

  CExpr expr(const ast::Expr& e, int self, int scope, bool pattern) {
    CExpr c;
    using A = ast::Expr::Op;
    using C = CExpr::Op;
    static const std::map<A, C> ops = {{A::add, C::add}, {A::sub, C::sub}, {A::mul, C::mul}, {A::neg, C::neg},
                                       {A::max, C::max}, {A::min, C::min}, {A::eq, C::eq},   {A::ne, C::ne},
                                       {A::lt, C::lt},   {A::le, C::le},   {A::gt, C::gt},   {A::ge, C::ge},
                                       {A::both, C::both}, {A::either, C::either}, {A::negate, C::negate}};
    switch (e.op) {
      case A::literal: c.value = e.value; return c;
      case A::none: c.op = C::none; return c;
      case A::name: {
        for (std::size_t i = 0; i < r_.vars.size(); ++i)
          if (r_.vars[i].name == e.name) {
            c.op = C::element;
            c.var = var(e.name, e.pos, scope);
            return c;
          }
        if (int iv = index_var(e.name, false); iv >= 0) {
          c.op = C::index;
          c.index_var = iv;
          return c;
        }
        if (self >= 0)
          if (auto a = schema_.find_attribute(r_.vars[self].kind, e.name)) {
            c.op = C::attribute;
            c.var = self;
            c.attr = *a;
            return c;
          }
        fail(e.pos, fmt::format("unknown name '{}'", e.name));
      }
      case A::attribute:
      case A::port: {
        c.var = e.name == "self" && self >= 0 ? self : var(e.name, e.pos, scope);
        KindId k = r_.vars[c.var].kind;
        if (e.op == A::attribute)
          if (auto a = schema_.find_attribute(k, e.member)) {
            c.op = C::attribute;
            c.attr = *a;
            return c;
          }
        auto p = schema_.find_port(k, e.member);
        if (!p) fail(e.pos, fmt::format("{} has no attribute or port '{}'", article(schema_.kind(k).name), e.member));
        c.op = C::port;
        c.port = *p;
        CIndex ix = index(e.index, *p, e.op == A::port, e.pos, pattern);
        if (ix.kind == CIndex::Kind::any) fail(e.pos, "'_' is not allowed in an expression");
        c.index_var = ix.variable;
        c.offset = ix.offset;
        return c;
      }
      default: {
        c.op = ops.at(e.op);
        for (const auto& a : e.args) c.args.push_back(expr(a, self, scope, pattern));
        return c;
      }
    }
  }

  Incidence incidence(const ast::Incidence& inc, int scope) {
    Incidence c;
    c.owner = var(inc.owner, inc.pos, scope);
    c.port = port(c.owner, inc.port, inc.pos);
    c.index = index(inc.index, c.port, inc.indexed, inc.pos, true);
    c.target = inc.target ? var(*inc.target, inc.pos, scope) : -1;
    if (c.target >= 0 && r_.vars[c.target].kind != schema_.port(c.port).target)
      fail(inc.pos, fmt::format("port '{}' points at {}, but '{}' is {}", inc.port,
                                article(schema_.kind(schema_.port(c.port).target).name), *inc.target,
                                article(schema_.kind(r_.vars[c.target].kind).name)));
    return c;
  }
  Filter filter(CExpr e) {
    Filter f;
    e.collect_vars(f.vars);
    collect_index_vars(e, f.index_vars);
    f.expr = std::move(e);
    return f;
  }

  void build_main_plan() {
    const ast::Pattern& p = ast_.pattern;
    std::vector<Incidence> incs;
    for (const auto& inc : p.incidences) incs.push_back(incidence(inc, -1));
    std::vector<Filter> filters;
    for (auto& [v, w] : where_)
      if (r_.vars[v].nac == -1) filters.push_back(filter(expr(*w, v, -1, true)));
    for (const auto& c : p.conditions) filters.push_back(filter(expr(c, -1, -1, true)));
    std::vector<PendingCount> counts;
    for (const auto& c : p.counts) counts.push_back(count(c));
    bound_.assign(r_.vars.size(), false);
    ibound_.assign(r_.index_vars.size() + 64, false);
    bound_[r_.anchor] = true;
    r_.vars[r_.anchor].via = Variable::Via::anchor;
    plan(r_.plan, incs, filters, counts, -1);
    for (std::size_t k = 0; k < p.negatives.size(); ++k) {
      PlanOp op;
      op.kind = PlanOp::Kind::negative;
      op.nac = static_cast<int>(k);
      r_.plan.push_back(op);
    }
  }

  PendingCount count(const ast::Count& c) {
    PendingCount pc;
    KindId k = kind(c.kind, c.pos);
    auto p = schema_.find_port(k, c.port);
    if (!p) fail(c.pos, fmt::format("{} has no port '{}'", article(c.kind), c.port));
    int target = var(c.target, c.pos, -1);
    if (schema_.port(*p).target != r_.vars[target].kind)
      fail(c.pos, fmt::format("port '{}' does not point at a {}", c.port, schema_.kind(r_.vars[target].kind).name));
    Variable self;
    self.name = fmt::format("count#{}", r_.count_watches.size());
    self.kind = k;
    self.nac = -2;
    r_.vars.push_back(self);
    int self_var = static_cast<int>(r_.vars.size() - 1);
    pc.op.kind = PlanOp::Kind::count;
    pc.op.owner = self_var;
    pc.op.target = target;
    pc.op.port = *p;
    pc.op.count_kind = k;
    pc.op.comparison = comparison(c.comparison);
    pc.op.bound = c.bound;
    CountWatch watch{k, *p, target, {}, {}};
    if (c.where) {
      pc.op.expr = expr(*c.where, self_var, -1, true);
      std::vector<int> vars;
      pc.op.expr->collect_vars(vars);
      for (int v : vars)
        if (v != self_var) pc.vars.push_back(v);
      collect_reads(*pc.op.expr, self_var, watch.attrs, watch.ports);
    }
    pc.vars.push_back(target);
    r_.count_watches.push_back(watch);
    return pc;
  }
  static CExpr::Op comparison(ast::Expr::Op op) {
    using A = ast::Expr::Op;
    using C = CExpr::Op;
    switch (op) {
      case A::eq: return C::eq;
      case A::ne: return C::ne;
      case A::lt: return C::lt;
      case A::le: return C::le;
      case A::gt: return C::gt;
      default: return C::ge;
    }
  }
  static void collect_reads(const CExpr& e, int var, std::vector<AttrId>& attrs, std::vector<PortId>& ports) {
    if (e.op == CExpr::Op::attribute && e.var == var) attrs.push_back(e.attr);
    if (e.op == CExpr::Op::port && e.var == var) ports.push_back(e.port);
    for (const auto& a : e.args) collect_reads(a, var, attrs, ports);
  }

  void build_negative(int k) {
    const ast::Pattern& p = ast_.pattern.negatives[k];
    std::vector<Incidence> incs;
    for (const auto& inc : p.incidences) incs.push_back(incidence(inc, k));
    std::vector<Filter> filters;
    for (auto& [v, w] : where_)
      if (r_.vars[v].nac == k) filters.push_back(filter(expr(*w, v, k, true)));
    for (const auto& c : p.conditions) filters.push_back(filter(expr(c, -1, k, true)));
    std::vector<PendingCount> none;
    bound_.assign(r_.vars.size(), false);
    for (int v = 0; v < r_.pattern_vars; ++v) bound_[v] = true;
    ibound_ = main_ibound_;
    NegativePlan nac;
    plan(nac.ops, incs, filters, none, k);
    r_.negatives.push_back(std::move(nac));
  }

  /// A condition `x.port[i] == y` or `x.port[i] == none` is a plain slot check,
  /// cheaper than evaluating an expression; anything else stays a filter.
  static PlanOp filter_op(const CExpr& e) {
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

  static PlanOp edge_op(PlanOp::Kind kind, const Incidence& inc) {
    PlanOp op;
    op.kind = kind;
    op.owner = inc.owner;
    op.target = inc.target;
    op.port = inc.port;
    op.index = inc.index;
    return op;
  }

  bool all_bound(const std::vector<int>& vars, const std::vector<int>& ivars) const {
    return std::all_of(vars.begin(), vars.end(), [&](int v) { return bound_[v]; }) &&
           std::all_of(ivars.begin(), ivars.end(), [&](int v) { return ibound_[v]; });
  }

  void bind_index(const CIndex& ix) {
    if (ix.kind == CIndex::Kind::variable) ibound_[ix.variable] = true;
  }

  /// Greedy search plan: emit every check that is ready, then extend by the
  /// cheapest incidence (an out-slot lookup before an incoming scan), else scan.
  void plan(std::vector<PlanOp>& ops, std::vector<Incidence>& incs, std::vector<Filter>& filters,
            std::vector<PendingCount>& counts, int scope) {
    auto emit_ready = [&] {
      for (bool progress = true; progress;) {
        progress = false;
        for (auto& inc : incs)
          if (!inc.used && bound_[inc.owner] && (inc.target < 0 || bound_[inc.target])) {
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
    auto in_scope = [&](int v) { return r_.vars[v].nac == scope; };
    emit_ready();
    for (;;) {
      int best = -1, best_cost = 1 << 30;
      for (std::size_t i = 0; i < incs.size(); ++i) {
        const Incidence& inc = incs[i];
        if (inc.used || inc.target < 0) continue;
        int cost;
        if (bound_[inc.owner] && !bound_[inc.target]) {
          bool index_known = inc.index.kind == CIndex::Kind::fixed ||
                             (inc.index.kind == CIndex::Kind::variable && ibound_[inc.index.variable]);
          cost = index_known ? 1 : schema_.port(inc.port).arity;
        } else if (!bound_[inc.owner] && bound_[inc.target]) {
          cost = 8;
        } else {
          continue;
        }
        if (cost < best_cost) best = static_cast<int>(i), best_cost = cost;
      }
      if (best >= 0) {
        Incidence& inc = incs[best];
        PlanOp op = edge_op(bound_[inc.owner] ? PlanOp::Kind::lookup : PlanOp::Kind::incoming, inc);
        int child = op.kind == PlanOp::Kind::lookup ? inc.target : inc.owner;
        int parent = op.kind == PlanOp::Kind::lookup ? inc.owner : inc.target;
        r_.vars[child].parent = parent;
        r_.vars[child].via = op.kind == PlanOp::Kind::lookup ? Variable::Via::lookup : Variable::Via::incoming;
        r_.vars[child].via_port = inc.port;
        bound_[child] = true;
        bind_index(inc.index);
        inc.used = true;
        ops.push_back(op);
        emit_ready();
        continue;
      }
      int unbound = -1;
      for (std::size_t v = 0; v < r_.vars.size() && unbound < 0; ++v)
        if (in_scope(static_cast<int>(v)) && !bound_[v] && !r_.vars[v].created) unbound = static_cast<int>(v);
      if (unbound < 0) break;
      PlanOp op;
      op.kind = PlanOp::Kind::scan;
      op.target = unbound;
      r_.vars[unbound].via = Variable::Via::scan;
      r_.global = true;
      bound_[unbound] = true;
      ops.push_back(op);
      emit_ready();
    }
    for (const auto& f : filters)
      if (!f.used) fail(ast_.pos, "a condition uses an index that no incidence binds");
    if (scope == -1) main_ibound_ = ibound_;
  }

  void statement(const ast::Statement& s) {
    using S = ast::Statement::Op;
    RewriteOp op;
    op.pos = s.pos;
    switch (s.op) {
      case S::create:
        for (const auto& n : s.names) {
          op.kind = RewriteOp::Kind::create;
          for (std::size_t i = 0; i < r_.vars.size(); ++i)
            if (r_.vars[i].name == n && r_.vars[i].created) created_.insert(static_cast<int>(i));
          op.var = var(n, s.pos, -3);
          op.create_kind = r_.vars[op.var].kind;
          r_.rewrite.push_back(op);
        }
        return;
      case S::remove:
        op.kind = RewriteOp::Kind::remove;
        op.var = var(s.names[0], s.pos, -3);
        break;
      case S::merge:
      case S::identify:
      {
        op.kind = s.op == S::merge ? RewriteOp::Kind::merge : RewriteOp::Kind::identify;
        op.value = expr(s.values[0], -1, -3, false);
        op.other = expr(s.values[1], -1, -3, false);
        auto ka = element_kind(op.value, s.pos), kb = element_kind(op.other, s.pos);
        if (ka != kb)
          fail(s.pos, fmt::format("cannot {} a {} with a {}", s.op == S::merge ? "merge" : "identify",
                                  schema_.kind(ka).name, schema_.kind(kb).name));
        if (!s.kind.empty()) {
          auto a = schema_.find_attribute(ka, s.kind);
          if (!a) fail(s.pos, fmt::format("{} has no attribute '{}'", article(schema_.kind(ka).name), s.kind));
          op.attr = *a;
          op.prefer = true;
        }
        break;
      }
      case S::call:
        op.kind = RewriteOp::Kind::call;
        op.action = s.kind;
        for (const auto& n : s.names) op.args.push_back(var(n, s.pos, -3));
        break;
      case S::set_port_list: {
        int owner = var(s.target, s.pos, -3);
        PortId p = port(owner, s.member, s.pos);
        if (s.values.size() != schema_.port(p).arity)
          fail(s.pos, fmt::format("port '{}' has {} slots but {} values are given", s.member, schema_.port(p).arity, s.values.size()));
        for (std::size_t i = 0; i < s.values.size(); ++i) {
          RewriteOp set;
          set.pos = s.pos;
          set.kind = RewriteOp::Kind::set_port;
          set.var = owner;
          set.port = p;
          set.index.value = static_cast<std::int64_t>(i);
          set.value = expr(s.values[i], -1, -3, false);
          expect_element(set.value, schema_.port(p).target, s.pos);
          r_.rewrite.push_back(std::move(set));
        }
        return;
      }
      case S::set_port:
      case S::set_attribute: {
        op.var = var(s.target, s.pos, -3);
        KindId k = r_.vars[op.var].kind;
        auto a = s.op == S::set_attribute ? schema_.find_attribute(k, s.member) : std::nullopt;
        op.value = expr(s.values[0], -1, -3, false);
        if (a) {
          if (yields_element(op.value)) fail(s.pos, fmt::format("attribute '{}' takes a number, not an element", s.member));
          op.kind = RewriteOp::Kind::set_attribute;
          op.attr = *a;
          break;
        }
        op.kind = RewriteOp::Kind::set_port;
        op.port = port(op.var, s.member, s.pos);
        expect_element(op.value, schema_.port(op.port).target, s.pos);
        CIndex ix = index(s.index, op.port, s.op == S::set_port, s.pos, false);
        if (ix.kind == CIndex::Kind::variable) {
          op.index.op = CExpr::Op::index;
          op.index.index_var = ix.variable;
          op.index.offset = ix.offset;
        } else {
          op.index.value = ix.offset;
        }
        break;
      }
    }
    r_.rewrite.push_back(std::move(op));
  }

  static bool yields_element(const CExpr& e) {
    return e.op == CExpr::Op::element || e.op == CExpr::Op::port || e.op == CExpr::Op::none;
  }
  /// A value assigned to a port slot: `none`, or an element of the port's target kind.
  void expect_element(const CExpr& e, KindId target, ast::Pos pos) const {
    if (e.op == CExpr::Op::none) return;
    if (!yields_element(e)) fail(pos, fmt::format("expected {} (or none), found a number", article(schema_.kind(target).name)));
    KindId k = element_kind(e, pos);
    if (k != target)
      fail(pos, fmt::format("expected {}, found {}", article(schema_.kind(target).name), article(schema_.kind(k).name)));
  }
  static std::string article(const std::string& noun) {
    return (noun.find_first_of("aeiou") == 0 ? "an " : "a ") + noun;
  }

  /// The kind of element an element expression (a variable or a port slot) yields.
  KindId element_kind(const CExpr& e, ast::Pos pos) const {
    if (e.op == CExpr::Op::element) return r_.vars[e.var].kind;
    if (e.op == CExpr::Op::port) return schema_.port(e.port).target;
    fail(pos, "expected an element: a variable or x.port[i]");
  }

  void record_distinctness() {
    r_.distinct.assign(r_.vars.size(), {});
    for (std::size_t v = 0; v < r_.vars.size(); ++v)
      for (std::size_t u = 0; u < r_.vars.size(); ++u) {
        const Variable &a = r_.vars[v], &b = r_.vars[u];
        if (u == v || a.kind != b.kind || a.created || b.created || a.nac == -2 || b.nac == -2) continue;
        bool same_scope = a.nac == b.nac || a.nac == -1 || b.nac == -1;
        if (same_scope && !r_.may_be_equal[u][v]) r_.distinct[v].push_back(static_cast<int>(u));
      }
  }

  void record_sensitivity() {
    auto note = [](std::vector<std::uint16_t>& v, std::uint16_t x) {
      if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
    };
    std::vector<const std::vector<PlanOp>*> plans{&r_.plan};
    for (const auto& n : r_.negatives) plans.push_back(&n.ops);
    std::function<void(const CExpr&)> reads = [&](const CExpr& e) {
      if (e.op == CExpr::Op::attribute) note(r_.vars[e.var].attrs, e.attr);
      if (e.op == CExpr::Op::port) note(r_.vars[e.var].out_ports, e.port);
      for (const auto& a : e.args) reads(a);
    };
    for (const auto* ops : plans)
      for (const PlanOp& op : *ops) {
        if (op.kind == PlanOp::Kind::lookup || op.kind == PlanOp::Kind::incoming || op.kind == PlanOp::Kind::check)
          note(r_.vars[op.owner].out_ports, op.port);
        if (op.kind == PlanOp::Kind::incoming && r_.vars[op.owner].nac >= 0) note(r_.vars[op.target].in_ports, op.port);
        if (op.kind == PlanOp::Kind::count) note(r_.vars[op.target].in_ports, op.port);
        if (op.expr) reads(*op.expr);
      }
    if (r_.order) reads(*r_.order);
  }

  const ast::Rule& ast_;
  const Schema& schema_;
  Rule r_;
  std::vector<std::pair<int, const ast::Expr*>> where_;
  std::vector<bool> bound_, ibound_, main_ibound_;
  std::set<int> created_;  ///< `new` variables declared so far in the rewrite
};

}  // namespace

Rule compile_rule(const ast::Rule& rule, const Schema& schema) { return Compiler(rule, schema).run(); }

std::vector<Rule> compile_rules(const std::string& text, const std::string& file, const Schema& schema) {
  std::vector<Rule> out;
  for (const auto& r : parse_rules(text, file)) out.push_back(compile_rule(r, schema));
  return out;
}

std::vector<Rule> load_rule_dir(const std::filesystem::path& dir, const Schema& schema) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw RuleError(dir.string(), {}, "no such rule directory; pass --rules DIR with the rule files (*.rule)");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".rule") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<Rule> rules;
  std::map<std::string, std::string> seen;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw RuleError(f.string(), {}, "cannot read the rule file");
    for (auto& r : compile_rules(text.str(), f.string(), schema)) {
      if (auto [it, fresh] = seen.emplace(r.name, f.string()); !fresh)
        throw RuleError(f.string(), {}, fmt::format("rule '{}' is also defined in {}", r.name, it->second));
      rules.push_back(std::move(r));
    }
  }
  if (rules.empty()) throw RuleError(dir.string(), {}, "no *.rule file in the rule directory");
  return rules;
}

}  // namespace loom::engine
