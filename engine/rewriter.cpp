#include "engine/rewriter.hpp"

#include <new>

#include <fmt/format.h>

#include "engine/rule_parser.hpp"

namespace loom::engine {

namespace {

void apply_op(Graph& g, Match& m, const RewriteOp& op, const Actions& actions, const Matcher& eval);

void merge_into(Graph& g, Match& m, Id from, Id into) {
  if (from == into || from == no_element || into == no_element) return;
  g.redirect_incoming(from, into);
  g.remove(from);
  for (Id& e : m.elements)
    if (e == from) e = into;
}

}  // namespace

void apply_rewrite(Graph& g, Match& m, const Actions& actions) {
  const Rule& rule = *m.rule;
  const Matcher eval(g);
  for (const RewriteOp& op : rule.rewrite) {
    try {
      apply_op(g, m, op, actions, eval);
    } catch (const RuleError&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw;  // not the rule's fault: the run is out of memory
    } catch (const std::exception& e) {
      throw RuleError(rule.file, op.pos, fmt::format("rule '{}' failed here: {}", rule.name, e.what()));
    }
  }
}

bool passes_tests(Graph& g, const Match& m, const Actions& actions) {
  const Rule& rule = *m.rule;
  std::vector<Id> args;
  for (const RewriteOp& t : rule.tests) {
    args.clear();
    for (int v : t.args) args.push_back(m.elements[v]);
    try {
      if (!actions.find_test(t.action)->test(g, args)) return false;
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw RuleError(rule.file, t.pos, fmt::format("rule '{}': test '{}' failed: {}", rule.name, t.action, e.what()));
    }
  }
  return true;
}

namespace {
void apply_op(Graph& g, Match& m, const RewriteOp& op, const Actions& actions, const Matcher& eval) {
  const Rule& rule = *m.rule;
  {
    switch (op.kind) {
      case RewriteOp::Kind::create: m.elements[op.var] = g.add(op.create_kind); break;
      case RewriteOp::Kind::set_port: {
        const PortSpec& p = g.schema().port(op.port);
        std::int64_t raw = eval.evaluate(op.index, m);
        unsigned slot = static_cast<unsigned>(p.order == PortOrder::cyclic ? ((raw % p.arity) + p.arity) % p.arity : raw);
        if (slot >= p.arity)
          throw RuleError(rule.file, op.pos, fmt::format("slot {} is out of range for port '{}'", raw, p.name));
        g.link(m.elements[op.var], op.port, slot, static_cast<Id>(eval.evaluate(op.value, m)));
        break;
      }
      case RewriteOp::Kind::set_attribute:
        g.set(m.elements[op.var], op.attr, static_cast<std::int32_t>(eval.evaluate(op.value, m)));
        break;
      case RewriteOp::Kind::remove: g.remove(m.elements[op.var]); break;
      case RewriteOp::Kind::merge:
        merge_into(g, m, static_cast<Id>(eval.evaluate(op.value, m)), static_cast<Id>(eval.evaluate(op.other, m)));
        break;
      case RewriteOp::Kind::identify: {
        Id a = static_cast<Id>(eval.evaluate(op.value, m)), b = static_cast<Id>(eval.evaluate(op.other, m));
        if (a == b || a == no_element || b == no_element) break;
        bool keep_a;
        if (op.prefer && g.get(a, op.attr) != g.get(b, op.attr)) keep_a = g.get(a, op.attr) > g.get(b, op.attr);
        else if (g.in_degree(a) != g.in_degree(b)) keep_a = g.in_degree(a) > g.in_degree(b);
        else keep_a = a < b;
        if (keep_a) merge_into(g, m, b, a);
        else merge_into(g, m, a, b);
        break;
      }
      case RewriteOp::Kind::call: {
        std::vector<Id> args;
        for (int v : op.args) args.push_back(m.elements[v]);
        actions.find(op.action)->run(g, args);
        break;
      }
    }
  }
}
}  // namespace

void check_actions(const Rule& rule, const Actions& actions, const Schema& schema) {
  auto kind = [&](KindId k) {
    const std::string& noun = schema.kind(k).name;
    return (noun.find_first_of("aeiou") == 0 ? "an " : "a ") + noun;
  };
  enum class Role { action, test, measure };
  auto check = [&](const RewriteOp& op, Role role) {
    const Actions::Entry* action = role == Role::test      ? actions.find_test(op.action)
                                   : role == Role::measure ? actions.find_measure(op.action)
                                                           : actions.find(op.action);
    const char* what = role == Role::test ? "test" : role == Role::measure ? "measure" : "action";
    if (!action) {
      std::string known;
      if (role == Role::measure)
        for (const auto& [name, entry] : actions.measures()) known += (known.empty() ? " (known: " : ", ") + name;
      if (!known.empty()) known += ")";
      throw RuleError(rule.file, op.pos, fmt::format("expected a known {}, found '{}'{}", what, op.action, known));
    }
    const auto& params = action->parameters;
    if (op.args.size() != params.size()) {
      std::string list;
      for (const ActionParameter& p : params)
        list += fmt::format("{}{} {}", list.empty() ? "" : ", ", schema.kind(p.kind).name, p.name);
      throw RuleError(rule.file, op.pos, fmt::format("{} '{}' takes {} argument{} ({}), found {}", what, op.action,
                                                     params.size(), params.size() == 1 ? "" : "s", list, op.args.size()));
    }
    for (std::size_t i = 0; i < params.size(); ++i) {
      const Variable& arg = rule.vars[static_cast<std::size_t>(op.args[i])];
      if (arg.kind != params[i].kind)
        throw RuleError(rule.file, op.pos,
                        fmt::format("argument {} of {} '{}' ({}) must be {}, found '{}', {}", i + 1, what, op.action,
                                    params[i].name, kind(params[i].kind), arg.name, kind(arg.kind)));
    }
  };
  for (const RewriteOp& op : rule.rewrite)
    if (op.kind == RewriteOp::Kind::call) check(op, Role::action);
  for (const RewriteOp& t : rule.tests) check(t, Role::test);
  for (const RewriteOp& m : rule.measures) check(m, Role::measure);
}

void bind_measures(Rule& rule, const Actions& actions) {
  rule.measure_fns.clear();
  for (const RewriteOp& m : rule.measures) rule.measure_fns.push_back(actions.find_measure(m.action)->measure);
}

}  // namespace loom::engine
