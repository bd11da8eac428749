#pragma once
// engine::Graph as a model of the Boost.Graph concepts: IncidenceGraph,
// BidirectionalGraph, AdjacencyGraph, VertexListGraph, EdgeListGraph and
// AdjacencyMatrix, with a vertex_index property map. Boost's algorithms
// (breadth_first_search, connected_components, vf2_subgraph_mono,
// write_graphviz) run on it unchanged.
//
// Vertices are element ids, edges are incidences (slots). As with
// boost::filtered_graph, num_vertices() is the id bound, tombstones included,
// so that vertex_index-keyed arrays are large enough; vertices() visits only
// the alive elements.
#include <utility>

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <boost/property_map/property_map.hpp>

#include "engine/graph.hpp"

namespace loom::engine {

/// A Boost.Graph edge: one incidence, identified by its slot.
struct Incidence {
  SlotId slot = no_slot;
  friend bool operator==(Incidence a, Incidence b) { return a.slot == b.slot; }
  friend bool operator!=(Incidence a, Incidence b) { return a.slot != b.slot; }
  friend bool operator<(Incidence a, Incidence b) { return a.slot < b.slot; }
};

namespace bgl {

/// Alive element ids in increasing order.
class VertexIterator : public boost::iterator_facade<VertexIterator, Id, boost::forward_traversal_tag, Id> {
public:
  VertexIterator() = default;
  VertexIterator(const Graph* g, Id v) : g_(g), v_(v) { skip(); }

private:
  friend class boost::iterator_core_access;
  void skip() {
    while (v_ < g_->id_bound() && !g_->alive(v_)) ++v_;
  }
  void increment() {
    ++v_;
    skip();
  }
  bool equal(const VertexIterator& o) const { return v_ == o.v_; }
  Id dereference() const { return v_; }
  const Graph* g_ = nullptr;
  Id v_ = 0;
};

/// Linked slots in [s, end) of alive owners, in slot order.
class SlotRangeIterator
    : public boost::iterator_facade<SlotRangeIterator, Incidence, boost::forward_traversal_tag, Incidence> {
public:
  SlotRangeIterator() = default;
  SlotRangeIterator(const Graph* g, SlotId s, SlotId end) : g_(g), s_(s), end_(end) { skip(); }

private:
  friend class boost::iterator_core_access;
  void skip() {
    while (s_ < end_ && (g_->slot_target(s_) == no_element || !g_->alive(g_->slot_owner(s_)))) ++s_;
  }
  void increment() {
    ++s_;
    skip();
  }
  bool equal(const SlotRangeIterator& o) const { return s_ == o.s_; }
  Incidence dereference() const { return Incidence{s_}; }
  const Graph* g_ = nullptr;
  SlotId s_ = 0, end_ = 0;
};

class InEdgeIterator
    : public boost::iterator_facade<InEdgeIterator, Incidence, boost::forward_traversal_tag, Incidence> {
public:
  InEdgeIterator() = default;
  InEdgeIterator(const Graph* g, SlotId s) : g_(g), s_(s) {}

private:
  friend class boost::iterator_core_access;
  void increment() { s_ = g_->next_incoming(s_); }
  bool equal(const InEdgeIterator& o) const { return s_ == o.s_; }
  Incidence dereference() const { return Incidence{s_}; }
  const Graph* g_ = nullptr;
  SlotId s_ = no_slot;
};

struct TraversalCategory : virtual boost::incidence_graph_tag,
                           virtual boost::bidirectional_graph_tag,
                           virtual boost::adjacency_graph_tag,
                           virtual boost::vertex_list_graph_tag,
                           virtual boost::edge_list_graph_tag,
                           virtual boost::adjacency_matrix_tag {};

}  // namespace bgl

// --- free functions required by the concepts (found by ADL) ---------------
inline Id source(Incidence e, const Graph& g) { return g.slot_owner(e.slot); }
inline Id target(Incidence e, const Graph& g) { return g.slot_target(e.slot); }

inline std::pair<bgl::SlotRangeIterator, bgl::SlotRangeIterator> out_edges(Id v, const Graph& g) {
  SlotId b = g.first_slot(v), e = b + g.slot_count(v);
  return {bgl::SlotRangeIterator(&g, b, e), bgl::SlotRangeIterator(&g, e, e)};
}
inline std::size_t out_degree(Id v, const Graph& g) {
  auto [b, e] = out_edges(v, g);
  return static_cast<std::size_t>(std::distance(b, e));
}
inline std::pair<bgl::InEdgeIterator, bgl::InEdgeIterator> in_edges(Id v, const Graph& g) {
  return {bgl::InEdgeIterator(&g, g.first_incoming(v)), bgl::InEdgeIterator(&g, no_slot)};
}
inline std::size_t in_degree(Id v, const Graph& g) { return g.in_degree(v); }
inline std::size_t degree(Id v, const Graph& g) { return in_degree(v, g) + out_degree(v, g); }

inline std::pair<bgl::VertexIterator, bgl::VertexIterator> vertices(const Graph& g) {
  return {bgl::VertexIterator(&g, 0), bgl::VertexIterator(&g, g.id_bound())};
}
inline std::size_t num_vertices(const Graph& g) { return g.id_bound(); }

inline std::pair<bgl::SlotRangeIterator, bgl::SlotRangeIterator> edges(const Graph& g) {
  return {bgl::SlotRangeIterator(&g, 0, g.slot_bound()), bgl::SlotRangeIterator(&g, g.slot_bound(), g.slot_bound())};
}
inline std::size_t num_edges(const Graph& g) { return g.incidence_count(); }

/// AdjacencyMatrix: the first incidence from u to v, O(slots of u).
inline std::pair<Incidence, bool> edge(Id u, Id v, const Graph& g) {
  for (SlotId s = g.first_slot(u), e = s + g.slot_count(u); s < e; ++s)
    if (g.slot_target(s) == v) return {Incidence{s}, true};
  return {Incidence{}, false};
}

}  // namespace loom::engine

namespace boost {

template <>
struct graph_traits<loom::engine::Graph> {
  using vertex_descriptor = loom::engine::Id;
  using edge_descriptor = loom::engine::Incidence;
  using directed_category = bidirectional_tag;
  using edge_parallel_category = allow_parallel_edge_tag;
  using traversal_category = loom::engine::bgl::TraversalCategory;
  using out_edge_iterator = loom::engine::bgl::SlotRangeIterator;
  using in_edge_iterator = loom::engine::bgl::InEdgeIterator;
  using vertex_iterator = loom::engine::bgl::VertexIterator;
  using edge_iterator = loom::engine::bgl::SlotRangeIterator;
  using adjacency_iterator =
      adjacency_iterator_generator<loom::engine::Graph, vertex_descriptor, out_edge_iterator>::type;
  using degree_size_type = std::size_t;
  using vertices_size_type = std::size_t;
  using edges_size_type = std::size_t;
  static vertex_descriptor null_vertex() { return loom::engine::no_element; }
};

template <>
struct property_map<loom::engine::Graph, vertex_index_t> {
  using type = typed_identity_property_map<loom::engine::Id>;
  using const_type = type;
};

}  // namespace boost

namespace loom::engine {

inline std::pair<boost::graph_traits<Graph>::adjacency_iterator, boost::graph_traits<Graph>::adjacency_iterator>
adjacent_vertices(Id v, const Graph& g) {
  using It = boost::graph_traits<Graph>::adjacency_iterator;
  auto [b, e] = out_edges(v, g);
  return {It(b, &g), It(e, &g)};
}

inline boost::typed_identity_property_map<Id> get(boost::vertex_index_t, const Graph&) { return {}; }
inline Id get(boost::vertex_index_t, const Graph&, Id v) { return v; }

}  // namespace loom::engine
