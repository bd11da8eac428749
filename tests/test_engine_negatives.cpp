// Incremental matching and negative patterns: a change that can only make a
// negative pattern match (an element or slot the step created) does not offer
// an anchor of an unordered rule again; a change that can unblock one (an old
// element's slot cleared) does.
#include <doctest/doctest.h>

#include <memory>

#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"

using namespace loom;
using engine::Id;

namespace {

struct Tags {
  std::shared_ptr<engine::Schema> schema = std::make_shared<engine::Schema>();
  engine::KindId item = schema->add_kind("item"), tag = schema->add_kind("tag");
  engine::PortId of = schema->add_port(tag, "of", 1, item);
  engine::AttrId done = schema->add_attribute(item, "done"), fresh = schema->add_attribute(tag, "fresh");
};

// finish: an untagged item is done. stamp: a fresh tag adds a second tag to
// its item (which was tagged already). drop: a tag marked 2 goes.
const char* kRules = R"(
rule finish {
  priority 1
  match {
    x: item where self.done == 0
    not {
      t: tag
      t.of == x
    }
  }
  rewrite { x.done = 1 }
}
rule stamp {
  priority 1
  match {
    s: tag where self.fresh == 1
    y: item
    s.of == y
  }
  rewrite {
    s.fresh = 0
    new t: tag
    t.of = y
  }
}
rule drop {
  priority 1
  match { d: tag where self.fresh == 2 }
  rewrite { delete d }
}
)";

}  // namespace

TEST_CASE("a tag the step creates offers no blocked item again; a tag it deletes unblocks one") {
  Tags k;
  engine::Graph g(k.schema);
  const Id x0 = g.add(k.item), x1 = g.add(k.item);
  const Id s0 = g.add(k.tag), s1 = g.add(k.tag);
  g.link(s0, k.of, 0, x0);
  g.set(s0, k.fresh, 1);
  g.link(s1, k.of, 0, x1);
  g.set(s1, k.fresh, 2);
  engine::Engine eng(g, engine::compile_rules(kRules, "tags.rule", *k.schema), {});
  const auto finish = eng.select(engine::StrategyNode::Pick::priority, false, {"finish"});
  const auto stamp = eng.select(engine::StrategyNode::Pick::priority, false, {"stamp"});
  const auto drop = eng.select(engine::StrategyNode::Pick::priority, false, {"drop"});

  CHECK_FALSE(eng.step(finish));  // both items are tagged
  const std::size_t offered = eng.counters().candidates;
  CHECK(offered == 2);

  REQUIRE(eng.step(stamp));  // x0 gets a second tag: finish is not offered x0 again
  CHECK(g.members(k.tag).size() == 3);
  // stamp's own: s0 and s1 when first used, then s0 (fresh changed) and the new tag
  CHECK(eng.counters().candidates == offered + 2 + 2);
  CHECK_FALSE(eng.step(finish));
  CHECK(eng.counters().match_attempts == 2 + 1);  // finish's first two, stamp's s0

  REQUIRE(eng.step(drop));  // x1's only tag goes: finish must see x1 again
  CHECK(eng.step(finish));
  CHECK(g.get(x1, k.done) == 1);
  CHECK(g.get(x0, k.done) == 0);
}

TEST_CASE("a blocking tag a rollback takes away unblocks the item again") {
  Tags k;
  engine::Graph g(k.schema);
  const Id x = g.add(k.item), s = g.add(k.tag);
  g.link(s, k.of, 0, x);
  g.set(s, k.fresh, 3);
  // finish is blocked only by a tag marked 9; label adds one to s's item.
  const char* rules = R"(
rule finish {
  match {
    x: item where self.done == 0
    not {
      t: tag where self.fresh == 9
      t.of == x
    }
  }
  rewrite { x.done = 1 }
}
rule label {
  match {
    s: tag where self.fresh == 3
    y: item
    s.of == y
  }
  rewrite {
    new t: tag
    t.of = y
    t.fresh = 9
  }
}
)";
  engine::Engine eng(g, engine::compile_rules(rules, "label.rule", *k.schema), {});
  const auto finish = eng.select(engine::StrategyNode::Pick::priority, false, {"finish"});
  const auto label = eng.select(engine::StrategyNode::Pick::priority, false, {"label"});
  const auto before = eng.mark();
  REQUIRE(eng.step(label));
  CHECK_FALSE(eng.step(finish));  // x is blocked, and leaves finish's queue
  eng.undo(before);               // the tag made by label goes: nothing is new after a rollback
  CHECK(g.members(k.tag).size() == 1);
  CHECK(eng.step(finish));
  CHECK(g.get(x, k.done) == 1);
}
