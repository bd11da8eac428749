#include "engine/vf2_reference.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/vf2_sub_graph_iso.hpp>

#include "engine/graph_traits.hpp"

namespace loom::engine {

bool accepts(const Graph& graph, const Rule& rule, const std::vector<Id>& elements) {
  Matcher matcher(graph);
  bool found = false;
  matcher.each_at(rule, elements[static_cast<std::size_t>(rule.anchor)], [&](const Match& m) {
    found = std::equal(elements.begin(), elements.end(), m.elements.begin());
    return !found;
  });
  return found;
}

void vf2_matches(const Graph& graph, const Rule& rule, const std::function<bool(const std::vector<Id>&)>& visit) {
  struct Vertex {
    KindId kind;
  };
  struct Edge {
    PortId port;
  };
  using Pattern = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, Vertex, Edge>;
  Pattern pattern;
  for (int v = 0; v < rule.pattern_vars; ++v) boost::add_vertex(Vertex{rule.vars[v].kind}, pattern);
  for (const PlanOp& op : rule.plan)
    if ((op.kind == PlanOp::Kind::lookup || op.kind == PlanOp::Kind::incoming || op.kind == PlanOp::Kind::check) &&
        op.target >= 0)
      boost::add_edge(op.owner, op.target, Edge{op.port}, pattern);

  auto same_kind = [&](Pattern::vertex_descriptor p, Id h) { return pattern[p].kind == graph.kind(h); };
  auto same_port = [&](Pattern::edge_descriptor p, Incidence h) { return pattern[p].port == graph.slot_port(h.slot); };
  std::vector<Id> elements(static_cast<std::size_t>(rule.pattern_vars));
  auto found = [&](auto&& map, auto&&) {
    for (int v = 0; v < rule.pattern_vars; ++v) elements[v] = boost::get(map, v);
    std::vector<Id> full(rule.vars.size(), no_element);
    std::copy(elements.begin(), elements.end(), full.begin());
    if (!accepts(graph, rule, full)) return true;
    return visit(elements);
  };
  boost::vf2_subgraph_mono(pattern, graph, found, boost::vertex_order_by_mult(pattern),
                           boost::edges_equivalent(same_port).vertices_equivalent(same_kind));
}

}  // namespace loom::engine
