#pragma once
// The reference matcher: Boost's vf2_subgraph_mono, run from scratch on the
// whole graph. It finds the embeddings of a rule's main pattern (kinds and
// port-labelled incidences); each embedding is then checked against the rest
// of the rule (slot indices, conditions, counts, negative patterns). Used by
// the tests as an oracle for the anchored matcher, and by the benchmarks.
#include <functional>
#include <vector>

#include "engine/graph.hpp"
#include "engine/matcher.hpp"
#include "engine/rule.hpp"

namespace loom::engine {

/// Elements of the main-pattern variables of every match VF2 finds (all
/// variables distinct: VF2 embeddings are injective). `visit` returns false to stop.
void vf2_matches(const Graph& graph, const Rule& rule, const std::function<bool(const std::vector<Id>&)>& visit);

/// Whether the main-pattern variables bound to `elements` form a match of `rule`.
bool accepts(const Graph& graph, const Rule& rule, const std::vector<Id>& elements);

}  // namespace loom::engine
