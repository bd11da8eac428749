#pragma once
// Matching a compiled rule: its search plan is walked from an anchor element,
// binding one pattern variable per step (backtracking over the choices).
#include <functional>
#include <vector>

#include "engine/graph.hpp"
#include "engine/rule.hpp"

namespace loom::engine {

/// One occurrence of a rule's pattern: an element per variable (no_element for
/// negative-pattern, count and not-yet-created variables) and a value per index.
struct Match {
  const Rule* rule = nullptr;
  std::vector<Id> elements;
  std::vector<int> indices;
  Id anchor() const { return elements[rule->anchor]; }
};

class Matcher {
public:
  explicit Matcher(const Graph& graph) : g_(graph) {}

  /// The first match whose anchor is `anchor`, in plan order.
  bool first_at(const Rule& rule, Id anchor, Match& out) const;
  /// Every match anchored at `anchor`; `visit` returns false to stop. The
  /// match passed to `visit` is only valid during the call (not re-entrant).
  void each_at(const Rule& rule, Id anchor, const std::function<bool(const Match&)>& visit) const;
  /// Every match in the graph (anchors in id order); `visit` returns false to stop.
  void each(const Rule& rule, const std::function<bool(const Match&)>& visit) const;

  /// Evaluates an integer or element expression over a match.
  std::int64_t evaluate(const CExpr& e, const Match& m) const;

private:
  struct Search;
  /// A measure call's value (Rule::measure_fns, bound by the Engine).
  std::int64_t measure(const CExpr& e, const Match& m) const;
  const Graph& g_;
  mutable Match scratch_;
};

}  // namespace loom::engine
