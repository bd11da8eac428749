#pragma once
// Strategies: which applicable match a weave applies next.
//   priority  rules by descending priority (ties: load order); within a rule,
//             the match with the smallest `order` key, then the smallest anchor id
//   sequence  the rules named in `order` only, first named first; within a rule
//             as for priority
//   random    rules by descending priority; within the highest priority that
//             has a match, a match drawn uniformly with a seeded generator
#include <cstdint>
#include <string>
#include <vector>

namespace loom::engine {

struct Strategy {
  enum class Kind { priority, sequence, random };
  Kind kind = Kind::priority;
  std::vector<std::string> order;  ///< sequence: rule names, first applied first
  std::uint64_t seed = 0;

  /// "priority", "random", "sequence:a,b,c", or the path of a strategy file:
  ///   # comment
  ///   strategy sequence        (priority | sequence | random)
  ///   order seam cross         (rule names; for sequence)
  ///   seed 7                   (for random; --seed overrides it)
  /// Throws std::invalid_argument with a message naming what is wrong.
  static Strategy parse(const std::string& spec);
  std::string name() const;
};

}  // namespace loom::engine
