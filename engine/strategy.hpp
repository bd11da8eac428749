#pragma once
// Strategies: the program that says which rules an engine applies, in what
// order and until when. A strategy is data, like a rule file
// (docs/strategies.md has the grammar):
//
//   seed 7                                   # of the random picks
//   phase weave {                            # phases run in order
//     backtrack {                            # repeat `apply`; on a dead end short of
//       goal front  window 64  branching 3  max 200   # the goal, undo a recent choice
//       apply priority all except pillow_improper     # and take its next alternative
//     }
//   }
//   phase repair { when front  repeat { apply pillow_improper } }
//
// Nodes, and when they succeed:
//   apply PICK RULES   one application of a match of RULES; fails when none applies.
//                      PICK: priority (the default: rules by descending priority,
//                      ties in load order; within a rule the smallest `order` key,
//                      then the smallest anchor id), sequence (the rules in the
//                      order named), random (within the highest priority that has
//                      a match, a match drawn uniformly with the seeded generator).
//                      RULES: names, `all`, or `all except NAMES`.
//   repeat { ... }     the block until it fails (normal form); always succeeds
//   try { ... } else { ... }
//                      the first block, undone if it fails, then the second
//                      (`else` optional); succeeds when the block that ran did
//   backtrack { ... }  see above; succeeds when the goal (a measure the domain
//                      names, at zero) is met. It also stops, failing, once the
//                      measure has not reached a new minimum for 4 x minimum + 256
//                      applications (a front rolling round without shrinking).
//   search { goal MEASURE  depth D  branching B  max N  apply PICK RULES }
//                      iterative deepening over applications: depth 1, 2, ...
//                      D, each state trying the first B matches of the apply in
//                      its pick order. The first state found whose measure is 0
//                      (fewest applications, then pick order) is kept, and the
//                      node succeeds; the domain sees only the applications on
//                      the path to it. Otherwise, after depth D or N
//                      applications tried, the graph is as before and it fails.
//                      Counted in applications, never seconds: the same on
//                      every machine. Defaults: depth 4, branching 3, max 10000.
//   beam { goal MEASURE  cost MEASURE  width W  depth D  branching B  max N  apply PICK RULES }
//                      beam search over applications: level by level, each
//                      state kept tries the first B matches of the apply; of
//                      the states they make, the W of least cost (ties: the
//                      one made first) make the next level. The first level
//                      that holds a state whose goal measure is 0 ends it: of
//                      those, the one of least cost is kept and the node
//                      succeeds (the domain sees only the path to it).
//                      Otherwise, after D levels or N applications tried, it
//                      fails and leaves the closest state it saw (least goal
//                      measure, then least cost), as a backtrack leaves its
//                      progress; `try` undoes it. Defaults: width 8, depth 4,
//                      branching 3, max 10000.
//   when MEASURE       succeeds when the measure is 0, else fails (and so
//                      ends its block)
// A block runs its nodes in turn and fails at the first that fails; what the
// nodes before it did stays (wrap it in `try` to undo it).
#include <cstdint>
#include <string>
#include <vector>

#include "engine/rule_ast.hpp"

namespace loom::engine {

struct StrategyNode {
  enum class Op { apply, repeat, try_else, backtrack, search, beam, when };
  enum class Pick { priority, sequence, random };
  Op op = Op::apply;
  ast::Pos pos;
  // apply
  Pick pick = Pick::priority;
  bool all = false;                 ///< every loaded rule but `rules`
  std::vector<std::string> rules;   ///< named (or excepted, with `all`)
  // repeat: body; try_else: body, otherwise; backtrack: body (one apply)
  std::vector<StrategyNode> body, otherwise;
  // backtrack, search, beam, when
  std::string goal;
  std::string cost;                 ///< beam: the measure it keeps the least of
  std::size_t window = 64, branching = 3, max_backtracks = 200;  ///< backtrack
  std::size_t depth = 4, max_tried = 10'000;                     ///< search, beam (and branching)
  std::size_t width = 8;                                         ///< beam
};

/// Calls f(node) for every node of `nodes`, nested ones included, parents first.
template <class Nodes, class F>
void each_node(Nodes& nodes, F&& f) {
  for (auto& n : nodes) {
    f(n);
    each_node(n.body, f);
    each_node(n.otherwise, f);
  }
}

struct StrategyPhase {
  std::string name;
  std::vector<StrategyNode> body;
};

struct Strategy {
  std::vector<StrategyPhase> phases;
  std::uint64_t seed = 0;
  std::string source = "priority";  ///< the name given, or the file read

  /// "priority", "random", "sequence:a,b,c" (a single phase repeating one
  /// apply of every rule, or of those named), or the path of a strategy file.
  /// Throws RuleError (file:line:column) for a broken file, and
  /// std::invalid_argument for a spec that is neither.
  static Strategy parse(const std::string& spec);
  /// The text of a strategy file; `file` names it in errors.
  static Strategy parse_text(const std::string& text, const std::string& file);

  std::string name() const { return source; }
  /// Whether some apply picks at random (the seed then matters).
  bool random() const;
  /// The same program with every pick random (a pipeline's further attempts).
  Strategy with_random_picks() const;
  /// The same program with each `backtrack { ... apply }` a `repeat { apply }`:
  /// the apply runs to a dead end and stays there (an ordering bench's
  /// baseline, for any rule set).
  Strategy without_backtracking() const;
};

}  // namespace loom::engine
