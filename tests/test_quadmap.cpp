// The quad-map kernel: simplicity checks, canonical codes (against nauty),
// the enumerator (against OEIS) and hex gluing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include <nauty.h>
#include <nautinv.h>

#include "src/gen/generators.hpp"
#include "src/quadmap/automorphisms.hpp"
#include "src/quadmap/canonical.hpp"
#include "src/quadmap/enumerate.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/quadmap/quad_map.hpp"

using namespace loom;
using namespace loom::quadmap;

namespace {

/// The same map with vertices renamed, each quad read from another corner and the quads shuffled.
QuadMap scrambled(const QuadMap& m, std::mt19937& rng) {
  std::vector<Vertex> name(m.vertex_bound);
  std::iota(name.begin(), name.end(), 0u);
  std::shuffle(name.begin(), name.end(), rng);
  QuadMap out{{}, m.vertex_bound};
  for (const Quad& q : m.quads) {
    const auto r = static_cast<int>(rng() % 4);
    out.quads.push_back({name[q[r % 4]], name[q[(r + 1) % 4]], name[q[(r + 2) % 4]], name[q[(r + 3) % 4]]});
  }
  std::shuffle(out.quads.begin(), out.quads.end(), rng);
  return out;
}

/// nauty's canonical form of the map as a coloured digraph: a vertex per dart
/// (colour 0) with an arc to the next dart of its quad, and a vertex per edge
/// (colour 1) joined both ways to its two darts. Isomorphisms of this graph
/// are the orientation-preserving isomorphisms of the map.
struct NautyForm {
  std::vector<setword> canonical;
  double automorphisms = 0;
};

NautyForm nauty_form(const QuadMap& m) {
  const auto twin = twins(m);
  const int darts = static_cast<int>(4 * m.size()), n = darts + darts / 2;
  const int words = SETWORDSNEEDED(n);
  std::vector<setword> g(static_cast<std::size_t>(words) * n, 0), canon(g.size(), 0);
  auto arc = [&](int from, int to) { ADDELEMENT(GRAPHROW(g.data(), from, words), to); };
  int edge = darts;
  for (int d = 0; d < darts; ++d) {
    arc(d, static_cast<int>(next_in_quad(static_cast<Dart>(d))));
    if (static_cast<int>(twin[static_cast<std::size_t>(d)]) > d) {
      for (int x : {d, static_cast<int>(twin[static_cast<std::size_t>(d)])}) {
        arc(edge, x);
        arc(x, edge);
      }
      ++edge;
    }
  }
  std::vector<int> lab(static_cast<std::size_t>(n)), ptn(static_cast<std::size_t>(n), 1), orbits(static_cast<std::size_t>(n));
  std::iota(lab.begin(), lab.end(), 0);
  ptn[static_cast<std::size_t>(darts - 1)] = 0;
  ptn[static_cast<std::size_t>(n - 1)] = 0;
  DEFAULTOPTIONS_DIGRAPH(options);
  options.getcanon = TRUE;
  options.defaultptn = FALSE;
  statsblk stats;
  densenauty(g.data(), lab.data(), ptn.data(), orbits.data(), &options, &stats, words, n, canon.data());
  return {canon, stats.grpsize1 * std::pow(10.0, stats.grpsize2)};
}

std::vector<setword> nauty_canonical(const QuadMap& m) { return nauty_form(m).canonical; }

}  // namespace

TEST_CASE("the enumerator finds every simple quadrangulation with degrees >= 3, and the 3-connected ones") {
  // OEIS A078666 and A007022, from 6 quads (reflections identified).
  const std::map<int, std::pair<std::size_t, std::size_t>> known{
      {6, {1, 1}},    {7, {0, 0}},    {8, {1, 1}},     {9, {1, 1}},     {10, {3, 3}},   {11, {3, 3}},
      {12, {12, 11}}, {13, {19, 18}}, {14, {64, 58}},  {15, {155, 139}}, {16, {510, 451}}};
  const auto classes = enumerate_quadrangulations(16);
  REQUIRE(classes.size() == known.size());
  for (const auto& c : classes) {
    CAPTURE(c.quads);
    const auto [all, three] = known.at(c.quads);
    CHECK(c.codes.size() == all);
    CHECK(static_cast<std::size_t>(std::count(c.three_connected.begin(), c.three_connected.end(), true)) == three);
    for (const Code& code : c.codes) {
      const QuadMap m = map_of_code(code);
      CHECK(why_not_simple(m).empty());
      CHECK(canonical_unoriented(m).code == code);
    }
  }
  // The even 3-connected ones with 6 to 16 quads: the 525 of the closure corpus.
  std::size_t even = 0;
  for (int f = 6; f <= 16; f += 2) even += three_connected_quadrangulations(f).size();
  CHECK(even == 525);
}

TEST_CASE("canonical codes do not depend on how a map is written, and tell maps apart as nauty does") {
  std::mt19937 rng(7);
  std::vector<QuadMap> maps;
  for (const auto& c : enumerate_quadrangulations(14))
    for (const Code& code : c.codes) maps.push_back(map_of_code(code));
  REQUIRE(maps.size() == 104);
  std::set<std::vector<setword>> nauty_classes;
  std::size_t chiral = 0;
  for (const QuadMap& m : maps) {
    const Canonical own = canonical_oriented(m), mirror = canonical_oriented(mirrored(m));
    for (int trial = 0; trial < 3; ++trial) {
      const QuadMap s = scrambled(m, rng);
      CHECK(canonical_oriented(s).code == own.code);
      CHECK(canonical_oriented(mirrored(s)).code == mirror.code);
      CHECK(nauty_canonical(s) == nauty_canonical(m));
    }
    // Chiral exactly when nauty finds the map and its mirror image different.
    const bool nauty_chiral = nauty_canonical(m) != nauty_canonical(mirrored(m));
    CHECK((own.code != mirror.code) == nauty_chiral);
    chiral += nauty_chiral;
    nauty_classes.insert(std::min(nauty_canonical(m), nauty_canonical(mirrored(m))));
    // One start dart per orientation-preserving automorphism: as many as the
    // automorphism group nauty finds has elements.
    CHECK(static_cast<double>(own.starts.size()) == nauty_form(m).automorphisms);
  }
  CHECK(nauty_classes.size() == maps.size());  // the enumerator's classes are distinct for nauty too
  CHECK(chiral > 0);
}

TEST_CASE("automorphisms map quads onto quads, one per canonical start dart, and fall into conjugacy classes") {
  auto is_automorphism = [](const QuadMap& m, const Permutation& p) {
    std::set<std::vector<Vertex>> quads;  // each read from its least corner
    auto read = [](Quad q) {
      std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
      return std::vector<Vertex>(q.begin(), q.end());
    };
    for (const Quad& q : m.quads) quads.insert(read(q));
    return std::all_of(m.quads.begin(), m.quads.end(),
                       [&](const Quad& q) { return quads.count(read({p[q[0]], p[q[1]], p[q[2]], p[q[3]]})) > 0; });
  };
  for (const auto& [m, count] : std::vector<std::pair<QuadMap, std::size_t>>{
           {pseudo_double_wheel(6), 24}, {pseudo_double_wheel(16), 16}, {pseudo_double_wheel(10), 10}}) {
    const auto group = automorphisms(m);
    REQUIRE(group.size() == count);
    CHECK(group.size() == canonical_oriented(m).starts.size());
    CHECK(order_of(group.front()) == 1);
    CHECK(std::set<Permutation>(group.begin(), group.end()).size() == group.size());
    for (const Permutation& p : group) CHECK(is_automorphism(m, p));
  }
  // The octagonal trapezohedron: rotations about its axis of order 2, 4 and
  // 8, and 8 half-turns about axes across it, which fall into two classes
  // (through opposite edges, and through the other opposite edges).
  const auto group = automorphisms(pseudo_double_wheel(16));
  std::map<int, int> by_order;
  std::vector<Permutation> half_turns;
  for (const Permutation& p : group) {
    ++by_order[order_of(p)];
    if (order_of(p) == 2) half_turns.push_back(p);
  }
  CHECK(by_order == std::map<int, int>{{1, 1}, {2, 9}, {4, 2}, {8, 4}});
  CHECK(up_to_conjugacy(half_turns, group).size() == 3);
  // The cube: 3 half-turns about face axes, 6 about edge axes.
  const auto cube = automorphisms(pseudo_double_wheel(6));
  std::vector<Permutation> cube_half_turns;
  for (const Permutation& p : cube)
    if (order_of(p) == 2) cube_half_turns.push_back(p);
  CHECK(cube_half_turns.size() == 9);
  CHECK(up_to_conjugacy(cube_half_turns, cube).size() == 2);
}

TEST_CASE("simplicity and properness name what is wrong") {
  QuadMap cube = pseudo_double_wheel(6);
  CHECK(why_not_proper(cube).empty());
  CHECK(is_three_connected(cube));
  QuadMap open = cube;
  open.quads.pop_back();
  CHECK(why_not_simple(open).find("is open") != std::string::npos);
  QuadMap repeated = cube;
  repeated.quads[0][1] = repeated.quads[0][0];
  CHECK(why_not_simple(repeated).find("repeats vertex") != std::string::npos);
  // Two cubes glued on a face make a degree-2-free map; a pillow (two quads on
  // the same four vertices) has vertices of degree 2.
  QuadMap pillow{{{0, 1, 2, 3}, {0, 3, 2, 1}}, 4};
  CHECK(why_not_simple(pillow).find("fewer than 3") != std::string::npos);
}

TEST_CASE("gluing a hex changes the quad count by 6 - 2k and keeps the map closed") {
  const QuadMap cube = pseudo_double_wheel(6);
  GluedHex g;
  // Every corner of the cube has degree 3: only a hex on one quad can go on.
  for (std::uint8_t sides = 1; sides < 16; ++sides)
    CHECK_FALSE(glue_hex(cube, twins(cube), degrees(cube), {0, sides}, g));
  REQUIRE(glue_hex(cube, twins(cube), degrees(cube), {0, 0}, g));
  CHECK(g.k == 1);
  CHECK(g.after.size() == 10);
  CHECK(why_not_proper(g.after).empty());
  // From the 10 quads, the hex on the quad just made glues back as a cup (k = 5)... not
  // allowed: the four corners of the inner quad would keep degree 2. A strip
  // of three round the box's long side is.
  const QuadMap box = from_surface(gen::box(2, 1, 1));
  std::size_t by_k[6] = {};
  for (std::uint32_t q = 0; q < box.size(); ++q)
    for (std::uint8_t sides = 0; sides < 16; ++sides)
      if (glue_hex(box, twins(box), degrees(box), {q, sides}, g) && why_not_proper(g.after).empty()) {
        ++by_k[g.k];
        CHECK(g.after.size() + 2 * static_cast<std::size_t>(g.k) == box.size() + 6);
      }
  CHECK(by_k[1] == 10);  // a pillow on each quad
  CHECK(by_k[5] == 2);   // the two cups that leave one cube
  Hex last;
  CHECK(fill_cube(cube, twins(cube), last));
  CHECK_FALSE(fill_cube(box, twins(box), last));
}

TEST_CASE("twins and degrees after a gluing, updated from before, are those of the map after") {
  // A walk of random proper gluings down several maps; at each step the
  // updates must agree with twins() and degrees() of the map rebuilt.
  std::mt19937 rng(11);
  std::size_t compared = 0, open_edges_matched = 0;
  for (const QuadSurface& surface : {gen::box(3, 2, 2), gen::randquad(60, 4), gen::cubesphere(3)}) {
    QuadMap m = from_surface(surface);
    auto twin = twins(m);
    auto degree = degrees(m);
    for (int step = 0; step < 40 && m.size() > 6; ++step) {
      GluedHex g;
      bool glued = false;
      for (int tries = 0; tries < 400 && !glued; ++tries) {
        const Gluing at{static_cast<std::uint32_t>(rng() % m.size()), static_cast<std::uint8_t>(rng() % 16)};
        glued = glue_hex(m, twin, degree, at, g) && why_not_proper(g.after).empty();
      }
      if (!glued) break;
      const auto updated_twin = twins_after_gluing(m, twin, g);
      const auto updated_degree = degrees_after_gluing(m, degree, g);
      CHECK(updated_twin == twins(g.after));
      CHECK(updated_degree == degrees(g.after));
      for (auto q = static_cast<std::uint32_t>(m.size() - static_cast<std::size_t>(g.k)); q < g.after.size(); ++q)
        open_edges_matched += updated_twin[4 * q] != no_dart;
      m = g.after;
      twin = updated_twin;
      degree = updated_degree;
      ++compared;
    }
  }
  CHECK(compared >= 60);
  CHECK(open_edges_matched > 0);
}

TEST_CASE("twins are found alike whether vertex ids are dense or sparse, and mirrored from the map's") {
  std::mt19937 rng(7);
  // Spread ids far apart: twins() then sorts instead of counting per vertex.
  auto sparse = [](QuadMap m) {
    for (Quad& q : m.quads)
      for (Vertex& v : q) v = 1000 * v + 7;
    m.vertex_bound = 1000 * m.vertex_bound + 7;
    return m;
  };
  std::vector<QuadMap> maps{pseudo_double_wheel(6), pseudo_double_wheel(12), from_surface(gen::box(3, 2, 1))};
  maps.push_back(scrambled(maps.back(), rng));
  // Open, with an edge run twice, and with a quad run the wrong way.
  QuadMap open = maps[1];
  open.quads.pop_back();
  QuadMap doubled = maps[2];
  doubled.quads.push_back(doubled.quads[0]);
  doubled.quads.push_back(doubled.quads[5]);
  QuadMap flipped = maps[2];
  std::reverse(flipped.quads[3].begin(), flipped.quads[3].end());
  for (const QuadMap& m : {open, doubled, flipped}) maps.push_back(m);
  for (std::size_t i = 0; i < maps.size(); ++i) {
    CAPTURE(i);
    Dart dense_duplicate = no_dart, sparse_duplicate = no_dart;
    const auto dense = twins(maps[i], &dense_duplicate);
    CHECK(dense == twins(sparse(maps[i]), &sparse_duplicate));
    CHECK(dense_duplicate == sparse_duplicate);
    CHECK((dense_duplicate != no_dart) == (i == 5 || i == 6));
    // Each twin runs its dart backwards; a closed map pairs every dart.
    for (Dart d = 0; d < dense.size(); ++d) {
      if (dense[d] == no_dart) continue;
      CHECK(maps[i].tail(dense[d]) == maps[i].head(d));
      CHECK(maps[i].head(dense[d]) == maps[i].tail(d));
    }
    if (i < 4) CHECK(std::count(dense.begin(), dense.end(), no_dart) == 0);
    if (i < 5) CHECK(mirrored_twins(dense) == twins(mirrored(maps[i])));
  }
}
