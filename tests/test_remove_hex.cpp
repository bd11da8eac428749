// Taking a hex off the weave (src/weave/remove_hex.hpp), and the report's
// triple-doublet deletion that calls it (rules/report/, outside the shipped
// set; docs/degeneracies.md compares it with the shipped prevention).
#include <doctest/doctest.h>

#include <map>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "src/gen/generators.hpp"
#include "src/stc/build.hpp"
#include "src/weave/remove_hex.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

struct Counts {
  std::size_t hexes, faces, edges, nodes, whiskers;
  bool operator==(const Counts&) const = default;
};
Counts counts(const stc::Stc& s) {
  return {s.hexes(), s.faces(), s.edges(), s.nodes(), s.whiskers()};
}

std::size_t applied(const engine::Engine& eng, const std::string& rule) {
  auto it = eng.applications().find(rule);
  return it == eng.applications().end() ? 0 : it->second;
}

/// Every edge of a front face lies in exactly two front faces (`manifold`), or
/// in an even number: the front has no border. Taking off a hex that touches
/// the front only along an edge makes that edge's count four.
bool front_is_closed(const stc::Stc& s, bool manifold = true) {
  std::map<engine::Id, int> uses;
  for (engine::Id f : s.graph().members(s.ids().face))
    if (s.is_whisker(f))
      for (unsigned k = 0; k < 4; ++k) ++uses[s.face_edge(f, k)];
  for (auto [e, n] : uses)
    if (manifold ? n != 2 : n % 2 != 0) return false;
  return !uses.empty();
}

engine::Id newest_hex(const stc::Stc& s) { return s.graph().members(s.ids().hex).back(); }

}  // namespace

TEST_CASE("remove_hex undoes a gluing: the counts before it, the invariants, a closed front") {
  stc::Stc s = stc::build_from_surface(gen::randquad(20, 3));
  engine::Engine eng(s.graph(), engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema),
                     weave::weave_actions(s));
  std::size_t undone = 0;
  for (std::size_t step = 0; step < 40; ++step) {
    const Counts before = counts(s);
    const std::size_t crosses = applied(eng, "cross") + applied(eng, "wedge");
    if (!eng.step()) break;
    // A cross or wedge only adds one hex and what it made: taking it off gives
    // back the state before it, up to ids.
    if (applied(eng, "cross") + applied(eng, "wedge") == crosses) continue;
    stc::Stc copy = s;
    weave::remove_hex(copy, newest_hex(copy));
    CHECK(copy.check_invariants() == "");
    CHECK(counts(copy) == before);
    CHECK(front_is_closed(copy));
    ++undone;
  }
  CHECK(undone >= 5);
}

TEST_CASE("remove_hex turns a face it made round to the hex glued onto it") {
  stc::Stc s = stc::build_from_surface(gen::randquad(20, 3));
  engine::Engine eng(s.graph(), engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema),
                     weave::weave_actions(s));
  std::size_t turned = 0;
  for (std::size_t step = 0; step < 200 && eng.step(); ++step) {
    // The first hex with another hex glued onto a face it made.
    for (engine::Id h : s.graph().members(s.ids().hex))
      for (unsigned i = 0; i < 6; ++i) {
        const engine::Id f = s.hex_face(h, i);
        const engine::Id glued = s.face_cell(f, 0);
        if (s.face_cell(f, 1) != h || glued == engine::no_element || glued == h) continue;
        stc::Stc copy = s;
        weave::remove_hex(copy, h);
        REQUIRE(copy.check_invariants() == "");
        CHECK_FALSE(copy.graph().alive(h));
        REQUIRE(copy.graph().alive(f));
        CHECK(copy.face_cell(f, 1) == glued);
        CHECK(copy.face_cell(f, 0) == engine::no_element);
        CHECK(copy.is_whisker(f));
        CHECK(front_is_closed(copy, false));
        ++turned;
        break;
      }
    if (turned >= 3) break;
  }
  CHECK(turned >= 3);
}

TEST_CASE("triple_doublet_deletion: where a seam would make a doublet's hexes share a third face, both come off") {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  const auto file = weave::default_rules_dir() / "report" / "triple_doublet_deletion.rule";
  for (auto& r : engine::compile_rules(test::slurp(file), file.string(), *stc::StcSchema::get().schema))
    rules.push_back(std::move(r));
  // Where the ordering bench saw it apply (docs/degeneracies.md).
  std::size_t deleted = 0;
  for (auto [faces, seed] : {std::pair{10, 5}, {14, 3}, {18, 0}}) {
    CAPTURE(faces);
    CAPTURE(seed);
    stc::Stc s = stc::build_from_surface(gen::randquad(faces, static_cast<std::uint64_t>(seed)));
    engine::Engine eng(s.graph(), rules, weave::weave_actions(s));
    std::size_t here = 0;
    for (std::size_t step = 0; step < 300 && here < 3; ++step) {
      const stc::Stc before = s;
      const std::size_t n = applied(eng, "triple_doublet_deletion");
      if (!eng.step()) break;
      REQUIRE(s.check_invariants() == "");
      if (applied(eng, "triple_doublet_deletion") == n) continue;
      ++here;
      CHECK(s.hexes() + 2 == before.hexes());
      CHECK(front_is_closed(s));
      // The two hexes gone shared two faces.
      std::vector<engine::Id> gone;
      for (engine::Id h : before.graph().members(before.ids().hex))
        if (!s.graph().alive(h)) gone.push_back(h);
      REQUIRE(gone.size() == 2);
      std::size_t shared = 0;
      for (unsigned i = 0; i < 6; ++i)
        for (unsigned k = 0; k < 6; ++k) shared += before.hex_face(gone[0], i) == before.hex_face(gone[1], k);
      CHECK(shared >= 2);
    }
    deleted += here;
  }
  CHECK(deleted >= 3);
}
