// The strategy node `beam` (docs/strategies.md): level by level, the states of
// least cost are kept, and the first level that reaches the goal ends it with
// its cheapest state. Shown on a domain small enough to work out by hand.
#include <doctest/doctest.h>

#include <cstdlib>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "engine/schema_file.hpp"
#include "engine/strategy_run.hpp"

using namespace loom;

namespace {

// A counter climbs to 6 by steps of 3 (`big`, costly, first in load order)
// or 2 (`small`, cheap); past 6 it is stuck. One priority, so that both are
// among a state's choices.
const char* kRules = R"(
rule big {
  match { c: counter where value < 6 }
  rewrite {
    c.value = c.value + 3
    c.spent = c.spent + 10
  }
}
rule small {
  match { c: counter where value < 6 }
  rewrite {
    c.value = c.value + 2
    c.spent = c.spent + 1
  }
}
)";

struct Counter {
  std::shared_ptr<const engine::Schema> schema =
      engine::parse_schema("kind counter\nattribute counter.value 0\nattribute counter.spent 0\n", "counter.txt");
  engine::Graph graph{schema};
  engine::Id c = graph.add(*schema->find_kind("counter"));
  engine::AttrId value = *schema->find_attribute(*schema->find_kind("counter"), "value");
  engine::AttrId spent = *schema->find_attribute(*schema->find_kind("counter"), "spent");
  engine::Engine eng{graph, engine::compile_rules(kRules, "counter.rule", *schema), {}};
  engine::StrategyDomain domain;
  std::size_t seen = 0;

  Counter() {
    domain.measures["left"] = [this] {
      const std::int64_t v = graph.get(c, value);
      return v == 6 ? 0 : 1 + std::abs(6 - v);
    };
    domain.measures["spent"] = [this] { return static_cast<std::int64_t>(graph.get(c, spent)); };
    domain.after_step = [this](const engine::Application&) { ++seen; };
  }
  engine::StrategyOutcome run(const std::string& beam) {
    auto s = engine::Strategy::parse_text("phase p { beam { goal left cost spent " + beam + " apply all } }", "b.strategy");
    engine::check_strategy(s, eng.rules(), {"left", "spent"});
    return engine::run_strategy(eng, s, domain);
  }
};

std::string error_of(const std::string& text, const std::vector<std::string>& measures = {"left", "spent"}) {
  try {
    Counter k;
    auto s = engine::Strategy::parse_text(text, "b.strategy");
    engine::check_strategy(s, k.eng.rules(), measures);
  } catch (const engine::RuleError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a beam one wide follows the cheapest step, and finds the cheap way up") {
  Counter k;
  // Level 1: big (cost 10) or small (1): small is kept. Level 2: small again
  // (4, cost 2) beats big (5, 11). Level 3: small reaches 6 at cost 3.
  auto out = k.run("width 1 branching 2 depth 5");
  CHECK(k.graph.get(k.c, k.value) == 6);
  CHECK(k.graph.get(k.c, k.spent) == 3);
  CHECK(k.seen == 3);  // the domain sees the path kept, not the states tried
  CHECK(out.phases[0].searched == 6);
}

TEST_CASE("a wider beam keeps the costly start too, and stops at the first level that reaches the goal") {
  Counter k;
  // Two wide, big then big reaches 6 at level 2, before the cheap way's level 3.
  k.run("width 2 branching 2 depth 5");
  CHECK(k.graph.get(k.c, k.value) == 6);
  CHECK(k.graph.get(k.c, k.spent) == 20);
  CHECK(k.seen == 2);
}

TEST_CASE("a beam that finds no goal within its depth or budget leaves the closest state it saw; try undoes it") {
  {
    Counter k;
    // One level: big leaves a goal measure of 4 (1 + |6 - 3|), small 5: big is the closer.
    auto out = k.run("width 4 branching 2 depth 1");
    CHECK(k.graph.get(k.c, k.value) == 3);
    CHECK(k.graph.get(k.c, k.spent) == 10);
    CHECK(k.seen == 1);
    CHECK(out.phases[0].searched == 2);
  }
  {
    Counter k;
    auto s = engine::Strategy::parse_text(
        "phase p { try { beam { goal left cost spent width 4 branching 2 depth 1 apply all } } }", "t.strategy");
    engine::run_strategy(k.eng, s, k.domain);
    CHECK(k.graph.get(k.c, k.value) == 0);
    CHECK(k.graph.get(k.c, k.spent) == 0);
  }
}

TEST_CASE("a beam's defaults, and its errors") {
  const auto s = engine::Strategy::parse_text("phase p { beam { goal left cost spent apply all } }", "d.strategy");
  const auto& n = s.phases.at(0).body.at(0);
  CHECK((n.op == engine::StrategyNode::Op::beam && n.width == 8 && n.depth == 4 && n.branching == 3 && n.max_tried == 10'000));
  CHECK(error_of("phase p { beam { goal left apply all } }") ==
        "b.strategy:1:28: beam needs 'cost MEASURE' (the states it keeps are those of least cost), found 'apply'");
  CHECK(error_of("phase p { beam { goal left cost spent width 0 apply all } }") ==
        "b.strategy:1:45: expected a width of at least 1 (with 0 a search tries nothing), found '0'");
  CHECK(error_of("phase p { beam { goal left cost volume apply all } }") ==
        "b.strategy:1:11: no measure 'volume' to make a cost of; this domain has: left, spent");
  CHECK(error_of("phase p { frobnicate }") ==
        "b.strategy:1:11: expected 'apply', 'repeat', 'try', 'backtrack', 'search', 'beam', 'when' or '}', found 'frobnicate'");
}
