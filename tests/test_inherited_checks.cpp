// What a child front inherits from its parent's expansion in the closure
// search (src/closure/inherited_checks.hpp): every plan and every verdict it
// says it knows must be what planning and checking the child anew gives.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "src/closure/cavity.hpp"
#include "src/closure/hex_meeting.hpp"
#include "src/closure/inherited_checks.hpp"
#include "src/gen/generators.hpp"
#include "src/quadmap/hex_glue.hpp"

using namespace loom;
using namespace loom::closure;
using namespace loom::quadmap;

namespace {

std::uint64_t quad_key(Quad q) {
  std::sort(q.begin(), q.end());
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint32_t v : q) h = (h ^ v) * 1099511628211ull;
  return h * 0x9E3779B97F4A7C15ull;
}

struct Front {
  QuadMap map;
  std::vector<Dart> twin;
  std::vector<int> degree;
  std::vector<Hex> placed;

  std::uint64_t covered_hash(const GluedHex& g) const {
    std::uint64_t h = 0;
    for (int c = 0; c < g.k; ++c) h ^= quad_key(map.quads[g.covered[static_cast<std::size_t>(c)]]);
    return h;
  }
  /// The search's three checks of a planned gluing.
  bool fits(const QuadsAtVertex& at, const GluedHex& g) const {
    const std::vector<std::uint32_t> covered(g.covered.begin(), g.covered.begin() + g.k);
    std::vector<const Quad*> onto;
    for (std::uint32_t c : covered) onto.push_back(&map.quads[c]);
    if (!glued_front_is_proper(map, at, g) || !touches_front_properly(g.hex, map, at, covered)) return false;
    return std::all_of(placed.begin(), placed.end(), [&](const Hex& h) { return meets_as_glued(g.hex, h, onto); });
  }
};

}  // namespace

TEST_CASE("a child front's inherited plans and verdicts are what planning and checking it anew gives") {
  std::mt19937 rng(3);
  std::size_t plans_known = 0, fits_known = 0, misfits_known = 0, steps = 0;
  for (const QuadSurface& surface : {gen::randquad(80, 2), gen::randquad(120, 7), gen::box(4, 3, 2), gen::randquad(60, 5),
                                     gen::cubesphere(3), gen::randquad(100, 9)}) {
    Front f{from_surface(surface), {}, {}, {}};
    f.twin = twins(f.map);
    f.degree = degrees(f.map);
    for (int step = 0; step < 80; ++step, ++steps) {
      const QuadsAtVertex at(f.map);
      PlanMasks plans(f.map.size());
      GluingVerdicts verdicts;
      std::vector<GluedHex> fitting;
      for (std::uint32_t q = 0; q < f.map.size(); ++q)
        for (unsigned sides = 0; sides < 16; ++sides) {
          GluedHex g;
          const bool planned = plan_gluing(f.map, f.twin, f.degree, {q, static_cast<std::uint8_t>(sides)}, g);
          plans.record(q, sides, planned);
          if (!planned) continue;
          const bool ok = f.fits(at, g);
          verdicts.record(f.covered_hash(g), ok);
          if (ok) fitting.push_back(g);
        }
      verdicts.seal();
      if (fitting.empty()) break;
      // Shrinking gluings next to the last hex make the contacts whose verdicts change.
      const int most_k = std::max_element(fitting.begin(), fitting.end(), [](auto& a, auto& b) { return a.k < b.k; })->k;
      std::erase_if(fitting, [&](const GluedHex& g) { return g.k < most_k && rng() % 4 != 0; });
      const GluedHex made_by = fitting[rng() % fitting.size()];
      Front child{after_gluing(f.map, made_by), twins_after_gluing(f.map, f.twin, made_by),
                  degrees_after_gluing(f.map, f.degree, made_by), f.placed};
      child.placed.push_back(made_by.hex);
      const QuadsAtVertex child_at(child.map);
      const PlanMasks known = plans.for_child(child.map, child.twin, child_at, made_by);
      for (std::uint32_t q = 0; q < child.map.size(); ++q)
        for (unsigned sides = 0; sides < 16; ++sides) {
          GluedHex g;
          const bool planned = plan_gluing(child.map, child.twin, child.degree, {q, static_cast<std::uint8_t>(sides)}, g);
          if (known.known(q, sides)) {
            ++plans_known;
            CHECK(known.planned(q, sides) == planned);
          }
          if (!planned) continue;
          const auto verdict = verdicts.for_child(child.covered_hash(g), g.hex, made_by.hex);
          if (verdict == GluingVerdicts::Verdict::unknown) continue;
          (verdict == GluingVerdicts::Verdict::fits ? fits_known : misfits_known) += 1;
          CHECK((verdict == GluingVerdicts::Verdict::fits) == child.fits(child_at, g));
        }
      f = std::move(child);
    }
  }
  CHECK(steps >= 60);
  // Most is inherited, both ways, or the test would prove little.
  CHECK(plans_known > 10'000);
  CHECK(fits_known > 1'000);
  CHECK(misfits_known > 100);
}
