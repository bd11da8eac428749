// The degeneracy and expansion rules of rules/, each on a tiny hand-built
// state: the rule file is loaded as shipped and applied by the engine, and
// the state after it is checked. With LOOM_DOC_PICTURES=DIR set, every case
// also writes DIR/NAME-before.dot and DIR/NAME-after.dot (hexes and faces;
// what the step made is highlighted), the pictures of docs/degeneracies.md
// (scripts/degeneracy-pictures.sh renders them).
#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "engine/dot.hpp"
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "src/check/hex_boundary.hpp"
#include "src/check/validity.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/improper.hpp"
#include "src/weave/pillow.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

/// The shipped rules named (file names without .rule), as the engine loads them.
std::vector<engine::Rule> shipped(std::initializer_list<const char*> names) {
  std::vector<engine::Rule> out;
  for (const char* name : names) {
    auto file = weave::default_rules_dir() / (std::string(name) + ".rule");
    auto rules = engine::compile_rules(test::slurp(file), file.string(), *stc::StcSchema::get().schema);
    out.insert(out.end(), rules.begin(), rules.end());
  }
  return out;
}

/// A rule of rules/insertions/ (not in the shipped set).
std::vector<engine::Rule> insertion(const std::string& name) {
  auto file = weave::default_rules_dir() / "insertions" / (name + ".rule");
  return engine::compile_rules(test::slurp(file), file.string(), *stc::StcSchema::get().schema);
}

/// A rule of rules/report/: the report's own operations, beside the shipped prevention.
std::vector<engine::Rule> report_rule(const std::string& name) {
  auto file = weave::default_rules_dir() / "report" / (name + ".rule");
  return engine::compile_rules(test::slurp(file), file.string(), *stc::StcSchema::get().schema);
}

/// Runs `rules` until none applies; returns the applications by rule name.
std::map<std::string, std::size_t> run(stc::Stc& s, std::vector<engine::Rule> rules, std::size_t max_steps = 1000) {
  engine::Engine eng(s.graph(), std::move(rules), weave::weave_actions(s));
  for (std::size_t i = 0; i < max_steps && eng.step(); ++i) REQUIRE(s.check_invariants() == "");
  return eng.applications();
}

/// Hexes and faces as DOT (only the hexes in `only` and their faces, when
/// given); elements with ids from `first_new` on are highlighted.
void picture(const stc::Stc& s, const std::string& name, engine::Id first_new = engine::no_element,
             const std::vector<engine::Id>& only = {}) {
  const char* dir = std::getenv("LOOM_DOC_PICTURES");
  if (!dir) return;
  const auto& g = s.graph();
  const auto& ids = s.ids();
  engine::DotStyle style;
  style.graph_name = name;
  style.layout = "neato";
  std::vector<engine::Id> shown;
  if (only.empty())
    for (auto kind : {ids.hex, ids.face})
      for (engine::Id e : g.members(kind)) shown.push_back(e);
  for (engine::Id h : only) {
    shown.push_back(h);
    for (unsigned i = 0; i < 6; ++i) shown.push_back(s.hex_face(h, i));
  }
  for (engine::Id e : shown) {
    style.only.insert(e);
    if (first_new != engine::no_element && e >= first_new) style.highlight.insert(e);
  }
  style.label = [&](engine::Id e) -> std::string {
    if (g.kind(e) == ids.hex) return fmt::format("hex {}", e);
    return s.is_boundary(e) ? fmt::format("quad {}", s.boundary_index(e)) : fmt::format("face {}", e);
  };
  std::ofstream out(std::filesystem::path(dir) / (name + ".dot"));
  engine::write_dot(out, g, style);
}

ValidityReport dualize_and_check(const stc::Stc& s, const QuadSurface& surface) {
  HexMesh mesh = stc::to_hex_mesh(s);
  return check_hex_mesh(mesh, &surface);
}

/// Two hexes sharing two faces (VTK faces 0154 and 0374 of the first): a doublet.
HexMesh doublet() {
  HexMesh m = gen::hexgrid(1, 1, 1);
  const Hex& c = m.hexes[0];
  m.points.push_back({1, 1, -1});
  m.points.push_back({1, 1, 2});
  m.hexes.push_back({c[0], c[1], 8, c[3], c[4], c[5], 9, c[7]});
  return m;
}

/// Every edge of a front face lies in exactly two front faces (the front is
/// a closed surface), counted with multiplicity.
bool front_is_closed(const stc::Stc& s) {
  std::map<engine::Id, int> uses;
  for (engine::Id f : s.graph().members(s.ids().face))
    if (s.is_whisker(f))
      for (unsigned k = 0; k < 4; ++k) ++uses[s.face_edge(f, k)];
  for (auto [e, n] : uses)
    if (n != 2) return false;
  return !uses.empty();
}

/// F4: four quads, one loop crossing itself in all four; both valence-2
/// nodes sit between two faces whose seam would fold the other two.
QuadSurface f4() {
  QuadSurface s;
  s.points = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -1}};
  s.quads = {{1, 3, 2, 0}, {5, 3, 1, 4}, {2, 4, 1, 0}, {5, 4, 2, 3}};
  return s;
}

}  // namespace

TEST_CASE("pillow_doublet: two hexes sharing two faces get a pillow around one of them") {
  HexMesh mesh = doublet();
  QuadSurface surface = hex_mesh_boundary(mesh);
  stc::Stc s = stc::build_from_hex_mesh(mesh);
  auto before = check_hex_mesh(mesh, &surface);
  REQUIRE(before.first_failure());
  CHECK(before.first_failure()->number == 3);  // the doublet
  picture(s, "doublet-before");
  engine::Id first_new = s.graph().id_bound();
  auto applied = run(s, shipped({"pillow_doublet"}));
  CHECK(applied["pillow_doublet"] == 1);
  picture(s, "doublet-after", first_new);
  CHECK(s.hexes() == 8);
  // The doublet is gone: no two hexes share two faces, and the edge they
  // shared has three hexes. What is left is the surface's own: its quads at
  // the doublet's ends share two edges, so the hexes on them still meet in
  // three nodes (criterion 3's second half) until hexes are woven beyond them.
  for (engine::Id h : s.graph().members(s.ids().hex)) {
    std::map<engine::Id, int> across;
    for (unsigned i = 0; i < 6; ++i)
      if (engine::Id o = s.across(s.hex_face(h, i), h); o != engine::no_element) CHECK(++across[o] == 1);
  }
  auto after = dualize_and_check(s, surface);
  REQUIRE(after.first_failure());
  CHECK(after.first_failure()->number == 3);
  CHECK(after.first_failure()->detail.find("meet in 3 nodes") != std::string::npos);
}

TEST_CASE("seam_through leaves a through-3-cell; pillow_through_cell pillows it and splits the node") {
  // A U of five hexes whose tips share the node (1,2,0) in place of their own
  // corners (1,2,0) and (2,2,0), as seam_through leaves it: boundary 2.
  HexMesh u = gen::hexgrid(3, 2, 1);
  u.hexes.erase(u.hexes.begin() + 4);
  QuadSurface surface = hex_mesh_boundary(u);
  HexMesh pinched = u;
  for (auto& p : pinched.hexes[4])
    if (p == 10) p = 9;
  stc::Stc s = stc::build_from_hex_mesh(pinched);
  const auto& ids = s.ids();
  for (stc::Id f : s.graph().members(ids.face)) {
    if (!s.is_boundary(f) || s.graph().get(s.face_cell(f, 0), ids.hex_source) != 4) continue;
    for (unsigned k = 0; k < 4; ++k)
      if (s.graph().get(s.face_node(f, k), ids.node_point) == 9) {
        s.boundary_points()[static_cast<std::size_t>(s.boundary_index(f))][k] = 10;
        s.graph().set(s.face_node(f, k), ids.node_boundary, 2);
      }
  }
  CHECK_FALSE(dualize_and_check(s, surface).combinatorial_valid());
  picture(s, "through-cell-before");
  engine::Id first_new = s.graph().id_bound();
  auto applied = run(s, shipped({"pillow_through_cell"}));
  CHECK(applied["pillow_through_cell"] == 1);
  picture(s, "through-cell-after", first_new);
  CHECK(s.hexes() == 5 + 12);
  auto after = dualize_and_check(s, surface);
  CHECK(after.combinatorial_valid());
}

TEST_CASE("seam_through identifies two boundary nodes and counts them; the seams refuse a fold") {
  // randquad 14 s4 under cross, seam and seam_through meets seam_through.
  stc::Stc s = stc::build_from_surface(gen::randquad(14, 4));
  engine::Engine eng(s.graph(), shipped({"cross", "seam", "seam_through"}), weave::weave_actions(s));
  std::size_t through = 0;
  engine::Application app;
  for (int i = 0; i < 2000 && eng.step(&app); ++i) {
    REQUIRE(s.check_invariants() == "");
    if (app.rule->name != "seam_through") continue;
    ++through;
    auto var = [&](const char* name) {
      for (std::size_t v = 0; v < app.rule->vars.size(); ++v)
        if (app.rule->vars[v].name == name) return v;
      return app.rule->vars.size();
    };
    engine::Id a = app.matched.elements[var("a")], b = app.matched.elements[var("b")];
    CHECK(a != b);
    engine::Id kept = s.graph().alive(a) ? a : b;
    CHECK_FALSE(s.graph().alive(a == kept ? b : a));  // one node now, standing for both
    CHECK(s.graph().get(kept, s.ids().node_boundary) >= 2);
  }
  CHECK(through >= 1);  // the rule did meet its case
  // Plain seams never do it: every node still stands for at most one surface node
  // when seam_through is not loaded.
  stc::Stc plain = stc::build_from_surface(gen::randquad(14, 4));
  run(plain, shipped({"cross", "seam"}));
  for (stc::Id n : plain.graph().members(plain.ids().node)) CHECK(plain.graph().get(n, plain.ids().node_boundary) <= 1);

  // F4: the seams at both valence-2 nodes would fold a face (a knife); the
  // seam rules refuse them, so no rule of the two applies.
  stc::Stc t = stc::build_from_surface(f4());
  picture(t, "knife-refused");
  auto none = run(t, shipped({"seam", "seam_through"}));
  CHECK(none.empty());
  CHECK(t.whiskers() == 4);
}

TEST_CASE("pillow_face and wedge change a front that cross and seam leave alone, and it stays closed") {
  for (const char* opener : {"pillow_face", "wedge"}) {
    CAPTURE(opener);
    std::string name = opener;
    // F4 is where the weave of Schneiders' pyramid gets stuck.
    stc::Stc s = stc::build_from_surface(f4());
    picture(s, name + "-before");
    engine::Id first_new = s.graph().id_bound();
    engine::Engine eng(s.graph(), shipped({opener}), weave::weave_actions(s));
    REQUIRE(eng.step());
    CHECK(s.check_invariants() == "");
    picture(s, name + "-after", first_new);
    CHECK(s.hexes() == 1);
    // pillow_face: 1 front face becomes 5; wedge: 2 become 4.
    CHECK(s.whiskers() == (name == "pillow_face" ? 8u : 6u));
    CHECK(front_is_closed(s));
    for (engine::Id n : s.graph().members(s.ids().node)) CHECK(s.graph().get(n, s.ids().node_point) >= 0);
  }
}

TEST_CASE("pillowing the through-cells of degenerate weaves keeps the STC invariants") {
  // Weaves where a pillow sheet met edges the weave had pinched (hexes round
  // one edge in two cycles, or an edge used inside and outside the shrink
  // set without lying on its boundary): the pillow once broke invariant 3.
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  for (auto [faces, seed] : {std::pair{26, 2}, std::pair{38, 1}}) {
    CAPTURE(faces);
    pipeline::MeshingOptions options;
    options.attempts = 2;
    // Checked here after every step, whether or not LOOM_CHECK_INVARIANTS is set.
    std::size_t steps = 0, broken = 0;
    options.weave.after_step = [&](const engine::Application&, const stc::Stc& st) {
      ++steps;
      broken += !st.check_invariants().empty();
    };
    CHECK_NOTHROW(pipeline::mesh_surface(gen::randquad(faces, std::uint64_t(seed)), rules, options));
    CHECK(steps > 0);
    CHECK(broken == 0);
  }
}

TEST_CASE("pillow_improper: a closed weave of Schneiders' pyramid with hexes meeting improperly is pillowed valid") {
  // Seed 176 of the random strategy closes the pyramid in 52 hexes, 31 pairs
  // of which meet improperly (mostly faces a b c d and a b c e sharing two
  // edges); the weave here runs without pillow_improper, then the rule alone.
  std::vector<engine::Rule> without;
  for (auto& r : engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema))
    if (r.name != "pillow_improper") without.push_back(r);
  weave::WeaveOptions options;
  options.strategy = weave::strategy_named("random");
  options.strategy.seed = 176;
  const QuadSurface surface = gen::schneiders();
  stc::Stc s = stc::build_from_surface(surface);
  auto woven = weave::weave(s, without, options);
  REQUIRE(woven.closed);
  CHECK(s.hexes() == 52);
  auto before = dualize_and_check(s, surface);
  REQUIRE(before.first_failure());
  CHECK(before.first_failure()->number == 3);
  CHECK(before.first_failure()->detail.find("31 such pairs") != std::string::npos);
  // The pictures show the first pillow only: the hexes at the node where it
  // parts two hexes, before and after, with the pillow hexes it adds.
  const engine::Id first_new = s.graph().id_bound();
  engine::Id at = engine::no_element;
  {
    engine::Engine eng(s.graph(), shipped({"pillow_improper"}), weave::weave_actions(s));
    engine::Application step;
    std::vector<engine::Id> region;
    std::pair<engine::Id, engine::Id> pair;
    weave::HexCornerCache corners(s);
    for (engine::Id n : s.graph().members(s.ids().node))
      if (auto p = weave::improper_pair_at(s, n, corners)) {
        at = n;
        pair = *p;
        region = weave::hexes_at_node(s, n);
        break;
      }
    REQUIRE(at != engine::no_element);
    picture(s, "improper-before", engine::no_element, region);
    REQUIRE(eng.step(&step));
    REQUIRE(step.matched.elements[step.rule->anchor] == at);  // the lowest node id with an improper pair
    region = weave::hexes_at_node(s, at);
    for (engine::Id e = first_new; e < s.graph().id_bound(); ++e)
      if (s.graph().alive(e) && s.graph().kind(e) == s.ids().hex) region.push_back(e);
    picture(s, "improper-after", first_new, region);
    auto first = weave::complete_hex_corners(s, pair.first), second = weave::complete_hex_corners(s, pair.second);
    REQUIRE((first && second));
    CHECK(weave::stc_hexes_meet_properly(s, pair.first, *first, pair.second, *second));
  }
  auto applied = run(s, shipped({"pillow_improper"}));
  applied["pillow_improper"] += 1;
  CHECK(applied["pillow_improper"] <= 31);  // at least one improper meeting fewer each
  auto after = dualize_and_check(s, surface);
  CHECK(after.combinatorial_valid());
  CHECK(s.hexes() > 52);
}

TEST_CASE("pillow_improper applies nowhere on a valid weave, and the default strategy runs it once the weave has closed") {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  auto r = pipeline::mesh_surface(gen::box(2, 2, 1), rules, {});
  REQUIRE(r.combinatorially_valid());
  CHECK(r.weave.applications.count("pillow_improper") == 0);
  stc::Stc open = stc::build_from_surface(gen::schneiders());
  CHECK(run(open, shipped({"pillow_improper"})).empty());  // every face a whisker: nothing to part yet
  CHECK(open.hexes() == 0);
}

TEST_CASE("hex insertions k = 3 along a strip, 4 (trough) and 5 (cup): one hex glued, nothing placed, the weave goes on") {
  struct Case {
    const char* rule;
    QuadSurface surface;
    std::size_t whiskers_after;  ///< k faces covered, 6 - k made
  };
  for (const Case& c : {Case{"strip", gen::box(3, 1, 2), 22}, Case{"trough", gen::box(2, 1, 2), 14},
                        Case{"cup", gen::box(1, 1, 1), 2}}) {
    CAPTURE(c.rule);
    stc::Stc s = stc::build_from_surface(c.surface);
    const std::size_t nodes = s.graph().size(s.ids().node);
    picture(s, std::string(c.rule) + "-before");
    const engine::Id first_new = s.graph().id_bound();
    engine::Engine eng(s.graph(), insertion(c.rule), weave::weave_actions(s));
    REQUIRE(eng.step());
    CHECK(s.check_invariants() == "");
    picture(s, std::string(c.rule) + "-after", first_new);
    CHECK(s.hexes() == 1);
    CHECK(s.whiskers() == c.whiskers_after);
    CHECK(front_is_closed(s));
    CHECK(s.graph().size(s.ids().node) == nodes);
    // The shipped rules close what is left into a valid mesh.
    run(s, engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema));
    CHECK(s.whiskers() == 0);
    CHECK(dualize_and_check(s, c.surface).combinatorial_valid());
    if (std::string(c.rule) == "cup") CHECK(s.hexes() == 1);  // a seam closed the pocket: the cube itself
  }
}

TEST_CASE("knife_pull_back: where a seam would fold a crossed hex's front face, that hex comes off and the seam goes on") {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  for (auto& r : report_rule("knife_pull_back")) rules.push_back(std::move(r));
  auto count = [](const std::map<std::string, std::size_t>& m, const char* name) {
    auto it = m.find(name);
    return it == m.end() ? std::size_t{0} : it->second;
  };
  std::size_t pulled = 0;
  // Where the bench of the ordering (docs/degeneracies.md) saw it apply.
  for (auto [faces, seed] : {std::pair{18, 8}, {20, 1}, {22, 0}, {22, 6}}) {
    CAPTURE(faces);
    CAPTURE(seed);
    stc::Stc s = stc::build_from_surface(gen::randquad(faces, static_cast<std::uint64_t>(seed)));
    engine::Engine eng(s.graph(), rules, weave::weave_actions(s));
    bool just_pulled = false;
    for (std::size_t step = 0; step < 2000; ++step) {
      const stc::Stc before = s;
      const auto applied = eng.applications();
      if (!eng.step()) break;
      REQUIRE(s.check_invariants() == "");
      if (just_pulled) CHECK(count(eng.applications(), "seam") == count(applied, "seam") + 1);
      just_pulled = count(eng.applications(), "knife_pull_back") > count(applied, "knife_pull_back");
      if (!just_pulled) continue;
      ++pulled;
      // One hex off, its three front faces gone and the three it was glued onto open again.
      CHECK(s.hexes() + 1 == before.hexes());
      CHECK(s.whiskers() == before.whiskers());
      CHECK(s.graph().size(s.ids().node) + 1 == before.graph().size(before.ids().node));
      CHECK(front_is_closed(s));
      engine::Id gone = engine::no_element;
      for (engine::Id h : before.graph().members(before.ids().hex))
        if (!s.graph().alive(h)) gone = h;
      REQUIRE(gone != engine::no_element);
      if (pulled == 1) picture(before, "knife-pull-back", gone, {gone});
    }
  }
  CHECK(pulled >= 4);
}
