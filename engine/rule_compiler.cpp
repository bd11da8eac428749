#include "engine/rule_compiler.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "engine/rule_arithmetic.hpp"
#include "engine/rule_parser.hpp"
#include "engine/rule_plan.hpp"

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

class Compiler {
public:
  Compiler(const ast::Rule& rule, const Schema& schema) : ast_(rule), schema_(schema) {}

  Rule run() {
    r_.name = ast_.name;
    r_.file = ast_.file;
    r_.pos = ast_.pos;
    r_.priority = ast_.priority;
    for (const auto& d : ast_.pattern.declarations) declare(d, -1);
    r_.pattern_vars = static_cast<int>(r_.vars.size());
    for (std::size_t k = 0; k < ast_.pattern.negatives.size(); ++k) {
      const ast::Pattern& nac = ast_.pattern.negatives[k];
      if (!nac.negatives.empty()) fail(nac.negatives.front().pos, "negative patterns cannot be nested");
      if (!nac.counts.empty()) fail(nac.counts.front().pos, "count(...) is only allowed in the main pattern");
      if (!nac.tests.empty()) fail(nac.tests.front().pos, "test ...(...) is only allowed in the main pattern");
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
    for (const auto& t : ast_.pattern.tests) {
      RewriteOp test;
      test.kind = RewriteOp::Kind::call;
      test.pos = t.pos;
      test.action = t.kind;
      for (const auto& n : t.names) test.args.push_back(var(n, t.pos, -1));
      r_.tests.push_back(std::move(test));
    }
    for (const auto& s : ast_.rewrite) statement(s);
    record_sensitivity(r_);
    record_distinctness(r_);
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
    c.pos = e.pos;
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
      case A::call: return measure(e, self, scope);
      default: {
        c.op = ops.at(e.op);
        for (const auto& a : e.args) c.args.push_back(expr(a, self, scope, pattern));
        return folded(std::move(c));
      }
    }
  }

  /// `NAME(a, b, ...)`: a call of a domain measure on element variables,
  /// recorded in Rule::measures (checked against the domain's signatures when
  /// an Engine binds them). A measure may read anything of its arguments, so
  /// a change to any attribute of one re-queues the match.
  CExpr measure(const ast::Expr& e, int self, int scope) {
    if (e.args.size() > max_measure_args)
      fail(e.pos, fmt::format("measure '{}' is given {} arguments; at most {} are allowed", e.name, e.args.size(),
                              max_measure_args));
    CExpr c;
    c.pos = e.pos;
    c.op = CExpr::Op::measure;
    c.value = static_cast<std::int64_t>(r_.measures.size());
    RewriteOp call;
    call.kind = RewriteOp::Kind::call;
    call.action = e.name;
    call.pos = e.pos;
    for (const ast::Expr& a : e.args) {
      CExpr arg;
      arg.pos = a.pos;
      arg.op = CExpr::Op::element;
      arg.var = a.name == "self" && self >= 0 ? self : var(a.name, a.pos, scope);
      if (r_.vars[arg.var].created) fail(a.pos, fmt::format("measure '{}' cannot read '{}', which the rewrite makes", e.name, a.name));
      Variable& v = r_.vars[arg.var];
      for (AttrId attr : schema_.kind(v.kind).attributes)
        if (std::find(v.attrs.begin(), v.attrs.end(), attr) == v.attrs.end()) v.attrs.push_back(attr);
      call.args.push_back(arg.var);
      c.args.push_back(std::move(arg));
    }
    r_.measures.push_back(std::move(call));
    return c;
  }

  // An operator on literals becomes a literal, so that a constant expression
  // that overflows is refused at load, and costs nothing when matching.
  CExpr folded(CExpr c) const {
    if (!std::all_of(c.args.begin(), c.args.end(), [](const CExpr& a) { return a.op == CExpr::Op::literal; }))
      return c;
    CExpr literal;
    literal.pos = c.pos;
    literal.value = apply_operator(r_, c, [&](std::size_t i) { return c.args[i].value; });
    return literal;
  }

  // Written the same way, hence the same element whatever the match.
  static bool same_expression(const CExpr& a, const CExpr& b) {
    if (a.op != b.op || a.value != b.value || a.var != b.var || a.index_var != b.index_var || a.offset != b.offset ||
        a.attr != b.attr || a.port != b.port || a.args.size() != b.args.size())
      return false;
    for (std::size_t i = 0; i < a.args.size(); ++i)
      if (!same_expression(a.args[i], b.args[i])) return false;
    return true;
  }

  PlanIncidence incidence(const ast::Incidence& inc, int scope) {
    PlanIncidence c;
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
  PlanFilter filter(CExpr e) {
    PlanFilter f;
    e.collect_vars(f.vars);
    collect_index_vars(e, f.index_vars);
    f.expr = std::move(e);
    return f;
  }

  void build_main_plan() {
    const ast::Pattern& p = ast_.pattern;
    std::vector<PlanIncidence> incs;
    for (const auto& inc : p.incidences) incs.push_back(incidence(inc, -1));
    std::vector<PlanFilter> filters;
    for (auto& [v, w] : where_)
      if (r_.vars[v].nac == -1) filters.push_back(filter(expr(*w, v, -1, true)));
    for (const auto& c : p.conditions) filters.push_back(filter(expr(c, -1, -1, true)));
    std::vector<PlanCount> counts;
    for (const auto& c : p.counts) counts.push_back(count(c));
    PlanBuilder builder(r_, schema_);
    builder.bound.assign(r_.vars.size(), false);
    builder.index_bound.assign(r_.index_vars.size() + 64, false);  // room for indices first met in negatives
    builder.bound[r_.anchor] = true;
    r_.vars[r_.anchor].via = Variable::Via::anchor;
    if (!builder.build(r_.plan, incs, filters, counts, -1)) fail(ast_.pos, "a condition uses an index that no incidence binds");
    main_index_bound_ = builder.index_bound;
    for (std::size_t k = 0; k < p.negatives.size(); ++k) {
      PlanOp op;
      op.kind = PlanOp::Kind::negative;
      op.nac = static_cast<int>(k);
      r_.plan.push_back(op);
    }
  }

  PlanCount count(const ast::Count& c) {
    PlanCount pc;
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
      // `self.port[k] == none`, the common case, is counted without evaluating.
      PlanOp slot = filter_op(*pc.op.expr);
      if (slot.kind == PlanOp::Kind::check && slot.owner == self_var && slot.target < 0 &&
          slot.index.kind == CIndex::Kind::fixed) {
        pc.op.count_empty_port = slot.port;
        pc.op.count_empty_slot = slot.index.offset;
        pc.op.expr.reset();
      }
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
    std::vector<PlanIncidence> incs;
    for (const auto& inc : p.incidences) incs.push_back(incidence(inc, k));
    std::vector<PlanFilter> filters;
    for (auto& [v, w] : where_)
      if (r_.vars[v].nac == k) filters.push_back(filter(expr(*w, v, k, true)));
    for (const auto& c : p.conditions) filters.push_back(filter(expr(c, -1, k, true)));
    std::vector<PlanCount> none;
    PlanBuilder builder(r_, schema_);
    builder.bound.assign(r_.vars.size(), false);
    for (int v = 0; v < r_.pattern_vars; ++v) builder.bound[v] = true;
    builder.index_bound = main_index_bound_;
    NegativePlan nac;
    if (!builder.build(nac.ops, incs, filters, none, k)) fail(p.pos, "a condition uses an index that no incidence binds");
    r_.negatives.push_back(std::move(nac));
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
        if (same_expression(op.value, op.other))
          fail(s.pos, fmt::format("rule '{}': {} an element with itself does nothing; name two different elements",
                                  r_.name, s.op == S::merge ? "merging" : "identifying"));
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

  const ast::Rule& ast_;
  const Schema& schema_;
  Rule r_;
  std::vector<std::pair<int, const ast::Expr*>> where_;
  std::vector<bool> main_index_bound_;  ///< indices bound by the main pattern
  std::set<int> created_;  ///< `new` variables declared so far in the rewrite
};

}  // namespace

Rule compile_rule(const ast::Rule& rule, const Schema& schema) { return Compiler(rule, schema).run(); }

}  // namespace loom::engine
