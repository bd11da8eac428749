#pragma once
// A compiled rule: variables resolved against a schema, the pattern turned into
// a search plan (a sequence of operations walked from an anchor), and the
// rewrite turned into a sequence of graph operations.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/graph.hpp"
#include "engine/rule_ast.hpp"

namespace loom::engine {

/// The most arguments a measure call may have.
inline constexpr std::size_t max_measure_args = 16;

/// A measure: an integer the domain computes from the elements of a match
/// (a length, an angle, a quality, in the unit its registration documents).
/// It reads the graph only, never changes it.
using MeasureFn = std::function<std::int64_t(const Graph& graph, std::span<const Id> args)>;

/// An integer or element expression over a match.
struct CExpr {
  enum class Op {
    literal, none, element, index, attribute, port,
    measure,  ///< Rule::measures[value] of the elements `args` name
    add, sub, mul, neg, max, min, eq, ne, lt, le, gt, ge, both, either, negate
  };
  Op op = Op::literal;
  std::int64_t value = 0;
  int var = -1;          ///< element variable (element, attribute, port)
  int index_var = -1;    ///< index variable (index; port index)
  int offset = 0;        ///< port index offset, or fixed index when index_var < 0
  AttrId attr = 0;
  PortId port = 0;
  std::vector<CExpr> args;
  ast::Pos pos;          ///< of the operator, for errors while evaluating
  /// Every element variable it reads (to know when it can be evaluated).
  void collect_vars(std::vector<int>& out) const;
};

/// A slot index in a compiled pattern: fixed, an index variable plus offset, or any.
struct CIndex {
  enum class Kind : std::uint8_t { fixed, variable, any } kind = Kind::fixed;
  int variable = -1;
  int offset = 0;
};

struct PlanOp {
  enum class Kind : std::uint8_t {
    lookup,     ///< bind `target` = owner.port[index] (iterating slots if the index is unbound)
    incoming,   ///< bind `owner` among the slots of `port` pointing at `target`
    scan,       ///< bind `target` among all elements of its kind (unanchored)
    check,      ///< owner.port[index] == target (target < 0: the slot is empty)
    filter,     ///< evaluate `expr` (a where-predicate or condition): must be non-zero
    count,      ///< count distinct owners of kind with `port` -> target satisfying expr
    negative,   ///< no extension of negative pattern `nac` may exist
  };
  Kind kind = Kind::check;
  int owner = -1, target = -1;
  PortId port = 0;
  CIndex index;
  std::optional<CExpr> expr;
  KindId count_kind = 0;
  CExpr::Op comparison = CExpr::Op::eq;
  std::int64_t bound = 0;
  int nac = -1;
  /// count: when >= 0, owners count only if slot count_empty_slot of this port is empty.
  int count_empty_slot = -1;
  PortId count_empty_port = 0;
};

struct Variable {
  std::string name;
  KindId kind = 0;
  bool created = false;     ///< made by the rewrite (`new`)
  int nac = -1;             ///< -1: main pattern; else the negative pattern it belongs to
  /// How the search reached it: the variable it was found from and how, so
  /// that a change to an element can be traced back to candidate anchors.
  int parent = -1;
  enum class Via : std::uint8_t { anchor, lookup, incoming, scan } via = Via::anchor;
  PortId via_port = 0;
  std::vector<PortId> out_ports;   ///< ports of this variable the pattern reads
  std::vector<PortId> in_ports;    ///< incoming ports a count reads
  /// Incoming ports only negative patterns read (and no count): a slot added
  /// to one can only make a negative pattern match, never the rule.
  std::vector<PortId> negative_in_ports;
  std::vector<AttrId> attrs;       ///< attributes of this variable the pattern reads
};

struct NegativePlan {
  std::vector<PlanOp> ops;
};

struct RewriteOp {
  enum class Kind : std::uint8_t { create, set_port, set_attribute, remove, merge, identify, call };
  Kind kind = Kind::create;
  int var = -1;                     ///< create, remove, set_*: the variable
  KindId create_kind = 0;
  PortId port = 0;
  CExpr index;                      ///< set_port: slot index (an integer expression)
  CExpr value;                      ///< set_port: element; set_attribute: integer;
                                    ///< merge: the element merged away; identify: one of the two
  CExpr other;                      ///< merge: the element kept; identify: the other
  AttrId attr = 0;
  bool prefer = false;              ///< identify: keep the larger `attr`
  std::string action;               ///< call
  std::vector<int> args;            ///< call: element variables
  ast::Pos pos;
};

/// Elements of a count's owners: a pseudo variable so attribute changes on
/// them can be traced (owner.port[any] -> target).
struct CountWatch {
  KindId kind;
  PortId port;
  int target;
  std::vector<AttrId> attrs;   ///< owner attributes the count's condition reads
  std::vector<PortId> ports;   ///< owner ports the count's condition reads
};

struct Rule {
  std::string name, file;
  ast::Pos pos;                          ///< of the rule's name
  std::int64_t priority = 0;
  std::optional<CExpr> order;
  std::vector<Variable> vars;            ///< main pattern, then negatives', then created
  std::vector<std::string> index_vars;
  int anchor = 0;
  int pattern_vars = 0;                  ///< number of main-pattern variables
  std::vector<std::vector<bool>> may_be_equal;  ///< [var][var]
  /// For each variable, the variables it may not be bound to the same element
  /// as: same kind, same scope (a negative pattern sees the main one), no hom().
  std::vector<std::vector<int>> distinct;
  std::vector<PlanOp> plan;              ///< after the anchor is bound
  std::vector<NegativePlan> negatives;
  std::vector<CountWatch> count_watches;
  std::vector<RewriteOp> rewrite;
  /// `test NAME(args)` of the main pattern: predicates the domain evaluates
  /// on a match the plan found (calls, in the order written).
  std::vector<RewriteOp> tests;
  /// Measure calls in the rule's expressions (`NAME(args)`), in the order
  /// compiled; CExpr::Op::measure names one by index.
  std::vector<RewriteOp> measures;
  /// The domain's function for each of `measures`, bound by the Engine that
  /// runs the rule (bind_measures, rewriter.hpp); empty until then.
  std::vector<MeasureFn> measure_fns;
  bool global = false;                   ///< uses a scan: any change may matter
};

}  // namespace loom::engine
