// engine/beam_search.hpp on a small explicit state space: how wide the beam
// is decides what it finds; keys seen before are merged; depth is bounded.
#include <doctest/doctest.h>

#include <map>
#include <vector>

#include "engine/beam_search.hpp"

using namespace loom;

namespace {

/// Nodes with a cost paid to reach them and an estimate of what is left;
/// goals are nodes with no estimate.
struct Node {
  double cost, estimate;
  bool goal;
  std::vector<int> next;
};

struct GraphSpace {
  using State = int;
  using Key = int;
  using KeyHash = std::hash<int>;
  std::map<int, Node> nodes;
  std::vector<int> expanded;

  Key key(int s) const { return s; }
  double cost(int s) const { return nodes.at(s).cost; }
  double estimate(int s) const { return nodes.at(s).estimate; }
  double lower_bound(int) const { return 0; }
  bool goal(int s) const { return nodes.at(s).goal; }
  template <class Emit>
  void expand(int s, Emit&& emit) {
    expanded.push_back(s);
    for (int n : nodes.at(s).next) emit(int(n));
  }
};

/// 0 leads to 1, which looks cheap and leads to a dear goal (3), and to 2,
/// which looks dear and leads to a cheap goal (4); both lead to 5.
GraphSpace decoy() {
  GraphSpace g;
  g.nodes[0] = {0, 0, false, {1, 2}};
  g.nodes[1] = {1, 1, false, {3, 5}};
  g.nodes[2] = {1, 5, false, {5, 4}};
  g.nodes[3] = {10, 0, true, {}};
  g.nodes[4] = {3, 0, true, {}};
  g.nodes[5] = {2, 4, false, {}};
  return g;
}

}  // namespace

TEST_CASE("a beam of one follows the cheapest-looking state; a wider one finds the cheaper goal behind another") {
  GraphSpace narrow = decoy();
  engine::BeamLimits limits;
  limits.width = 1;
  const auto one = engine::beam_search(narrow, 0, limits);
  REQUIRE(one.goal);
  CHECK(*one.goal == 3);
  CHECK(narrow.expanded == std::vector<int>{0, 1, 5});

  GraphSpace wide = decoy();
  limits.width = 2;
  const auto two = engine::beam_search(wide, 0, limits);
  REQUIRE(two.goal);
  CHECK(*two.goal == 4);
  CHECK(two.stats.goals == 2);
  // 5 is generated from 1 and again from 2 at the same level: kept once.
  CHECK(two.stats.merged == 1);
  CHECK(wide.expanded == std::vector<int>{0, 1, 2, 5});
}

TEST_CASE("a beam stops at its depth and its expansions, and says it ran out of budget") {
  GraphSpace g = decoy();
  engine::BeamLimits limits;
  limits.width = 2;
  limits.max_depth = 1;
  const auto shallow = engine::beam_search(g, 0, limits);
  CHECK_FALSE(shallow.goal);  // the goals are two levels down
  REQUIRE(shallow.closest);
  CHECK(*shallow.closest == 1);  // the least priority of the level kept

  GraphSpace h = decoy();
  limits.max_depth = 6;
  limits.max_expansions = 2;
  const auto cut = engine::beam_search(h, 0, limits);
  CHECK(cut.stats.out_of_budget);
  CHECK(cut.stats.expanded == 2);
  REQUIRE(cut.goal);
  CHECK(*cut.goal == 3);  // found while expanding 1, before the budget ran out at 2
}
