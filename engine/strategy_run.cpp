#include "engine/strategy_run.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <stdexcept>

#include <fmt/format.h>

#include "engine/rule_parser.hpp"

namespace loom::engine {

namespace {

class Runner {
public:
  Runner(Engine& engine, const Strategy& strategy, const StrategyDomain& domain)
      : eng_(engine), strategy_(strategy), domain_(domain) {
    for (const StrategyPhase& p : strategy.phases)
      each_node(p.body, [&](const StrategyNode& n) {
        if (n.op != StrategyNode::Op::apply) return;
        try {
          selection_[&n] = eng_.select(n.pick, n.all, n.rules);
        } catch (const std::invalid_argument& e) {
          throw RuleError(strategy.source, n.pos, std::string(e.what()) + "; see 'loom rules list'");
        }
      });
  }

  StrategyOutcome run() {
    for (const StrategyPhase& p : strategy_.phases) {
      if (stop_) break;
      phase_ = &out_.phases.emplace_back(PhaseFigures{p.name});
      const std::size_t before = eng_.counters().steps;
      const auto start = std::chrono::steady_clock::now();
      block(p.body);
      phase_->steps = eng_.counters().steps - before;
      phase_->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return out_;
  }

private:
  struct Choice {
    Graph::Checkpoint before;
    std::size_t taken = 0;  ///< rank of the match applied (0: the pick's first)
  };

  bool block(const std::vector<StrategyNode>& nodes) {
    for (const StrategyNode& n : nodes)
      if (stop_ || !node(n)) return false;
    return true;
  }

  bool node(const StrategyNode& n) {
    switch (n.op) {
      case StrategyNode::Op::apply: return apply(selection_.at(&n));
      case StrategyNode::Op::repeat:
        // An iteration that applies nothing would repeat for ever.
        for (std::size_t before = SIZE_MAX; !stop_ && before != eng_.counters().steps;) {
          before = eng_.counters().steps;
          if (!block(n.body)) break;
        }
        return true;
      case StrategyNode::Op::try_else: {
        const Graph::Checkpoint mark = eng_.mark();
        ++open_marks_;
        const bool ok = block(n.body);
        --open_marks_;
        if (!ok) undo(mark);
        eng_.release(mark);
        if (ok || n.otherwise.empty()) return ok;
        return block(n.otherwise);
      }
      case StrategyNode::Op::backtrack: return backtrack(n);
      case StrategyNode::Op::search: return search(n);
      case StrategyNode::Op::beam: return beam(n);
      case StrategyNode::Op::when: return domain_.measures.at(n.goal)() == 0;
    }
    return false;
  }

  bool limit_reached() {
    if (eng_.counters().steps < domain_.max_steps) return false;
    stop_ = out_.step_limit_hit = true;
    return true;
  }

  /// After an application the domain is shown, made at graph position `before`.
  void after(Graph::Checkpoint before) {
    if (domain_.after_undo) {
      // What was shown before the oldest open checkpoint is kept for good.
      while (!shown_.empty() && shown_.front().first < eng_.oldest_checkpoint()) shown_.pop_front();
      if (eng_.oldest_checkpoint() <= before) shown_.emplace_back(before, app_.step);
    }
    if (domain_.after_step) domain_.after_step(app_);
  }

  /// Engine::undo, telling the domain which of the applications it was shown go.
  void undo(Graph::Checkpoint c) {
    eng_.undo(c);
    while (!shown_.empty() && shown_.back().first >= c) {
      if (domain_.after_undo) domain_.after_undo(shown_.back().second);
      shown_.pop_back();
    }
  }

  bool apply(Engine::Selection s) {
    const Graph::Checkpoint before = eng_.position();
    if (limit_reached() || !eng_.step(s, &app_)) return false;
    after(before);
    return true;
  }

  // Alternatives are looked for only on a dead end, so a run that never gets
  // stuck pays one checkpoint a step and nothing else.
  bool backtrack(const StrategyNode& n) {
    const Engine::Selection s = selection_.at(&n.body.front());
    const auto& goal = domain_.measures.at(n.goal);
    const bool backtracking = n.max_backtracks > 0 && n.branching > 1 && n.window > 0;
    std::deque<Choice> choices;
    std::size_t backtracks = 0;
    auto go_back = [&] {
      while (!choices.empty() && backtracks < n.max_backtracks) {
        Choice& c = choices.back();
        undo(c.before);
        if (c.taken + 1 < n.branching) {
          auto alternatives = eng_.choices(s, c.taken + 2);
          if (alternatives.size() > c.taken + 1) {
            ++backtracks;
            eng_.apply(std::move(alternatives[++c.taken]), &app_);
            after(c.before);
            return true;
          }
        }
        eng_.release(c.before);
        choices.pop_back();
      }
      return false;
    };
    std::int64_t smallest = goal();
    std::size_t since_smallest = 0;
    auto stalled = [&] {
      const std::int64_t now = goal();
      if (now < smallest) smallest = now, since_smallest = 0;
      return ++since_smallest > static_cast<std::size_t>(4 * smallest + 256);
    };
    while (!limit_reached()) {
      if (backtracking) {
        choices.push_back({eng_.mark(), 0});
        // Inside a try, the oldest checkpoint is the try's: the window then grows.
        if (choices.size() > n.window && open_marks_ == 0) {
          eng_.release_oldest();
          choices.pop_front();
        }
      }
      const Graph::Checkpoint before = eng_.position();
      if (eng_.step(s, &app_)) {
        after(before);
        if (goal() == 0 || !stalled()) continue;
        out_.stalled = true;
        out_.stalled_for = since_smallest;
        break;
      }
      if (backtracking) {
        eng_.release(choices.back().before);
        choices.pop_back();
      }
      if (goal() == 0 || !backtracking || !go_back()) break;
    }
    while (!choices.empty()) {
      eng_.release(choices.front().before);
      choices.pop_front();
    }
    out_.backtracks += backtracks;
    phase_->backtracks += backtracks;
    return goal() == 0;
  }

  // Iterative deepening: memory is one checkpoint a level, and the first goal
  // found is one of fewest applications. The path to it is applied again
  // from the start, so that the domain sees each kept application on the
  // graph it was made on, and none of those undone.
  bool search(const StrategyNode& n) {
    const Engine::Selection s = selection_.at(&n.body.front());
    const auto& goal = domain_.measures.at(n.goal);
    if (goal() == 0) return true;
    std::vector<Match> path, found;
    std::size_t tried = 0;
    std::function<bool(std::size_t)> deepen = [&](std::size_t depth) {
      for (Match& m : eng_.choices(s, n.branching)) {
        if (tried >= n.max_tried || limit_reached()) return false;
        const Graph::Checkpoint before = eng_.mark();
        path.push_back(m);
        eng_.apply(std::move(m));
        ++tried;
        const bool done = goal() == 0 || (depth > 1 && deepen(depth - 1));
        if (done && found.empty()) found = path;
        eng_.undo(before);
        eng_.release(before);
        path.pop_back();
        if (done) return true;
      }
      return false;
    };
    for (std::size_t depth = 1; depth <= n.depth && found.empty() && tried < n.max_tried && !stop_; ++depth)
      deepen(depth);
    phase_->searched += tried;
    for (Match& m : found) {
      const Graph::Checkpoint before = eng_.position();
      eng_.apply(std::move(m), &app_);
      after(before);
    }
    return !found.empty();
  }

  // A state is its path from where the beam began. The graph holds one path
  // at a time, with a checkpoint before each of its applications; going to
  // another state undoes back to where the two paths part and applies the
  // rest, so siblings (expanded one after the other) cost little.
  bool beam(const StrategyNode& n) {
    const Engine::Selection s = selection_.at(&n.body.front());
    const auto& goal = domain_.measures.at(n.goal);
    const auto& cost = domain_.measures.at(n.cost);
    if (goal() == 0) return true;
    struct State {
      std::int64_t cost;
      std::size_t made;  ///< the order states were made in: ties go to the first
      std::vector<Match> path;
      std::int64_t left = 0;  ///< the goal measure
    };
    std::vector<Match> on_graph;
    std::vector<Graph::Checkpoint> marks;
    auto same = [](const Match& a, const Match& b) {
      return a.rule == b.rule && a.elements == b.elements && a.indices == b.indices;
    };
    auto back_to = [&](std::size_t length) {
      while (on_graph.size() > length) {
        eng_.undo(marks.back());
        eng_.release(marks.back());
        marks.pop_back();
        on_graph.pop_back();
      }
    };
    auto go_to = [&](const std::vector<Match>& path) {
      std::size_t common = 0;
      while (common < on_graph.size() && common < path.size() && same(on_graph[common], path[common])) ++common;
      back_to(common);
      for (std::size_t i = common; i < path.size(); ++i) {
        marks.push_back(eng_.mark());
        eng_.apply(path[i]);
        on_graph.push_back(path[i]);
      }
    };
    std::vector<State> level{{cost(), 0, {}, goal()}}, found;
    State closest = level.front();
    std::size_t tried = 0, made = 0;
    auto cheaper = [](const State& a, const State& b) { return a.cost != b.cost ? a.cost < b.cost : a.made < b.made; };
    auto closer = [&](const State& a, const State& b) { return a.left != b.left ? a.left < b.left : cheaper(a, b); };
    for (std::size_t depth = 1; depth <= n.depth && found.empty() && !level.empty(); ++depth) {
      std::vector<State> next;
      // Expanded in the order they were made, so that siblings come together.
      std::sort(level.begin(), level.end(), [](const State& a, const State& b) { return a.made < b.made; });
      for (const State& state : level) {
        if (tried >= n.max_tried || limit_reached()) break;
        go_to(state.path);
        for (Match& m : eng_.choices(s, n.branching)) {
          if (tried >= n.max_tried || limit_reached()) break;
          const Graph::Checkpoint before = eng_.mark();
          State child{0, ++made, state.path};
          child.path.push_back(m);
          eng_.apply(std::move(m));
          ++tried;
          child.cost = cost();
          child.left = goal();
          if (closer(child, closest)) closest = child;
          (child.left == 0 ? found : next).push_back(std::move(child));
          eng_.undo(before);
          eng_.release(before);
        }
      }
      std::sort(next.begin(), next.end(), cheaper);
      if (next.size() > n.width) next.resize(n.width);
      level = std::move(next);
    }
    back_to(0);
    phase_->searched += tried;
    // Short of the goal, the closest state stays, as a backtrack's progress does.
    std::sort(found.begin(), found.end(), cheaper);
    for (Match& m : found.empty() ? closest.path : found.front().path) {
      const Graph::Checkpoint before = eng_.position();
      eng_.apply(std::move(m), &app_);
      after(before);
    }
    return !found.empty();
  }

  Engine& eng_;
  const Strategy& strategy_;
  const StrategyDomain& domain_;
  std::map<const StrategyNode*, Engine::Selection> selection_;
  StrategyOutcome out_;
  PhaseFigures* phase_ = nullptr;
  Application app_;
  /// The applications shown to the domain that an open checkpoint could
  /// still undo: (graph position before it, step), oldest first.
  std::deque<std::pair<Graph::Checkpoint, std::size_t>> shown_;
  int open_marks_ = 0;
  bool stop_ = false;
};

}  // namespace

void check_strategy(const Strategy& strategy, const std::vector<Rule>& rules, const std::vector<std::string>& measures) {
  for (const StrategyPhase& p : strategy.phases)
    each_node(p.body, [&](const StrategyNode& n) {
      for (const std::string& name : n.rules)
        if (std::none_of(rules.begin(), rules.end(), [&](const Rule& r) { return r.name == name; }))
          throw RuleError(strategy.source, n.pos, fmt::format("no rule '{}' is loaded; see 'loom rules list'", name));
      const bool has_goal = n.op == StrategyNode::Op::backtrack || n.op == StrategyNode::Op::search ||
                            n.op == StrategyNode::Op::beam || n.op == StrategyNode::Op::when;
      auto known = [&](const std::string& name, const char* role) {
        if (std::find(measures.begin(), measures.end(), name) != measures.end()) return;
        std::string list;
        for (const auto& m : measures) list += (list.empty() ? "" : ", ") + m;
        throw RuleError(strategy.source, n.pos,
                        fmt::format("no measure '{}' to make {} of; this domain has: {}", name, role,
                                    list.empty() ? "none" : list));
      };
      if (has_goal) known(n.goal, "a goal");
      if (n.op == StrategyNode::Op::beam) known(n.cost, "a cost");
    });
}

StrategyOutcome run_strategy(Engine& engine, const Strategy& strategy, const StrategyDomain& domain) {
  return Runner(engine, strategy, domain).run();
}

}  // namespace loom::engine
