#pragma once
// Search plans (internal to the rule compiler): the greedy ordering of a
// pattern's constraints from its anchor, and what the incremental matcher
// needs to know about a compiled rule (which changes concern which variable,
// which variables must be distinct).
#include <vector>

#include "engine/rule.hpp"
#include "engine/schema.hpp"

namespace loom::engine {

/// `owner.port[index] == target` (target -1: the slot is empty).
struct PlanIncidence {
  int owner, target;
  PortId port;
  CIndex index;
  bool used = false;
};

/// A condition with the variables and indices it needs bound.
struct PlanFilter {
  CExpr expr;
  std::vector<int> vars, index_vars;
  bool used = false;
};

struct PlanCount {
  PlanOp op;
  std::vector<int> vars;
  bool used = false;
};

class PlanBuilder {
public:
  PlanBuilder(Rule& rule, const Schema& schema) : rule(rule), schema(schema) {}

  /// Emits every check that is ready, then extends by the cheapest incidence
  /// (an out-slot lookup before an incoming scan), else by a scan, until the
  /// variables of `scope` (-1: main pattern, k: negative pattern k) are bound.
  /// Records how each variable was reached. False if a condition uses an
  /// index no incidence binds.
  bool build(std::vector<PlanOp>& ops, std::vector<PlanIncidence>& incs, std::vector<PlanFilter>& filters,
             std::vector<PlanCount>& counts, int scope);

  Rule& rule;
  const Schema& schema;
  std::vector<bool> bound, index_bound;

private:
  bool all_bound(const std::vector<int>& vars, const std::vector<int>& ivars) const;
  void bind_index(const CIndex& ix);
};

/// A condition `x.port[i] == y` or `== none` as a slot check, else a filter.
PlanOp filter_op(const CExpr& e);

/// Fills Variable::out_ports, in_ports, negative_in_ports and attrs: the changes that concern each variable.
void record_sensitivity(Rule& rule);
/// Fills Rule::distinct.
void record_distinctness(Rule& rule);

}  // namespace loom::engine
