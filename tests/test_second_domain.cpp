// engine/ is generic: a second rewriting domain, edge flips of a triangle
// surface, runs through the same engine with its schema and its rule given as
// data (examples/trimesh/), and no C++ of its own but this test's checks.
#include <doctest/doctest.h>

#include <array>
#include <map>
#include <set>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "engine/schema_file.hpp"
#include "src/gen/generators.hpp"
#include "tests/support.hpp"

using namespace loom;
using engine::Id;

namespace {

const std::string kDomain = std::string(LOOM_SOURCE_DIR) + "/examples/trimesh";

struct TriKinds {
  engine::KindId vertex, edge, triangle;
  engine::PortId edge_vertex, tri_vertex, tri_edge;
  engine::AttrId degree;
  explicit TriKinds(const engine::Schema& s)
      : vertex(*s.find_kind("vertex")), edge(*s.find_kind("edge")), triangle(*s.find_kind("triangle")),
        edge_vertex(*s.find_port(edge, "vertex")), tri_vertex(*s.find_port(triangle, "vertex")),
        tri_edge(*s.find_port(triangle, "edge")), degree(*s.find_attribute(vertex, "degree")) {}
};

/// A quad surface with every quad cut along the diagonal from its corner 0.
engine::Graph triangulated(const QuadSurface& surface, const std::shared_ptr<const engine::Schema>& schema) {
  const TriKinds k(*schema);
  engine::Graph g(schema);
  std::vector<Id> vertex;
  for (std::size_t i = 0; i < surface.points.size(); ++i) vertex.push_back(g.add(k.vertex));
  std::map<std::pair<std::uint32_t, std::uint32_t>, Id> edges;
  auto edge = [&](std::uint32_t u, std::uint32_t v) {
    auto key = std::minmax(u, v);
    auto [it, fresh] = edges.try_emplace({key.first, key.second}, engine::no_element);
    if (fresh) {
      it->second = g.add(k.edge);
      g.link(it->second, k.edge_vertex, 0, vertex[u]);
      g.link(it->second, k.edge_vertex, 1, vertex[v]);
      for (std::uint32_t w : {u, v}) g.set(vertex[w], k.degree, g.get(vertex[w], k.degree) + 1);
    }
    return it->second;
  };
  for (const Quad& q : surface.quads)
    for (std::array<std::uint32_t, 3> t : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
      Id tri = g.add(k.triangle);
      for (unsigned i = 0; i < 3; ++i) {
        g.link(tri, k.tri_vertex, i, vertex[t[i]]);
        g.link(tri, k.tri_edge, i, edge(t[i], t[(i + 1) % 3]));
      }
    }
  return g;
}

/// Empty when the graph is a closed, simple, consistently linked triangle
/// surface of genus 0 whose degree attributes count the edges.
std::string broken(const engine::Graph& g) {
  const TriKinds k(g.schema());
  std::map<Id, int> degree, uses;
  std::set<std::pair<Id, Id>> pairs;
  for (Id e : g.members(k.edge)) {
    Id u = g.at(e, k.edge_vertex, 0), v = g.at(e, k.edge_vertex, 1);
    if (u == v) return "an edge joins a vertex to itself";
    if (!pairs.insert(std::minmax(u, v)).second) return "two edges join the same vertices";
    ++degree[u], ++degree[v];
  }
  for (Id t : g.members(k.triangle))
    for (unsigned i = 0; i < 3; ++i) {
      Id e = g.at(t, k.tri_edge, i), a = g.at(t, k.tri_vertex, i), b = g.at(t, k.tri_vertex, (i + 1) % 3);
      if (std::minmax(a, b) != std::minmax(g.at(e, k.edge_vertex, 0), g.at(e, k.edge_vertex, 1)))
        return "a triangle's edge does not join its corners";
      ++uses[e];
    }
  for (Id e : g.members(k.edge))
    if (uses[e] != 2) return "an edge is not on two triangles";
  for (Id v : g.members(k.vertex))
    if (g.get(v, k.degree) != degree[v]) return "a degree attribute is wrong";
  const long euler = long(g.size(k.vertex)) - long(g.size(k.edge)) + long(g.size(k.triangle));
  return euler == 2 ? "" : "the Euler characteristic is not 2";
}

long sum_of_squared_degrees(const engine::Graph& g) {
  const TriKinds k(g.schema());
  long sum = 0;
  for (Id v : g.members(k.vertex)) sum += long(g.get(v, k.degree)) * g.get(v, k.degree);
  return sum;
}

/// Edges the rule should still flip (checked by brute force, not by the engine).
std::size_t flippable(const engine::Graph& g) {
  const TriKinds k(g.schema());
  std::set<std::pair<Id, Id>> pairs;
  for (Id e : g.members(k.edge)) pairs.insert(std::minmax(g.at(e, k.edge_vertex, 0), g.at(e, k.edge_vertex, 1)));
  std::map<Id, std::vector<Id>> opposite;  // edge -> the corners across it
  for (Id t : g.members(k.triangle))
    for (unsigned i = 0; i < 3; ++i) opposite[g.at(t, k.tri_edge, i)].push_back(g.at(t, k.tri_vertex, (i + 2) % 3));
  std::size_t n = 0;
  for (Id e : g.members(k.edge)) {
    Id a = g.at(e, k.edge_vertex, 0), b = g.at(e, k.edge_vertex, 1), c = opposite[e][0], d = opposite[e][1];
    auto deg = [&](Id v) { return g.get(v, k.degree); };
    n += deg(a) + deg(b) - deg(c) - deg(d) > 2 && deg(a) > 3 && deg(b) > 3 && !pairs.count(std::minmax(c, d));
  }
  return n;
}

}  // namespace

TEST_CASE("edge flips of a triangle surface: schema and rule from files, run to normal form by the engine") {
  const auto schema = engine::load_schema(kDomain + "/schema.txt");
  const auto rules = engine::load_rule_dir(kDomain, *schema);
  REQUIRE(rules.size() == 1);
  for (const QuadSurface& surface : {gen::randquad(30, 1), gen::randquad(60, 2), gen::randquad(100, 3)}) {
    engine::Graph g = triangulated(surface, schema);
    REQUIRE(broken(g).empty());
    const long before = sum_of_squared_degrees(g);
    const std::size_t to_flip = flippable(g);
    CHECK(to_flip > 0);
    engine::Engine eng(g, rules, {}, {});
    std::vector<Id> flipped;
    engine::Application step;
    while (eng.step(&step)) flipped.push_back(step.matched.anchor());
    CHECK(flipped.size() > 0);
    CHECK(broken(g) == "");
    CHECK(flippable(g) == 0);                         // a normal form
    CHECK(sum_of_squared_degrees(g) < before);  // each flip lowered it

    // The same graph and rule give the same flips, and the incremental
    // matcher the same as offering every edge again after every flip.
    engine::Graph again = triangulated(surface, schema);
    engine::Engine full(again, rules, {}, {});
    full.set_full_rescan(true);
    std::vector<Id> flipped_again;
    while (full.step(&step)) flipped_again.push_back(step.matched.anchor());
    CHECK(flipped_again == flipped);
  }
}

TEST_CASE("a broken schema file is refused at its line and column") {
  auto error = [](const std::string& text) {
    try {
      engine::parse_schema(text, "s.txt");
    } catch (const engine::RuleError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error("kind v\nport v.next 2 -> w\n") == "s.txt:2:18: unknown kind 'w' (declare it first with 'kind w')");
  CHECK(error("kind v\nport v.next two -> v\n") == "s.txt:2:13: expected a number of slots (1 to 255), found 'two'");
  CHECK(error("kind v\nport v.next 2 sideways -> v\n") == "s.txt:2:15: expected 'cyclic', 'required' or '->', found 'sideways'");
  CHECK(error("kind v\nkind v\n") == "s.txt:2:6: kind 'v' declared twice");
  CHECK(error("kind v\nattribute v.x 1.5\n") == "s.txt:2:15: expected a 32-bit integer default, found '1.5'");
  CHECK(error("kind v\nattribute vx\n") == "s.txt:2:11: expected OWNER.NAME, e.g. triangle.vertex, found 'vx'");
  CHECK(error("kind v extra\n") == "s.txt:1:8: unexpected 'extra' at the end of the line");
  CHECK(error("# nothing\n") == "s.txt: the schema declares no kind; write 'kind NAME' lines");
  CHECK(error("edge v\n") == "s.txt:1:1: expected 'kind', 'port' or 'attribute', found 'edge'");
  // A rule written against the file's schema is checked against it.
  const auto schema = engine::parse_schema("kind v\nport v.next 1 -> v\n", "s.txt");
  CHECK_THROWS_WITH_AS(engine::compile_rules("rule r { match { x: hex } }", "r.rule", *schema),
                       "r.rule:1:18: expected a kind (v), found 'hex'", engine::RuleError);
}
