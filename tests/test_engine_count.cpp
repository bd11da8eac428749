// count(kind.port -> x): the owners that hold x, each once however many of
// its slots hold it.
#include <doctest/doctest.h>

#include <memory>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"

using namespace loom;
using engine::Id;

namespace {

struct Pairs {
  std::shared_ptr<engine::Schema> schema = std::make_shared<engine::Schema>();
  engine::KindId item = schema->add_kind("item"), pair = schema->add_kind("pair");
  engine::PortId ends = schema->add_port(pair, "ends", 2, item);
  engine::AttrId held = schema->add_attribute(item, "held");
};

// mark: an item gets the number of pairs holding it, when it is 1 or 2.
const char* kRules = R"(
rule mark_one {
  priority 1
  match {
    x: item where self.held == 0
    count(pair.ends -> x) == 1
  }
  rewrite { x.held = 1 }
}
rule mark_two {
  priority 1
  match {
    x: item where self.held == 0
    count(pair.ends -> x) == 2
  }
  rewrite { x.held = 2 }
}
)";

}  // namespace

TEST_CASE("count: an owner holding the target in two slots counts once, two owners twice") {
  Pairs k;
  engine::Graph g(k.schema);
  const Id a = g.add(k.item), b = g.add(k.item), c = g.add(k.item);
  // Pairs (a, a), (b, c) and (c, b): a is held by one pair in both of its
  // slots; b and c by two pairs each, in slot 0 of one and slot 1 of the other.
  const Id p = g.add(k.pair), q = g.add(k.pair), r = g.add(k.pair);
  g.link(p, k.ends, 0, a);
  g.link(p, k.ends, 1, a);
  g.link(q, k.ends, 0, b);
  g.link(q, k.ends, 1, c);
  g.link(r, k.ends, 0, c);
  g.link(r, k.ends, 1, b);
  engine::Engine eng(g, engine::compile_rules(kRules, "pairs.rule", *k.schema), {});
  const auto all = eng.select(engine::StrategyNode::Pick::priority, false, {"mark_one", "mark_two"});
  while (eng.step(all)) {
  }
  CHECK(g.get(a, k.held) == 1);
  CHECK(g.get(b, k.held) == 2);
  CHECK(g.get(c, k.held) == 2);
}
