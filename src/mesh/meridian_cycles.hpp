#pragma once
// Short meridians from the linking matrix (meridians.hpp): which classes bound
// inside, and short cycles of the surface in them.
#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

#include "src/mesh/meridians.hpp"
#include "src/mesh/surface_homology.hpp"

namespace loom {

class MeridianSearch {
public:
  /// `linking[i]` bit j: lk(basis cycle i pushed in, basis cycle j pushed out) mod 2.
  MeridianSearch(const QuadSurface& surface, const SurfaceHomology& homology, std::vector<HomologyClass> linking);

  /// Whether the classes bounding inside have dimension g, as Alexander
  /// duality demands (half of the 2g); false means the linking numbers are wrong.
  bool consistent() const { return inside_.size() * 2 == homology_.rank(); }
  /// g cycles whose classes span those bounding inside, short ones first.
  std::vector<NodeCycle> basis() const;
  /// Up to `count` distinct short cycles bounding inside, of any class but
  /// zero, shortest first: other places a disk may span when a basis cycle
  /// cannot take one.
  std::vector<NodeCycle> alternatives(std::size_t count) const;
  /// A short odd cycle bounding inside, if any class bounding inside is odd.
  std::optional<NodeCycle> odd() const;

private:
  struct Candidate {
    std::uint32_t length, root, edge;  // tree path + edge + tree path, from root
    auto key() const { return std::tuple(length, root, edge); }
  };
  void collect_candidates();
  static void keep_shortest(std::vector<Candidate>& few, const Candidate& candidate);
  NodeCycle walk_of(const Candidate& c) const;
  NodeCycle walk_of_class(const HomologyClass& c) const;
  bool odd_class(const HomologyClass& c) const;

  const QuadSurface& surface_;
  const SurfaceHomology& homology_;
  std::vector<std::vector<std::uint32_t>> incident_;
  std::vector<HomologyClass> inside_;  // a basis of the classes bounding inside
  HomologyClass parity_;               // bit i: the length of basis cycle i is odd
  std::vector<std::uint64_t> image_of_edge_;  // per edge, the linking row sum of its class
  std::vector<std::pair<HomologyClass, Candidate>> bounding_;  // shortest per class, by length
  std::vector<Candidate> alternatives_;  // the shortest few per class, from distinct roots, by length
};

}  // namespace loom
