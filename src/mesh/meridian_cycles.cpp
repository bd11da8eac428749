#include "src/mesh/meridian_cycles.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <set>

namespace loom {

namespace {

using Words = HomologyClass;

bool is_zero(const Words& w) {
  return std::all_of(w.begin(), w.end(), [](std::uint64_t x) { return x == 0; });
}

void add_to(Words& target, const std::uint64_t* source) {
  for (std::size_t i = 0; i < target.size(); ++i) target[i] ^= source[i];
}

bool bit(const Words& w, std::size_t i) { return (w[i / 64] >> (i % 64)) & 1; }

// Vectors over Z/2 kept by their lowest set bit, to test independence.
class Echelon {
public:
  /// Adds `v` if it is independent of those added; says whether it was.
  bool insert(Words v) {
    for (;;) {
      std::size_t w = 0;
      while (w < v.size() && v[w] == 0) ++w;
      if (w == v.size()) return false;
      const std::size_t low = w * 64 + static_cast<std::size_t>(std::countr_zero(v[w]));
      auto row = rows_.find(low);
      if (row == rows_.end()) {
        rows_.emplace(low, std::move(v));
        return true;
      }
      add_to(v, row->second.data());
    }
  }
  std::size_t size() const { return rows_.size(); }

private:
  std::map<std::size_t, Words> rows_;
};

// The x with sum over i of x_i rows[i] = 0: a basis, by elimination.
std::vector<Words> left_null_space(std::vector<Words> rows, std::size_t words) {
  const std::size_t n = rows.size();
  std::vector<Words> combination(n, Words(words, 0));
  for (std::size_t i = 0; i < n; ++i) combination[i][i / 64] |= std::uint64_t{1} << (i % 64);
  std::size_t rank = 0;
  for (std::size_t column = 0; column < n && rank < n; ++column) {
    std::size_t pivot = rank;
    while (pivot < n && !bit(rows[pivot], column)) ++pivot;
    if (pivot == n) continue;
    std::swap(rows[pivot], rows[rank]);
    std::swap(combination[pivot], combination[rank]);
    for (std::size_t k = 0; k < n; ++k)
      if (k != rank && bit(rows[k], column)) {
        add_to(rows[k], rows[rank].data());
        add_to(combination[k], combination[rank].data());
      }
    ++rank;
  }
  return {combination.begin() + static_cast<std::ptrdiff_t>(rank), combination.end()};
}

// Breadth-first trees from this many roots at most cover V x E up to here.
constexpr std::size_t kCandidateWork = 20'000'000;
// Candidates kept per class beyond the shortest; many are one cycle seen from
// each of its nodes, so more are kept than are usually asked for.
constexpr std::size_t kKeptPerClass = 64;

}  // namespace

MeridianSearch::MeridianSearch(const QuadSurface& surface, const SurfaceHomology& homology,
                               std::vector<HomologyClass> linking)
    : surface_(surface), homology_(homology), incident_(incident_edges(homology.edges, surface.points.size())) {
  const std::size_t words = homology_.words;
  inside_ = left_null_space(linking, words);
  parity_.assign(words, 0);
  for (std::size_t i = 0; i < homology_.rank(); ++i)
    if (homology_.cycles[i].size() % 2 == 1) parity_[i / 64] |= std::uint64_t{1} << (i % 64);
  image_of_edge_.assign(homology_.edges.ends.size() * words, 0);
  for (std::size_t e = 0; e < homology_.edges.ends.size(); ++e) {
    Words cls(homology_.class_of_edge(e), homology_.class_of_edge(e) + words);
    for (std::size_t i = 0; i < homology_.rank(); ++i)
      if (bit(cls, i))
        for (std::size_t w = 0; w < words; ++w) image_of_edge_[e * words + w] ^= linking[i][w];
  }
  if (consistent()) collect_candidates();
}

// A cycle made of the tree paths from a root to the two ends of an edge, for
// every edge and for roots spread over the surface, keeping the shortest of
// each class that bounds inside.
void MeridianSearch::collect_candidates() {
  const std::size_t words = homology_.words, edges = homology_.edges.ends.size();
  std::vector<std::uint32_t> roots;
  for (std::uint32_t v = 0; v < incident_.size(); ++v)
    if (!incident_[v].empty()) roots.push_back(v);
  const std::size_t stride = std::max<std::size_t>(1, roots.size() * edges / kCandidateWork);
  std::map<Words, Candidate> best;
  std::map<Words, std::vector<Candidate>> kept;
  std::vector<std::uint64_t> cls(incident_.size() * words), image(incident_.size() * words);
  for (std::size_t r = 0; r < roots.size(); r += stride) {
    const NodeTree tree = breadth_first_tree(homology_.edges, incident_, roots[r]);
    std::fill(cls.begin(), cls.end(), 0);
    std::fill(image.begin(), image.end(), 0);
    for (std::uint32_t v : tree.order) {
      const std::uint32_t e = tree.parent_edge[v];
      if (e == UINT32_MAX) continue;
      for (std::size_t w = 0; w < words; ++w) {
        cls[v * words + w] = cls[tree.parent[v] * words + w] ^ homology_.coordinates[e * words + w];
        image[v * words + w] = image[tree.parent[v] * words + w] ^ image_of_edge_[e * words + w];
      }
    }
    Words c(words), phi(words);
    for (std::uint32_t e = 0; e < edges; ++e) {
      const auto [x, y] = homology_.edges.ends[e];
      if (tree.parent_edge[x] == e || tree.parent_edge[y] == e) continue;
      for (std::size_t w = 0; w < words; ++w) {
        c[w] = cls[x * words + w] ^ cls[y * words + w] ^ homology_.coordinates[e * words + w];
        phi[w] = image[x * words + w] ^ image[y * words + w] ^ image_of_edge_[e * words + w];
      }
      if (is_zero(c) || !is_zero(phi)) continue;
      const Candidate candidate{tree.depth[x] + tree.depth[y] + 1, roots[r], e};
      auto [it, inserted] = best.emplace(c, candidate);
      if (!inserted && candidate.key() < it->second.key()) it->second = candidate;
      keep_shortest(kept[c], candidate);
    }
  }
  bounding_.assign(best.begin(), best.end());
  std::sort(bounding_.begin(), bounding_.end(),
            [](const auto& a, const auto& b) { return a.second.key() < b.second.key(); });
  for (const auto& [cls, few] : kept) alternatives_.insert(alternatives_.end(), few.begin(), few.end());
  std::sort(alternatives_.begin(), alternatives_.end(), [](const auto& a, const auto& b) { return a.key() < b.key(); });
}

// Keeps the kKeptPerClass shortest, one per root, sorted.
void MeridianSearch::keep_shortest(std::vector<Candidate>& few, const Candidate& candidate) {
  auto same_root = std::find_if(few.begin(), few.end(), [&](const Candidate& c) { return c.root == candidate.root; });
  if (same_root != few.end()) {
    if (candidate.key() >= same_root->key()) return;
    few.erase(same_root);
  } else if (few.size() == kKeptPerClass) {
    if (candidate.key() >= few.back().key()) return;
    few.pop_back();
  }
  few.insert(std::upper_bound(few.begin(), few.end(), candidate,
                              [](const Candidate& a, const Candidate& b) { return a.key() < b.key(); }),
             candidate);
}

std::vector<NodeCycle> MeridianSearch::alternatives(std::size_t count) const {
  std::vector<NodeCycle> cycles;
  std::set<std::vector<std::uint32_t>> seen;
  for (const Candidate& candidate : alternatives_) {
    if (cycles.size() == count) break;
    NodeCycle cycle = walk_of(candidate);
    std::vector<std::uint32_t> nodes = cycle;
    std::sort(nodes.begin(), nodes.end());
    if (seen.insert(std::move(nodes)).second) cycles.push_back(std::move(cycle));
  }
  return cycles;
}

std::vector<NodeCycle> MeridianSearch::basis() const {
  std::vector<NodeCycle> cycles;
  Echelon chosen;
  for (const auto& [cls, candidate] : bounding_) {
    if (chosen.size() == inside_.size()) break;
    if (chosen.insert(cls)) cycles.push_back(walk_of(candidate));
  }
  // Classes no candidate reached: the basis cycles' sum.
  for (const Words& cls : inside_)
    if (chosen.size() < inside_.size() && chosen.insert(cls)) cycles.push_back(walk_of_class(cls));
  return cycles;
}

std::optional<NodeCycle> MeridianSearch::odd() const {
  for (const auto& [cls, candidate] : bounding_)
    if (odd_class(cls)) return walk_of(candidate);
  for (const Words& cls : inside_)
    if (odd_class(cls)) return walk_of_class(cls);
  return std::nullopt;
}

bool MeridianSearch::odd_class(const HomologyClass& c) const {
  int ones = 0;
  for (std::size_t w = 0; w < c.size(); ++w) ones += std::popcount(c[w] & parity_[w]);
  return ones % 2 == 1;
}

NodeCycle MeridianSearch::walk_of(const Candidate& c) const {
  const NodeTree tree = breadth_first_tree(homology_.edges, incident_, c.root);
  return cycle_through(tree, homology_.edges.ends[c.edge][0], homology_.edges.ends[c.edge][1]);
}

// The edges of the basis cycles in `c`, each kept if it occurs an odd number of
// times, walked as one closed walk per connected piece (Hierholzer), one after
// the other.
NodeCycle MeridianSearch::walk_of_class(const HomologyClass& c) const {
  std::vector<bool> used(homology_.edges.ends.size(), false);
  auto edge_between = [&](std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t e : incident_[a])
      if (homology_.edges.ends[e][0] == b || homology_.edges.ends[e][1] == b) return e;
    return UINT32_MAX;
  };
  for (std::size_t i = 0; i < homology_.rank(); ++i) {
    if (!bit(c, i)) continue;
    const NodeCycle& cycle = homology_.cycles[i];
    for (std::size_t k = 0; k < cycle.size(); ++k) {
      const std::uint32_t e = edge_between(cycle[k], cycle[(k + 1) % cycle.size()]);
      used[e] = !used[e];
    }
  }
  NodeCycle walk;
  for (std::uint32_t start = 0; start < used.size(); ++start) {
    if (!used[start]) continue;
    std::vector<std::uint32_t> stack{homology_.edges.ends[start][0]}, piece;
    while (!stack.empty()) {
      const std::uint32_t v = stack.back();
      auto next = std::find_if(incident_[v].begin(), incident_[v].end(), [&](std::uint32_t e) { return used[e]; });
      if (next == incident_[v].end()) {
        piece.push_back(v);
        stack.pop_back();
        continue;
      }
      used[*next] = false;
      stack.push_back(homology_.edges.ends[*next][0] == v ? homology_.edges.ends[*next][1]
                                                          : homology_.edges.ends[*next][0]);
    }
    piece.pop_back();  // Hierholzer's circuit ends where it began
    walk.insert(walk.end(), piece.begin(), piece.end());
  }
  return walk;
}

}  // namespace loom
