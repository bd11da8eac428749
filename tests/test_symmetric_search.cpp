// closure/symmetric_search.hpp: shelling in symmetric pairs of hexes.
#include <doctest/doctest.h>

#include "src/closure/shelling_search.hpp"
#include "src/closure/symmetric_search.hpp"
#include "src/quadmap/automorphisms.hpp"
#include "src/quadmap/enumerate.hpp"
#include "src/quadmap/quad_map.hpp"
#include "support.hpp"

using namespace loom;
using namespace loom::closure;

// Under the sanitizers this case alone would take minutes; the pieces it
// joins (gluing, the inner search, the beam) run sanitized in other suites.
#ifdef LOOM_SANITIZED
constexpr bool kSkipLongSearch = true;
#else
constexpr bool kSkipLongSearch = false;
#endif

TEST_CASE("symmetric pairs close the octagonal trapezohedron within 72 hexes, where the plain search stops at 78" *
          doctest::skip(kSkipLongSearch)) {
  // Quadrangulation 16 439: two poles of degree 8.
  const quadmap::QuadMap surface = quadmap::pseudo_double_wheel(16);
  ClosureOptions plain;
  plain.limits.max_expansions = 50'000;
  const ClosureResult one_at_a_time = close_cavity(surface_cavity(surface), &test::shipped_database(), plain);
  REQUIRE(one_at_a_time.closed);
  CHECK(one_at_a_time.hexes.size() == 78);

  SymmetricOptions options;
  options.beam.max_depth = 5;  // 68 is found at depth 5
  const ClosureResult pairs = close_symmetric(surface, &test::shipped_database(), options);
  REQUIRE(pairs.closed);
  CHECK(pairs.hexes.size() <= 72);
  CHECK(pairs.source.size() == pairs.hexes.size());
  CHECK(test::check_against(test::surface_of(surface), pairs.hexes).combinatorial_valid());
  CHECK(pairs.stats.goals > 0);
}

TEST_CASE("a surface with no half-turn is left to the other searches; one with one gets the same mesh twice") {
  const quadmap::QuadMap* lopsided = nullptr;
  const auto maps = quadmap::three_connected_quadrangulations(12);
  for (const quadmap::QuadMap& m : maps)
    if (quadmap::automorphisms(m).size() == 1) {
      lopsided = &m;
      break;
    }
  REQUIRE(lopsided);
  const ClosureResult none = close_symmetric(*lopsided, &test::shipped_database(), {});
  CHECK_FALSE(none.closed);
  CHECK(none.hexes.empty());
  CHECK(none.stats.expanded == 0);

  SymmetricOptions shallow;
  shallow.beam.max_depth = 1;
  const quadmap::QuadMap square = quadmap::pseudo_double_wheel(8);  // two poles of degree 4
  const ClosureResult a = close_symmetric(square, &test::shipped_database(), shallow);
  const ClosureResult b = close_symmetric(square, &test::shipped_database(), shallow);
  REQUIRE(a.closed);
  CHECK(a.hexes == b.hexes);
  CHECK(a.source == b.source);
  CHECK(test::check_against(test::surface_of(square), a.hexes).combinatorial_valid());
}
