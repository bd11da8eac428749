// The STC graph built from hex meshes and from quad surfaces; primal
// construction; invariants; Boost.Graph algorithms on the STC.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/vf2_sub_graph_iso.hpp>
#include <gmsh.h>

#include "engine/graph_traits.hpp"
#include "src/gen/generators.hpp"
#include "src/io/gmsh_session.hpp"
#include "src/io/hex_io.hpp"
#include "tests/support.hpp"
#include "src/stc/build.hpp"
#include "src/stc/loops.hpp"
#include "src/stc/primal.hpp"
#include "src/stc/summary.hpp"

using namespace loom;
using namespace loom::stc;

namespace {
/// An unstructured hex mesh: Gmsh tetrahedralizes a box and splits every tet
/// into four hexes (Mesh.SubdivisionAlgorithm = 2); written as MSH and read back.
HexMesh gmsh_tet_split_box() {
  loom::test::ScratchDir dir("tetsplit");
  auto file = dir / "tetsplit.msh";
  run_gmsh_isolated("tet-split box", "", [&] {
    gmsh::model::add("tetsplit");
    gmsh::model::occ::addBox(0, 0, 0, 1, 1.5, 2);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.6);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 2);
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(file.string());
    return std::string();
  });
  return read_hex_mesh(file);
}
}  // namespace

TEST_CASE("the STC of a structured hex grid") {
  Stc stc = build_from_hex_mesh(gen::hexgrid(3, 4, 5));
  CHECK(stc.check_invariants() == "");
  CHECK(stc.hexes() == 60);
  CHECK(stc.sheets() == 12);  // 3 + 4 + 5 layers
  CHECK(stc.chords() == 47);  // 3*4 + 4*5 + 5*3 columns
  CHECK(stc.nodes() == 4 * 5 * 6);
  CHECK(stc.whiskers() == 0);
  StcSummary s = summarize(stc);
  CHECK(s.boundary_faces == 2 * (12 + 20 + 15));
  CHECK(s.loops == 12);
  CHECK(s.self_intersecting_sheets == 0);
  CHECK(s.self_intersecting_chords == 0);
  // Every chord joins two boundary faces: a hex grid has no closed chord.
  std::map<Id, int> ends;
  for (Id f : stc.graph().members(stc.ids().face))
    if (stc.is_boundary(f)) ++ends[stc.face_chord(f)];
  for (auto& [c, n] : ends) CHECK(n == 2);
}

TEST_CASE("navigation: opposite faces, faces across an edge, sides") {
  Stc stc = build_from_hex_mesh(gen::hexgrid(2, 1, 1));
  auto hexes = stc.graph().members(stc.ids().hex);
  REQUIRE(hexes.size() == 2);
  Id h0 = hexes[0], h1 = hexes[1];
  // Hex 0 spans x in [0,1]; its +x face (slot 5) is shared with hex 1's -x face (slot 4).
  Id shared = stc.hex_face(h0, 5);
  CHECK(stc.hex_face(h1, 4) == shared);
  CHECK(stc.across(shared, h0) == h1);
  CHECK(stc.face_cell(shared, 0) == h0);  // h0 sees the stored cycle outward
  CHECK(stc.face_cell(shared, 1) == h1);
  CHECK(stc.opposite_face(h0, 5) == stc.hex_face(h0, 4));
  CHECK(stc.face_chord(stc.hex_face(h0, 4)) == stc.face_chord(stc.hex_face(h1, 5)));
  Id e = stc.face_edge(shared, 0);
  Id next = stc.face_across_edge(h0, shared, e);
  CHECK(next != no_element);
  CHECK(next != shared);
  CHECK(stc.slot_in_face(next, e) < 4);
}

TEST_CASE("the initial weave state of a box surface") {
  Stc stc = build_from_surface(gen::box(3, 4, 5));
  CHECK(stc.check_invariants() == "");
  CHECK(stc.hexes() == 0);
  CHECK(stc.faces() == 94);
  CHECK(stc.sheets() == 12);
  CHECK(stc.chords() == 94);  // one whisker chord per boundary face
  CHECK(stc.whiskers() == 94);
  auto loops = trace_loops(stc);
  CHECK(loops.size() == 12);
  std::size_t edges_on_loops = 0;
  for (auto& l : loops) {
    edges_on_loops += l.edges.size();
    CHECK(l.self_crossings() == 0);
    // Consecutive loop faces share the loop edge between them.
    for (std::size_t i = 0; i < l.faces.size(); ++i) {
      CHECK(stc.slot_in_face(l.faces[i], l.edges[i]) < 4);
      CHECK(stc.slot_in_face(l.faces[i], l.edges[(i + 1) % l.edges.size()]) < 4);
    }
  }
  CHECK(edges_on_loops == stc.edges());
}

TEST_CASE("Schneiders' pyramid: two loops, one crossing itself in 8 quads") {
  Stc stc = build_from_surface(gen::schneiders());
  StcSummary s = summarize(stc);
  CHECK(s.loops == 2);
  CHECK(s.self_intersecting_sheets == 1);
  std::vector<std::pair<std::size_t, std::size_t>> lengths;
  for (auto& sh : s.sheet_list) lengths.push_back({sh.loop_length, sh.self_crossing_quads});
  std::sort(lengths.begin(), lengths.end());
  CHECK(lengths == std::vector<std::pair<std::size_t, std::size_t>>{{8, 0}, {24, 8}});
}

TEST_CASE("round trip: hex mesh -> STC -> hex mesh is the identity") {
  SUBCASE("structured grids") {
    for (auto [a, b, c] : {std::array{1, 1, 1}, std::array{3, 4, 5}, std::array{2, 1, 6}}) {
      HexMesh m = gen::hexgrid(a, b, c);
      HexMesh back = to_hex_mesh(build_from_hex_mesh(m));
      CHECK(back.points == m.points);
      CHECK(back.hexes == m.hexes);
    }
  }
  SUBCASE("an unstructured mesh: Gmsh's tetrahedra split into hexes") {
    HexMesh m = gmsh_tet_split_box();
    REQUIRE(m.hexes.size() > 100);
    Stc stc = build_from_hex_mesh(m);
    CHECK(stc.check_invariants() == "");
    HexMesh back = to_hex_mesh(stc);
    CHECK(back.points == m.points);
    CHECK(back.hexes == m.hexes);
  }
}

TEST_CASE("invariants catch a broken STC") {
  Stc stc = build_from_hex_mesh(gen::hexgrid(2, 2, 1));
  const auto& ids = stc.ids();
  Id h = stc.graph().members(ids.hex)[0];
  SUBCASE("a face that forgot its chord") {
    stc.graph().link(stc.hex_face(h, 0), ids.face_chord, 0, no_element);
    CHECK(stc.check_invariants().find("lies on no chord") != std::string::npos);
  }
  SUBCASE("opposite faces on different chords") {
    Id other = stc.face_chord(stc.hex_face(h, 2));
    stc.graph().link(stc.hex_face(h, 0), ids.face_chord, 0, other);
    CHECK_FALSE(stc.check_invariants().empty());
  }
  SUBCASE("a hex pointing at a face that does not point back") {
    Id h2 = stc.graph().members(ids.hex)[3];
    stc.graph().link(h, ids.hex_face, 0, stc.hex_face(h2, 1));
    CHECK_FALSE(stc.check_invariants().empty());
  }
}

TEST_CASE("Boost.Graph algorithms on the STC") {
  Stc stc = build_from_hex_mesh(gen::hexgrid(2, 1, 1));
  const engine::Graph& g = stc.graph();
  SUBCASE("breadth_first_search from a hex reaches the whole two-hex STC") {
    std::vector<boost::default_color_type> color(num_vertices(g));
    std::map<engine::KindId, int> reached;
    struct Visitor : boost::default_bfs_visitor {
      std::map<engine::KindId, int>* out;
      void discover_vertex(Id v, const engine::Graph& gr) const { ++(*out)[gr.kind(v)]; }
    } vis;
    vis.out = &reached;
    boost::breadth_first_search(g, g.members(stc.ids().hex)[0], boost::visitor(vis).color_map(color.data()));
    // Out-edges: hex -> face -> edge/node/chord/cell, so the other hex is
    // reached through the shared face, and from there everything.
    CHECK(reached[stc.ids().hex] == 2);
    CHECK(reached[stc.ids().face] == 11);
    CHECK(reached[stc.ids().edge] == 20);
    CHECK(reached[stc.ids().node] == 12);
    CHECK(reached[stc.ids().chord] == 5);
    CHECK(reached[stc.ids().sheet] == 4);
  }
  SUBCASE("vf2_subgraph_mono counts hexes sharing a face") {
    using Pattern = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, engine::KindId>;
    Pattern p;
    auto a = boost::add_vertex(stc.ids().hex, p), f = boost::add_vertex(stc.ids().face, p),
         b = boost::add_vertex(stc.ids().hex, p);
    boost::add_edge(a, f, p);
    boost::add_edge(b, f, p);
    int n = 0;
    boost::vf2_subgraph_mono(
        p, g, [&](auto&&, auto&&) { return ++n, true; }, boost::vertex_order_by_mult(p),
        boost::vertices_equivalent([&](Pattern::vertex_descriptor x, Id y) { return p[x] == g.kind(y); }));
    CHECK(n == 2);  // one interior face, two orders of its hexes
  }
}
