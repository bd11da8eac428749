// Closure: the database of small hexahedrizations, the search over hex
// gluings, the cavities a weave leaves and their closure.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include "engine/rule_compiler.hpp"
#include "src/check/edge_valence.hpp"
#include "src/check/validity.hpp"
#include "src/closure/cavities.hpp"
#include "src/closure/database.hpp"
#include "src/closure/database_improve.hpp"
#include "src/closure/shelling_search.hpp"
#include "src/fill/fill.hpp"
#include "src/gen/generators.hpp"
#include "src/pipeline/cavity_closure.hpp"
#include "src/pipeline/mesh_surface.hpp"
#include "src/quadmap/hex_glue.hpp"
#include "src/stc/build.hpp"
#include "src/stc/primal.hpp"
#include "src/util/error.hpp"
#include "src/weave/weave.hpp"
#include "support.hpp"

using namespace loom;
using namespace loom::closure;
using test::check_against;
using test::shipped_database;
using test::surface_of;

TEST_CASE("the outward shelling finds as many meshes of 1 to 6 hexes as Verhetsel et al. list") {
  // "Finding hexahedrizations for small quadrangulations of the sphere"
  // (2019): 1, 2, 5, 17, 74, 489 meshes of at most 1..6 hexes.
  const Database db = Database::build({6, 40, 40});
  std::size_t by_size[7] = {};
  for (const auto& e : db.entries()) ++by_size[e.hexes()];
  std::size_t total = 0;
  const std::size_t listed[7] = {0, 1, 2, 5, 17, 74, 489};
  for (int n = 1; n <= 6; ++n) {
    total += by_size[n];
    CHECK(total == listed[n]);
  }
  // Every entry is a valid mesh of its boundary.
  for (const auto& e : db.entries()) {
    const auto hexes = mesh_of(e);
    REQUIRE(hexes.size() == e.hexes());
    CHECK(check_against(surface_of(quadmap::map_of_code(e.code)), hexes).combinatorial_valid());
  }
}

TEST_CASE("growing several meshes per boundary reaches the same boundaries in as few hexes, and keeps one mesh each") {
  DatabaseLimits one{6, 40, 40}, three{6, 40, 40};
  three.grown_per_boundary = 3;
  std::size_t grown_one = 0, grown_three = 0;
  const Database a = Database::build(one, [&](int, std::size_t n) { grown_one = n; });
  const Database b = Database::build(three, [&](int, std::size_t n) { grown_three = n; });
  CHECK(grown_three > grown_one);  // the other meshes of a boundary were grown too
  REQUIRE(b.size() == a.size());   // every boundary of up to 6 hexes, once
  for (const auto& e : b.entries()) {
    const auto* same = a.find(e.code);
    REQUIRE(same != nullptr);
    CHECK(e.hexes() == same->hexes());
    const auto hexes = mesh_of(e);
    CHECK(check_against(surface_of(quadmap::map_of_code(e.code)), hexes).combinatorial_valid());
  }
}

TEST_CASE("the shipped database: every entry replays to a valid mesh, and a rebuild writes the same file") {
  const Database& db = shipped_database();
  REQUIRE(db.size() > 1000);
  std::size_t invalid = 0;
  for (const auto& e : db.entries()) {
    const auto report = check_against(surface_of(quadmap::map_of_code(e.code)), mesh_of(e));
    invalid += !report.combinatorial_valid();
  }
  CHECK(invalid == 0);
  // The file is what Database::save writes for it.
  test::ScratchDir dir("db");
  db.save(dir / "again.txt");
  CHECK(test::slurp(dir / "again.txt") == test::slurp(database_file(weave::default_rules_dir())));
}

TEST_CASE("the database's own search gives an entry a smaller mesh where it finds one") {
  Database db = Database::build({1, 40, 40});
  REQUIRE(db.size() == 1);
  const quadmap::Code cube = db.entries().front().code;
  // The cube's boundary meshed the long way: an inner cube and a pillow of
  // six hexes round it, listed outwards (the inner cube first).
  const Hex outer = mesh_of(db.entries().front()).front();
  static constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
  std::vector<Hex> pillowed{{8, 9, 10, 11, 12, 13, 14, 15}};
  for (const auto& f : faces)
    pillowed.push_back({outer[f[0]], outer[f[1]], outer[f[2]], outer[f[3]], 8u + f[0], 8u + f[1], 8u + f[2], 8u + f[3]});
  REQUIRE(db.mesh(*db.find(cube)).size() == 1);
  db.replace(entry_of_mesh(cube, pillowed));
  REQUIRE(db.find(cube)->hexes() == 7);
  // The replayed mesh kept for the entry follows the replacement.
  CHECK(db.mesh(*db.find(cube)) == mesh_of(*db.find(cube)));
  CHECK(db.mesh(*db.find(cube)).size() == 7);

  const DatabaseImprovement r = improve_by_search(db, ClosureOptions{});
  CHECK(r.searched == 1);
  CHECK(r.improved == 1);
  CHECK(r.hexes_saved == 6);
  CHECK(db.find(cube)->hexes() == 1);
  CHECK(db.mesh(*db.find(cube)).size() == 1);
  CHECK(check_against(surface_of(quadmap::map_of_code(cube)), mesh_of(*db.find(cube))).combinatorial_valid());
  // Nothing is left to improve.
  CHECK(improve_by_search(db, ClosureOptions{}).improved == 0);
}

TEST_CASE("a broken database file is refused naming its line") {
  test::ScratchDir dir("baddb");
  const std::string good = "entry 6 1 | 3 3 3 3 0 1 2 3 1 0 4 5 2 1 5 6 3 2 6 7 0 3 7 4 5 4 7 6 |\n";
  for (const auto& [text, what] :
       std::vector<std::pair<std::string, std::string>>{{"entri 6 1 |", "line 1: expected 'entry'"},
                                                        {good + "entry 6 2 | 3 3 3 3 0 1 2 3 1 0 4 5 2 1 5 6 3 2 6 7 0 3 7 4 5 4 7 6 | x\n",
                                                         "line 2: 'x' is not a gluing"},
                                                        {good + good, "line 2: a boundary listed twice"}}) {
    test::spit(dir / "db.txt", text);
    try {
      Database::load(dir / "db.txt");
      FAIL("accepted: " << text);
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(what) != std::string::npos);
    }
  }
}

TEST_CASE("the search closes small surfaces with valid meshes, the spindle with the database") {
  ClosureOptions options;
  for (const auto& [name, surface, at_most] :
       std::vector<std::tuple<std::string, QuadSurface, std::size_t>>{
           {"cube", gen::box(1, 1, 1), 1}, {"box 2 1 1", gen::box(2, 1, 1), 2}, {"tet4", gen::tet4(), 4}}) {
    CAPTURE(name);
    const auto r = close_cavity(surface_cavity(quadmap::from_surface(surface)), nullptr, options);
    REQUIRE(r.closed);
    CHECK(r.hexes.size() <= at_most);
    CHECK(check_against(surface, r.hexes).combinatorial_valid());
  }
  const QuadSurface spindle = gen::spindle();
  const auto without = close_cavity(surface_cavity(quadmap::from_surface(spindle)), nullptr, options);
  CHECK_FALSE(without.closed);
  const auto with = close_cavity(surface_cavity(quadmap::from_surface(spindle)), &shipped_database(), options);
  REQUIRE(with.closed);
  CHECK(with.hexes.size() <= 60);
  CHECK(check_against(spindle, with.hexes).combinatorial_valid());
  CHECK(std::count(with.source.begin(), with.source.end(), HexSource::database) > 0);
}

/// Sum of |valence - 4| over the interior edges of `hexes` over the surface's points.
static std::size_t irregularity(const QuadSurface& surface, const std::vector<Hex>& hexes) {
  HexMesh mesh{surface.points, hexes};
  for (const Hex& h : hexes)
    for (std::uint32_t v : h)
      if (mesh.points.size() <= v) mesh.points.resize(v + 1);
  std::size_t sum = 0;
  for (const auto& [valence, edges] : interior_valence_histogram(mesh))
    sum += edges * (valence > 4 ? valence - 4 : 4 - valence);
  return sum;
}

TEST_CASE("a search costed by irregularity closes with fewer irregular edges, the fewest-hexes one with fewer hexes") {
  // randquad 16 2 from the surface: 55 hexes, irregularity 109 by fewest
  // hexes; 56 and 90 with weight 1.
  const QuadSurface surface = gen::randquad(16, 2);
  ClosureOptions fewest, regular;
  REQUIRE(fewest.irregularity_weight == 0);
  regular.irregularity_weight = 1;
  const Cavity cavity = surface_cavity(quadmap::from_surface(surface));
  const auto by_hexes = close_cavity(cavity, &shipped_database(), fewest);
  const auto by_regularity = close_cavity(cavity, &shipped_database(), regular);
  REQUIRE(by_hexes.closed);
  REQUIRE(by_regularity.closed);
  CHECK(check_against(surface, by_regularity.hexes).combinatorial_valid());
  CHECK(irregularity(surface, by_regularity.hexes) < irregularity(surface, by_hexes.hexes));
  CHECK(by_hexes.hexes.size() <= by_regularity.hexes.size());
}

/// The hexes of a weave of `surface` stopped after 30 steps, over the surface's points.
static HexMesh weave_cut_short(const QuadSurface& surface) {
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  stc::Stc s = stc::build_from_surface(surface);
  weave::WeaveOptions options;
  options.max_steps = 30;
  REQUIRE_FALSE(weave::weave(s, rules, options).closed);
  return stc::woven_over_surface(s, surface.points.size());
}

TEST_CASE("the woven hexes of a weave cut short are kept, and the cavity they leave is closed") {
  const QuadSurface box = gen::box(3, 3, 3);
  const HexMesh partial = weave_cut_short(box);
  REQUIRE(partial.hexes.size() > 5);
  const Cavities c = cavities_left(box, partial.hexes);
  CHECK(c.peeled == 0);
  CHECK(c.kept.size() == partial.hexes.size());
  REQUIRE(c.pieces.size() == 1);
  CHECK(why_not_closable(c.pieces[0]) == "");
  const auto closed = pipeline::close_cavities(box, partial, &shipped_database(),
                                               fill::load_caps(fill::default_caps_dir()), {});
  CHECK(closed.complete);
  CHECK(closed.report.woven == partial.hexes.size());
  CHECK(check_hex_mesh(closed.mesh, &box).combinatorial_valid());
}

TEST_CASE("hexes a template rule put into the weave stay database hexes through cavity closure") {
  const QuadSurface box = gen::box(3, 3, 3);
  const HexMesh partial = weave_cut_short(box);
  REQUIRE(partial.hexes.size() > 5);
  // Say the first two came from the database.
  std::vector<HexSource> given(partial.hexes.size(), HexSource::woven);
  given[0] = given[1] = HexSource::database;
  const auto closed = pipeline::close_cavities(box, partial, &shipped_database(), {}, {}, given);
  REQUIRE(closed.complete);
  CHECK(closed.report.peeled == 0);
  CHECK(closed.report.woven == partial.hexes.size() - 2);
  CHECK(closed.report.database >= 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto at = std::find(closed.mesh.hexes.begin(), closed.mesh.hexes.end(), partial.hexes[i]);
    REQUIRE(at != closed.mesh.hexes.end());
    CHECK(closed.source[static_cast<std::size_t>(at - closed.mesh.hexes.begin())] == HexSource::database);
  }
  CHECK_THROWS_AS(pipeline::close_cavities(box, partial, &shipped_database(), {}, {}, {HexSource::woven}),
                  std::logic_error);
}

TEST_CASE("woven hexes that could not be part of a valid mesh are peeled off") {
  const QuadSurface cube = gen::box(1, 1, 1);
  auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  stc::Stc s = stc::build_from_surface(cube);
  REQUIRE(weave::weave(s, rules, {}).closed);
  HexMesh woven = stc::woven_over_surface(s, cube.points.size());
  REQUIRE(woven.hexes.size() == 1);
  CHECK(cavities_left(cube, woven.hexes).pieces.empty());
  // A second hex with six corners of the first: the two would share two faces.
  const Hex h = woven.hexes[0];
  woven.hexes.push_back({h[0], h[1], h[2], h[3], h[4], h[5], 8, 9});
  const Cavities c = cavities_left(cube, woven.hexes);
  CHECK(c.peeled == 1);
  REQUIRE(c.kept.size() == 1);
  CHECK(c.kept[0] == h);
  CHECK(c.pieces.empty());
}

TEST_CASE("pulling back round a stuck front takes off the hexes against it and the nodes only they used") {
  // Three hexes in a row; the front stuck on the face between the second and third.
  const HexMesh row = gen::hexgrid(3, 1, 1);
  REQUIRE(row.hexes.size() == 3);
  std::map<std::array<std::uint32_t, 4>, int> uses;
  std::vector<Quad> between;
  for (const Hex& h : row.hexes)
    for (const Quad& f : quadmap::outward_faces(h)) {
      std::array<std::uint32_t, 4> k = f;
      std::sort(k.begin(), k.end());
      if (++uses[k] == 2) between.push_back(f);
    }
  REQUIRE(between.size() == 2);
  const Quad stuck = std::max(between[0], between[1], [&](const Quad& a, const Quad& b) {
    return row.points[a[0]][0] + row.points[a[2]][0] < row.points[b[0]][0] + row.points[b[2]][0];
  });
  const auto pulled = pipeline::without_hexes_on(row, {stuck}, 2);
  const HexMesh& left = pulled.mesh;
  REQUIRE(left.hexes.size() == 1);
  CHECK(pulled.kept == std::vector<std::size_t>{0});
  // Points 0 and 1 stay, used or not; then the first hex's other corners.
  const auto among_first_two = std::count_if(row.hexes[0].begin(), row.hexes[0].end(), [](std::uint32_t v) { return v < 2; });
  CHECK(left.points.size() == static_cast<std::size_t>(2 + 8 - among_first_two));
  CHECK(left.points[0] == row.points[0]);
  CHECK(left.points[1] == row.points[1]);
  // The hex kept is the first of the row, at the same places.
  for (int i = 0; i < 8; ++i) CHECK(left.points[left.hexes[0][i]] == row.points[row.hexes[0][i]]);
  // A front no hex touches takes nothing off.
  const HexMesh all = pipeline::without_hexes_on(row, {}, 0).mesh;
  REQUIRE(all.hexes.size() == row.hexes.size());
  CHECK(all.points.size() == row.points.size());
  for (std::size_t h = 0; h < row.hexes.size(); ++h)
    for (int i = 0; i < 8; ++i) CHECK(all.points[all.hexes[h][i]] == row.points[row.hexes[h][i]]);
}

TEST_CASE("closure is deterministic: the same surface gives the same hexes, and the search from a random quadrangulation closes it") {
  const QuadSurface surface = gen::randquad(30, 3);
  const auto caps = fill::load_caps(fill::default_caps_dir());
  const HexMesh bare{surface.points, {}};
  const auto a = pipeline::close_cavities(surface, bare, &shipped_database(), caps, {});
  const auto b = pipeline::close_cavities(surface, bare, &shipped_database(), caps, {});
  CHECK(a.mesh.hexes == b.mesh.hexes);
  CHECK(a.source == b.source);
  REQUIRE(a.complete);
  CHECK(a.report.filled == 0);  // closed by search and database alone
  CHECK(check_hex_mesh(a.mesh, &surface).combinatorial_valid());
}

/// What `loom weave --closure search` does: the shipped rules, 16 attempts,
/// cavity closure and the search, no fill.
/// The stages it went through are counted by name in `stages`.
pipeline::MeshingResult mesh_without_fill(const QuadSurface& surface,
                                          std::map<std::string, int>* stages = nullptr,
                                          std::size_t wide_expansions = pipeline::wide_search_defaults().limits.max_expansions,
                                          std::size_t symmetric_depth = closure::SymmetricOptions{}.beam.max_depth,
                                          pipeline::Prefer prefer = pipeline::Prefer::quality) {
  pipeline::MeshingOptions options;
  options.prefer = prefer;
  options.symmetric.beam.max_depth = symmetric_depth;
  if (stages) options.on_stage = [stages](const char* stage) { ++(*stages)[stage]; };
  options.wide_search.limits.max_expansions = wide_expansions;
  options.attempts = 16;
  options.closure = pipeline::Closure::search;
  options.database = database_file(weave::default_rules_dir());
  const auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
  return pipeline::mesh_surface(surface, rules, options);
}

// Under ASan+UBSan (-DLOOM_SANITIZE=ON) this case alone took 279 s of ctest's
// 300: its one input, quadrangulation 16 90, is the point of the case (the
// full search of 50,000 expansions), so it cannot shrink and is skipped there.
// The search itself runs under the sanitizers in the cases above.
#ifdef LOOM_SANITIZED
constexpr bool kSkipFullSearch = true;
#else
constexpr bool kSkipFullSearch = false;
#endif

TEST_CASE("loom weave's pipeline searches a small surface fully when the weave's mesh is larger than 72 hexes" *
          doctest::skip(kSkipFullSearch)) {
  // Quadrangulation 16 90: the weave gives a valid mesh of 117 hexes; a short
  // search from the surface finds 77, the full one 55 (before the boundary layer).
  const QuadSurface surface = gen::quadrangulation(16, 90);
  std::map<std::string, int> stages;
  const pipeline::MeshingResult r = mesh_without_fill(surface, &stages);
  REQUIRE(r.combinatorially_valid());
  CHECK(r.made_by == "searched");
  CHECK(r.mesh->hexes.size() - r.boundary_layer.hexes_added <= 72);
  // Within the bound after it: neither the symmetric nor the wide search.
  CHECK(stages["searching from the surface"] == 1);
  CHECK(stages["searching symmetric pairs"] == 0);
  // Placement's global untangling leaves none of the 8 hexes <= 0 that moving
  // one node at a time left.
  CHECK(r.check->quality.below_zero == 0);
  CHECK(r.smoothing.global_rounds > 0);
}

TEST_CASE("a small surface still over 72 hexes after the direct search gets a symmetric one, then a wide one" *
          doctest::skip(kSkipFullSearch)) {
  // Quadrangulation 14 54 (two poles of degree 7): 79 hexes after the direct
  // search, 81 in symmetric pairs (not kept). The wide search's own budget
  // (1,000,000 expansions, 255 s) finds 67; here it gets 2,000 and the
  // symmetric search two levels, so only that they run in turn, and what
  // they may keep by hexes, is tested.
  const QuadSurface surface = gen::quadrangulation(14, 54);
  std::map<std::string, int> stages;
  const pipeline::MeshingResult r = mesh_without_fill(surface, &stages, 2'000, 2, pipeline::Prefer::fewest_hexes);
  REQUIRE(r.combinatorially_valid());
  CHECK(stages["searching symmetric pairs"] == 1);
  CHECK(stages["searching from the surface"] == 2);
  CHECK(r.mesh->hexes.size() - r.boundary_layer.hexes_added <= 79);
}

TEST_CASE("by quality the run keeps a valid mesh over a smaller one with inverted hexes; by hexes, the smaller" *
          doctest::skip(kSkipFullSearch)) {
  // randquad 14 s3: the cavity closure gives 108 hexes (14 of them the
  // boundary layer), none <= 0 once placed; the search from the surface 70
  // (56 before the layer, within the published 72), 12 of them <= 0.
  auto run = [](pipeline::Prefer prefer, const QuadSurface& surface = gen::randquad(14, 3)) {
    pipeline::MeshingOptions options = pipeline::default_meshing_options();
    options.prefer = prefer;
    const auto rules = engine::load_rule_dir(weave::default_rules_dir(), *stc::StcSchema::get().schema);
    return pipeline::mesh_surface(surface, rules, options);
  };
  const pipeline::MeshingResult quality = run(pipeline::Prefer::quality), fewest = run(pipeline::Prefer::fewest_hexes);
  REQUIRE(quality.combinatorially_valid());
  REQUIRE(fewest.combinatorially_valid());
  CHECK(quality.check->quality.below_zero == 0);
  CHECK(fewest.check->quality.below_zero > 0);
  CHECK(quality.mesh->hexes.size() > fewest.mesh->hexes.size());
  CHECK(fewest.mesh->hexes.size() - fewest.boundary_layer.hexes_added <= 72);
  CHECK(quality.made_by == "closed");
  CHECK(fewest.made_by == "searched");

  // randquad 22 s4: the cavity closure's 91 hexes (69 before the layer, within
  // the bound) keep hexes <= 0, so by quality the search from the surface gets
  // its full budget, not the short one, and finds 77 with none.
  const pipeline::MeshingResult searched = run(pipeline::Prefer::quality, gen::randquad(22, 4));
  REQUIRE(searched.combinatorially_valid());
  CHECK(searched.made_by == "searched");
  CHECK(searched.check->quality.below_zero == 0);
}

// Sixteen weave attempts on one input are the point of this case too: 8 s
// plain, 110 s under the sanitizers, where it is skipped (cavities_left runs
// sanitized in the cases above).
TEST_CASE("a closed weave with two cycles of hexes round one edge is cut back to what a mesh can hold, not filled" *
          doctest::skip(kSkipFullSearch)) {
  // randquad 38 seed 4: every weave attempt closes, the last into 229 hexes of
  // which every pair meets properly but two cycles go round one edge (criterion
  // 4). Cavity closure kept them all, the mesh failed the check, and the
  // whole-surface fill made 6,080 hexes. Now the newest hex there is peeled.
  const QuadSurface surface = gen::randquad(38, 4);
  const pipeline::MeshingResult r = mesh_without_fill(surface);
  REQUIRE(r.weave.closed);
  REQUIRE(r.combinatorially_valid());
  CHECK(r.made_by == "closed");
  CHECK(r.closure.peeled > 0);
  CHECK(r.closure.woven > 200);
  CHECK(std::count(r.source.begin(), r.source.end(), HexSource::filled) == 0);
}

TEST_CASE("the closure search gives the same result whatever memory it may keep fronts in") {
  // With a budget of a few fronts, nearly every parent front is dropped and
  // rebuilt by replaying its gluings, without what its expansion had learnt.
  for (std::uint64_t seed : {1, 2}) {
    const Cavity cavity = surface_cavity(quadmap::from_surface(gen::randquad(200, seed)));
    ClosureOptions roomy, tight;
    roomy.limits.max_expansions = tight.limits.max_expansions = 1500;
    tight.front_bytes = 64 << 10;
    const ClosureResult a = close_cavity(cavity, nullptr, roomy), b = close_cavity(cavity, nullptr, tight);
    CHECK(a.stats.expanded == 1500);
    CHECK(a.stats.expanded == b.stats.expanded);
    CHECK(a.stats.generated == b.stats.generated);
    CHECK(a.hexes == b.hexes);
    CHECK(a.left.front.quads == b.left.front.quads);
    CHECK(a.left.owner == b.left.owner);
  }
}
