#include "src/quadmap/automorphisms.hpp"

#include <algorithm>

#include "src/quadmap/canonical.hpp"

namespace loom::quadmap {

namespace {

Permutation identity(std::size_t n) {
  Permutation p(n);
  for (Vertex v = 0; v < n; ++v) p[v] = v;
  return p;
}

/// (a after b)[v] = a[b[v]]
Permutation compose(const Permutation& a, const Permutation& b) {
  Permutation c(b.size());
  for (Vertex v = 0; v < b.size(); ++v) c[v] = a[b[v]];
  return c;
}

Permutation inverse(const Permutation& p) {
  Permutation q(p.size());
  for (Vertex v = 0; v < p.size(); ++v) q[p[v]] = v;
  return q;
}

}  // namespace

std::vector<Permutation> automorphisms(const QuadMap& m) {
  const auto twin = twins(m);
  const Canonical canon = canonical_oriented(m, twin);
  const std::vector<Vertex> first = labels_from(m, twin, canon.starts.front());
  std::vector<Vertex> vertex_of_label(m.vertex_bound, no_vertex);
  std::vector<Permutation> out;
  for (Dart start : canon.starts) {
    const std::vector<Vertex> labels = labels_from(m, twin, start);
    for (Vertex v = 0; v < m.vertex_bound; ++v)
      if (labels[v] != no_vertex) vertex_of_label[labels[v]] = v;
    Permutation p = identity(m.vertex_bound);
    for (Vertex v = 0; v < m.vertex_bound; ++v)
      if (first[v] != no_vertex) p[v] = vertex_of_label[first[v]];
    out.push_back(std::move(p));
  }
  return out;
}

int order_of(const Permutation& p) {
  const Permutation id = identity(p.size());
  Permutation power = p;
  int k = 1;
  for (; power != id; ++k) power = compose(p, power);
  return k;
}

std::vector<Permutation> up_to_conjugacy(const std::vector<Permutation>& elements,
                                         const std::vector<Permutation>& group) {
  std::vector<Permutation> representatives, met;
  for (const Permutation& e : elements) {
    if (std::find(met.begin(), met.end(), e) != met.end()) continue;
    representatives.push_back(e);
    for (const Permutation& g : group) met.push_back(compose(g, compose(e, inverse(g))));
  }
  return representatives;
}

}  // namespace loom::quadmap
