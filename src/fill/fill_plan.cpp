#include "src/fill/fill_plan.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <unordered_map>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include "src/util/error.hpp"

namespace loom::fill {

namespace {

constexpr const char* where = "constructive fill";

void number_edges(const QuadSurface& s, FillPlan& plan) {
  std::unordered_map<std::uint64_t, std::uint32_t> ids;
  plan.quad_edges.resize(s.quads.size());
  for (std::size_t q = 0; q < s.quads.size(); ++q)
    for (int k = 0; k < 4; ++k) {
      std::uint32_t u = s.quads[q][k], v = s.quads[q][(k + 1) % 4];
      std::uint64_t key = (std::uint64_t{std::min(u, v)} << 32) | std::max(u, v);
      auto [it, added] = ids.emplace(key, static_cast<std::uint32_t>(plan.edge_nodes.size()));
      if (added) plan.edge_nodes.push_back({u, v});
      plan.quad_edges[q][k] = it->second;
    }
}

void colour_nodes(const QuadSurface& s, FillPlan& plan) {
  const std::size_t n = s.points.size();
  std::vector<std::vector<std::uint32_t>> next(n);
  for (const auto& [u, v] : plan.edge_nodes) next[u].push_back(v), next[v].push_back(u);
  std::vector<int> colour(n, -1);
  std::deque<std::uint32_t> queue{0};
  colour[0] = 0;
  std::size_t reached = 1;
  while (!queue.empty()) {
    std::uint32_t u = queue.front();
    queue.pop_front();
    for (std::uint32_t v : next[u]) {
      if (colour[v] == colour[u])
        fail_input(where, fmt::format("nodes {} and {} are joined and on an odd cycle", u, v),
                   "the fill needs a two-colourable surface (every sphere quadrangulation is)");
      if (colour[v] < 0) colour[v] = 1 - colour[u], queue.push_back(v), ++reached;
    }
  }
  if (reached != n) fail_input(where, "the surface is not connected", "fill each piece on its own");
  plan.white.resize(n);
  for (std::size_t v = 0; v < n; ++v) plan.white[v] = colour[v] == 1;
}

void match_quads(const QuadSurface& s, FillPlan& plan) {
  using Dual = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Dual dual(s.quads.size());
  std::vector<std::array<std::uint32_t, 2>> sides(plan.edge_nodes.size(), {UINT32_MAX, UINT32_MAX});
  for (std::uint32_t q = 0; q < s.quads.size(); ++q)
    for (std::uint32_t e : plan.quad_edges[q]) sides[e][sides[e][0] == UINT32_MAX ? 0 : 1] = q;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_between;
  for (std::uint32_t e = 0; e < sides.size(); ++e) {
    auto [p, q] = sides[e];
    if (q == UINT32_MAX)
      fail_input(where, fmt::format("edge {}-{} is on one quad only", plan.edge_nodes[e][0], plan.edge_nodes[e][1]),
                 "the fill needs a closed surface");
    if (edge_between.emplace(std::pair{std::min(p, q), std::max(p, q)}, e).second) boost::add_edge(p, q, dual);
  }
  std::vector<boost::graph_traits<Dual>::vertex_descriptor> mate(s.quads.size());
  boost::edmonds_maximum_cardinality_matching(dual, mate.data());
  plan.even_edge.assign(plan.edge_nodes.size(), false);
  plan.mate.assign(s.quads.size(), 0);
  for (std::uint32_t q = 0; q < s.quads.size(); ++q) {
    if (mate[q] == boost::graph_traits<Dual>::null_vertex())
      fail_input(where, fmt::format("quad {} cannot be paired with a neighbour across an edge", q),
                 "the fill needs a perfect matching of the quads (every sphere without repeated edges has one)");
    plan.mate[q] = static_cast<std::uint32_t>(mate[q]);
    if (q < mate[q]) plan.even_edge[edge_between.at({q, static_cast<std::uint32_t>(mate[q])})] = true;
  }
}

}  // namespace

FillPlan plan_fill(const QuadSurface& s) {
  FillPlan plan;
  if (s.quads.empty() || s.quads.size() % 2) fail_input(where, "the surface needs an even, non-zero number of quads",
                                                           "split every quad into four to make the count even");
  number_edges(s, plan);
  long euler = static_cast<long>(s.points.size()) - static_cast<long>(plan.edge_nodes.size()) +
               static_cast<long>(s.quads.size());
  if (euler != 2)
    fail_input(where, fmt::format("the surface has Euler characteristic {}, not a sphere's 2", euler),
               "the fill meshes balls only");
  colour_nodes(s, plan);
  match_quads(s, plan);
  return plan;
}

}  // namespace loom::fill
