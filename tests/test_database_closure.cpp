// The template rule (rules/closure/database.rule): a closed piece of the
// front that the closure database holds is closed in one rewrite
// (src/weave/database_closure.hpp).
#include <doctest/doctest.h>

#include <algorithm>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/gen/generators.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/quadmap/canonical.hpp"
#include "src/quadmap/quad_map.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/weave/database_closure.hpp"
#include "src/weave/weave.hpp"
#include "tests/support.hpp"

using namespace loom;
using test::shipped_database;

namespace {

std::vector<engine::Rule> rules_with_template() {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  const auto file = weave::default_rules_dir() / "closure" / "database.rule";
  for (auto& r : engine::compile_rules(test::slurp(file), file.string(), *stc::StcSchema::get().schema))
    rules.push_back(std::move(r));
  return rules;
}

}  // namespace

TEST_CASE("a whole small surface is closed from the database in one rewrite, as a valid mesh") {
  for (const auto& [name, surface] : std::vector<std::pair<std::string, QuadSurface>>{
           {"spindle", gen::spindle()}, {"quadrangulation 12 4", gen::quadrangulation(12, 4)}, {"cube", gen::box(1, 1, 1)}}) {
    CAPTURE(name);
    stc::Stc s = stc::build_from_surface(surface);
    const engine::Id any = s.graph().members(s.ids().face).front();
    REQUIRE(weave::closes_from_database(s, any, shipped_database()));
    const auto* entry = shipped_database().find(
        quadmap::canonical_unoriented(quadmap::from_surface(surface)).code);
    REQUIRE(entry != nullptr);
    CHECK(weave::close_from_database(s, any, shipped_database()) == entry->hexes());
    CHECK(s.check_invariants() == "");
    CHECK(s.whiskers() == 0);
    CHECK(s.hexes() == entry->hexes());
    const HexMesh mesh = stc::to_hex_mesh(s);
    CHECK(check_hex_mesh(mesh, &surface).combinatorial_valid());
  }
}

TEST_CASE("the template rule is refused where the component is open or too large") {
  stc::Stc s = stc::build_from_surface(gen::randquad(40, 1));  // 40 quads: more than the database's 18
  const engine::Id any = s.graph().members(s.ids().face).front();
  CHECK_FALSE(weave::closes_from_database(s, any, shipped_database()));
  CHECK_THROWS_AS(weave::close_from_database(s, any, shipped_database()), std::runtime_error);
}

TEST_CASE("with the template rule the weave closes small surfaces that the shipped rules alone leave open") {
  const auto base = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  const auto with = rules_with_template();
  std::size_t closed_base = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    CAPTURE(seed);
    const QuadSurface surface = gen::randquad(12, seed);
    stc::Stc a = stc::build_from_surface(surface), b = a;
    closed_base += weave::weave(a, base, {}).closed;
    const weave::WeaveResult r = weave::weave(b, with, {});
    REQUIRE(r.closed);
    CHECK(r.applications.at("database_closure") == 1);
    CHECK(b.check_invariants() == "");
    CHECK(check_hex_mesh(stc::to_hex_mesh(b), &surface).combinatorial_valid());
  }
  CHECK(closed_base < 5);
}

TEST_CASE("loom weave's pipeline reports the template rule's hexes as from the database, not woven") {
  pipeline::MeshingOptions options = pipeline::default_meshing_options();
  options.closure = pipeline::Closure::none;
  const pipeline::MeshingResult r = pipeline::mesh_surface(gen::randquad(12, 1), rules_with_template(), options);
  REQUIRE(r.mesh);
  CHECK(r.made_by == "woven");
  REQUIRE_FALSE(r.source.empty());
  const auto from_database = std::count(r.source.begin(), r.source.end(), closure::HexSource::database);
  const auto woven = std::count(r.source.begin(), r.source.end(), closure::HexSource::woven);
  CHECK(from_database == static_cast<std::ptrdiff_t>(shipped_database()
                                                         .find(quadmap::canonical_unoriented(
                                                                   quadmap::from_surface(gen::randquad(12, 1)))
                                                                   .code)
                                                         ->hexes()));
  CHECK(woven == 0);
}

TEST_CASE("the template rule reads the pipeline's database: with none, it closes nothing") {
  pipeline::MeshingOptions options = pipeline::default_meshing_options();
  options.closure = pipeline::Closure::none;
  options.attempts = 1;
  options.database.clear();  // as for a rules directory without closure/database.txt
  const pipeline::MeshingResult r = pipeline::mesh_surface(gen::randquad(12, 1), rules_with_template(), options);
  CHECK(r.weave.applications.count("database_closure") == 0);
  CHECK(std::count(r.source.begin(), r.source.end(), closure::HexSource::database) == 0);
}
