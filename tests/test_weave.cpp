// Weaving block shapes with the shipped rules: boxes give exactly the
// structured grid, L-shapes close with good elements, and results are
// deterministic.
#include <doctest/doctest.h>

#include <algorithm>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "src/closure/database.hpp"
#include "src/fill/cap.hpp"
#include "src/gen/generators.hpp"
#include "src/io/hex_io.hpp"
#include "src/stc/build.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {
std::vector<engine::Rule> shipped_rules() {
  return engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
}

pipeline::MeshingResult weave_box(int a, int b, int c) {
  return pipeline::mesh_surface(gen::box(a, b, c), shipped_rules(), {});
}
}  // namespace

TEST_CASE("a box weaves into exactly its structured grid") {
  std::vector<std::array<int, 3>> sizes;
  for (int a = 1; a <= 6; ++a)
    for (int b = 1; b <= 6; ++b)
      for (int c = 1; c <= 6; ++c) sizes.push_back({a, b, c});
  sizes.push_back({2, 3, 5});
  sizes.push_back({1, 1, 8});
  for (auto [a, b, c] : sizes) {
    CAPTURE(a);
    CAPTURE(b);
    CAPTURE(c);
    auto r = weave_box(a, b, c);
    REQUIRE_MESSAGE(r.weave.closed, r.weave.left);
    REQUIRE_MESSAGE(r.mesh.has_value(), r.failure);
    CHECK(r.mesh->hexes.size() == static_cast<std::size_t>(a * b * c));
    CHECK(r.check->combinatorial_valid());
    CHECK(r.check->valid());
    CHECK(r.check->quality.min_scaled_jacobian >= 0.99);
    CHECK(r.stc.check_invariants() == "");
  }
}

TEST_CASE("a 10 x 10 x 10 box") {
  auto r = weave_box(10, 10, 10);
  REQUIRE(r.weave.closed);
  REQUIRE(r.mesh.has_value());
  CHECK(r.mesh->hexes.size() == 1000);
  CHECK(r.check->valid());
  CHECK(r.check->quality.min_scaled_jacobian >= 0.99);
}

TEST_CASE("L-shapes close with good elements") {
  for (int n : {2, 3}) {
    CAPTURE(n);
    auto r = pipeline::mesh_surface(gen::lshape(n), shipped_rules(), {});
    REQUIRE_MESSAGE(r.weave.closed, r.weave.left);
    REQUIRE(r.mesh.has_value());
    CHECK(r.mesh->hexes.size() == static_cast<std::size_t>(3 * n * n * n));
    CHECK(r.check->valid());
    CHECK(r.check->quality.min_scaled_jacobian > 0.5);
  }
}

TEST_CASE("the block-structured bosses close, valid, at two sizes") {
  for (int k : {1, 2}) {
    CAPTURE(k);
    const QuadSurface surface = gen::bosses(k);
    auto r = pipeline::mesh_surface(surface, shipped_rules(), {});
    REQUIRE_MESSAGE(r.weave.closed, r.weave.left);
    REQUIRE(r.mesh.has_value());
    CHECK(r.check->valid());  // criteria 1-7 against the surface: every scaled Jacobian > 0
    CHECK(r.check->quality.min_scaled_jacobian > 0.2);
    CHECK(r.attempts == 1);
    // One placement, the woven mesh's, timed within the whole run.
    CHECK(r.placements == 1);
    CHECK(r.placement_seconds > 0);
    CHECK(r.placement_seconds <= r.seconds);
    MESSAGE("bosses " << k << ": " << r.stc.hexes() << " woven hexes + " << r.boundary_layer.hexes_added
                      << " in the boundary layer, min SJ " << r.check->quality.min_scaled_jacobian);
  }
}

TEST_CASE("the same input, rules and strategy give the same mesh") {
  for (const char* strategy : {"priority", "random"}) {
    CAPTURE(strategy);
    pipeline::MeshingOptions options;
    options.weave.strategy = std::string(strategy) == "random" ? weave::default_strategy().with_random_picks()
                                                               : weave::default_strategy();
    options.weave.strategy.seed = 3;
    auto a = pipeline::mesh_surface(gen::box(3, 2, 2), shipped_rules(), options);
    auto b = pipeline::mesh_surface(gen::box(3, 2, 2), shipped_rules(), options);
    REQUIRE(a.mesh.has_value());
    REQUIRE(b.mesh.has_value());
    CHECK(a.mesh->hexes == b.mesh->hexes);
    CHECK(a.mesh->points == b.mesh->points);
    CHECK(a.weave.applications == b.weave.applications);
  }
}

TEST_CASE("without the seam rule a 2x2x2 box cannot close") {
  auto rules = shipped_rules();
  std::erase_if(rules, [](const engine::Rule& r) { return r.name == "seam"; });
  auto r = pipeline::mesh_surface(gen::box(2, 2, 2), std::move(rules), {});
  CHECK_FALSE(r.weave.closed);
  CHECK(r.weave.left.find("whiskers") != std::string::npos);
  CHECK_FALSE(r.mesh.has_value());
}

TEST_CASE("cross never wraps a hex around the convex corner of another (no triple doublet)") {
  // After the first cross on a box, the new node n has three front faces, all
  // faces of the new hex: front valence 3, yet crossing there would glue a
  // second hex onto three faces of the first.
  stc::Stc stc = stc::build_from_surface(gen::box(2, 2, 2));
  auto rules = shipped_rules();
  engine::Engine eng(stc.graph(), rules, weave::weave_actions(stc), {});
  engine::Application app;
  REQUIRE(eng.step(&app));
  REQUIRE(app.rule->name == "cross");
  int n_var = -1;
  for (int v = 0; v < static_cast<int>(app.rule->vars.size()); ++v)
    if (app.rule->vars[v].name == "n") n_var = v;
  REQUIRE(n_var >= 0);
  engine::Id n = app.result.elements[n_var];
  int front_faces = 0;
  for (engine::SlotId s : stc.graph().incoming(n))
    if (stc.graph().kind(stc.graph().slot_owner(s)) == stc.ids().face) front_faces += stc.is_whisker(stc.graph().slot_owner(s));
  CHECK(front_faces == 3);
  const engine::Rule& cross = *app.rule;
  engine::Matcher matcher(stc.graph());
  engine::Match m;
  CHECK_FALSE(matcher.first_at(cross, n, m));
  // The same rule without its guard would cross there.
  std::string text = "rule unguarded { anchor v match { v: node\n f1, f2, f3: face where self.cell[0] == none\n"
                     " count(face.node -> v where self.cell[0] == none) == 3\n"
                     " f1.node[i] == v  f2.node[j] == v  f3.node[k] == v } }";
  auto unguarded = engine::compile_rules(text, "unguarded.rule", *stc::StcSchema::get().schema);
  CHECK(matcher.first_at(unguarded.front(), n, m));
}

TEST_CASE("each new attempt is told how the one before it ended") {
  // The spindle does not close under the shipped rules: every attempt stops
  // with whiskers left, and the next one is told what they were.
  pipeline::MeshingOptions options;
  options.attempts = 3;
  std::vector<std::size_t> attempts;
  std::vector<weave::WeaveResult> before;
  options.before_attempt = [&](std::size_t attempt, const engine::Strategy& strategy,
                               const weave::WeaveResult& previous) {
    CHECK(strategy.random());
    attempts.push_back(attempt);
    before.push_back(previous);
  };
  auto r = pipeline::mesh_surface(gen::spindle(), shipped_rules(), options);
  REQUIRE_FALSE(r.weave.closed);
  CHECK(r.attempts == 3);
  CHECK(attempts == std::vector<std::size_t>{2, 3});
  REQUIRE(before.size() == 2);
  for (const auto& previous : before) {
    CHECK_FALSE(previous.closed);
    CHECK(previous.whiskers_left > 0);
    CHECK(previous.left.find("whiskers (open front faces) left") != std::string::npos);
  }
}

TEST_CASE("the closure keeps the woven hexes of the attempt that left the fewest whiskers, and says which") {
  // randquad 50 s1 with three attempts: the second leaves the fewest.
  pipeline::MeshingOptions options = pipeline::default_meshing_options();
  options.attempts = 3;
  std::vector<std::size_t> left;
  options.before_attempt = [&](std::size_t, const engine::Strategy&, const weave::WeaveResult& previous) {
    left.push_back(previous.whiskers_left);
  };
  const auto r = pipeline::mesh_surface(gen::randquad(50, 1), shipped_rules(), options);
  left.push_back(r.weave.whiskers_left);
  REQUIRE(r.made_by == "closed");
  REQUIRE(left.size() == 3);
  const auto fewest = static_cast<std::size_t>(std::min_element(left.begin(), left.end()) - left.begin()) + 1;
  REQUIRE(fewest < 3);  // else the fewest could not be told from the last
  CHECK(r.woven_attempt == fewest);
  CHECK(std::count(r.source.begin(), r.source.end(), closure::HexSource::woven) > 0);
}
