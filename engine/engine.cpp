#include "engine/engine.hpp"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "engine/random_draws.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

Engine::Engine(Graph& graph, std::vector<Rule> rules, Actions actions, std::uint64_t seed)
    : g_(graph), rules_(std::move(rules)), actions_(std::move(actions)), matcher_(graph), state_(rules_.size()),
      rng_(seed) {
  for (Rule& r : rules_) {
    check_actions(r, actions_, g_.schema());
    bind_measures(r, actions_);
  }
  index_relevance();
}

Engine::Selection Engine::select(StrategyNode::Pick pick, bool all, const std::vector<std::string>& names) {
  std::vector<std::size_t> chosen;
  for (const std::string& name : names)
    if (std::none_of(rules_.begin(), rules_.end(), [&](const Rule& r) { return r.name == name; }))
      throw std::invalid_argument(fmt::format("no rule '{}' is loaded", name));
  if (all) {
    for (std::size_t i = 0; i < rules_.size(); ++i)
      if (std::find(names.begin(), names.end(), rules_[i].name) == names.end()) chosen.push_back(i);
  } else {
    for (const std::string& name : names)
      chosen.push_back(rule_index(&*std::find_if(rules_.begin(), rules_.end(), [&](const Rule& r) { return r.name == name; })));
  }
  SelectionState s;
  s.random = pick == StrategyNode::Pick::random;
  if (pick == StrategyNode::Pick::sequence) {
    for (std::size_t r : chosen) s.tiers.push_back({r});
  } else {  // by descending priority, ties in load order
    std::stable_sort(chosen.begin(), chosen.end(), [&](std::size_t a, std::size_t b) { return rules_[a].priority > rules_[b].priority; });
    for (std::size_t r : chosen) {
      if (s.tiers.empty() || rules_[s.tiers.back().front()].priority != rules_[r].priority) s.tiers.emplace_back();
      s.tiers.back().push_back(r);
    }
  }
  selections_.push_back(std::move(s));
  return selections_.size() - 1;
}

Engine::Selection Engine::all_by_priority() {
  if (all_by_priority_ == SIZE_MAX) all_by_priority_ = select(StrategyNode::Pick::priority, true, {});
  return all_by_priority_;
}

void Engine::activate(SelectionState& s) {
  s.active = true;
  for (const auto& tier : s.tiers)
    for (std::size_t r : tier) {
      RuleState& st = state_[r];
      bool& use = s.random ? st.use_pool : st.use_queue;
      if (use) continue;
      const bool other = st.use_pool || st.use_queue;
      use = true;
      if (!other) {
        for (Id a : g_.members(rules_[r].vars[rules_[r].anchor].kind)) offer(r, a);
        continue;
      }
      // Kept up to date for the other pick already: copy its candidates.
      if (s.random) {
        auto queue = st.queue;
        for (; !queue.empty(); queue.pop()) offer(r, queue.top().anchor);
      } else {
        for (Id a : std::vector<Id>(st.pool)) offer(r, a);
      }
    }
}

void Engine::rescan() {
  for (std::size_t r = 0; r < rules_.size(); ++r)
    if (state_[r].use_queue || state_[r].use_pool)
      for (Id a : g_.members(rules_[r].vars[rules_[r].anchor].kind)) offer(r, a);
}

bool Engine::match_at(std::size_t r, Id anchor, Match& m) {
  const Rule& rule = rules_[r];
  ++counters_.match_attempts;
  if (!g_.alive(anchor)) return false;
  if (rule.tests.empty()) return matcher_.first_at(rule, anchor, m);
  // A test may change the graph (and undo it): the matches are copied first.
  std::vector<Match> found;
  matcher_.each_at(rule, anchor, [&](const Match& one) {
    found.push_back(one);
    return true;
  });
  for (Match& one : found)
    if (passes_tests(g_, one, actions_)) {
      m = std::move(one);
      return true;
    }
  return false;
}

void Engine::offer(std::size_t r, Id anchor) {
  const Rule& rule = rules_[r];
  RuleState& st = state_[r];
  if (!g_.alive(anchor) || g_.kind(anchor) != rule.vars[rule.anchor].kind) return;
  ++counters_.candidates;
  auto mark = [&](std::vector<bool>& in) {
    if (in.size() <= anchor) in.resize(g_.id_bound() + 1024, false);
    const bool fresh = !in[anchor];
    in[anchor] = true;
    return fresh;
  };
  if (st.use_pool && mark(st.pooled)) st.pool.push_back(anchor);
  if (!st.use_queue) return;
  if (!rule.order) {  // no key to compute: it is matched once, when chosen
    // Queued at most once: a rule whose turn comes late (a low priority)
    // would otherwise meet every change since as a duplicate.
    if (mark(st.queued)) st.queue.push({0, anchor});
    return;
  }
  if (!match_at(r, anchor, scratch_)) return;
  st.queue.push({matcher_.evaluate(*rule.order, scratch_), anchor});
}

bool Engine::step(Selection selection, Application* applied) {
  SelectionState& s = selections_.at(selection);
  if (!s.active) activate(s);
  for (const auto& tier : s.tiers) {
    if (s.random) {
      if (try_random_tier(tier, applied)) return true;
      continue;
    }
    for (std::size_t r : tier)
      if (try_rule_queue(r, applied)) return true;
  }
  return false;
}

bool Engine::pop_best(std::size_t r, Entry& entry, Match& m) {
  const Rule& rule = rules_[r];
  auto& queue = state_[r].queue;
  while (!queue.empty()) {
    entry = queue.top();
    queue.pop();
    if (!rule.order) state_[r].queued[entry.anchor] = false;
    if (!match_at(r, entry.anchor, m)) continue;
    std::int64_t key = rule.order ? matcher_.evaluate(*rule.order, m) : 0;
    if (key > entry.key) {  // its key grew since it was queued: take its new place
      queue.push({key, entry.anchor});
      continue;
    }
    return true;
  }
  return false;
}

bool Engine::try_rule_queue(std::size_t r, Application* applied) {
  Entry entry;
  Match m;
  if (!pop_best(r, entry, m)) return false;
  apply_rule(r, m, applied);
  return true;
}

bool Engine::try_random_tier(const std::vector<std::size_t>& tier, Application* applied) {
  for (;;) {
    std::size_t total = 0;
    for (std::size_t r : tier) total += state_[r].pool.size();
    if (total == 0) return false;
    std::size_t pick = uniform_below(rng_, total);
    std::size_t r = tier.front();
    for (std::size_t t : tier) {
      if (pick < state_[t].pool.size()) {
        r = t;
        break;
      }
      pick -= state_[t].pool.size();
    }
    RuleState& st = state_[r];
    Id anchor = st.pool[pick];
    st.pool[pick] = st.pool.back();
    st.pool.pop_back();
    st.pooled[anchor] = false;
    Match m;
    if (!match_at(r, anchor, m)) continue;
    apply_rule(r, m, applied);
    return true;
  }
}

std::vector<Match> Engine::choices(Selection selection, std::size_t limit) {
  SelectionState& s = selections_.at(selection);
  if (!s.active) activate(s);
  std::vector<Match> out;
  for (const auto& tier : s.tiers) {
    for (std::size_t r : tier) {
      const Rule& rule = rules_[r];
      if (s.random) {
        // The pool in a seeded shuffled order; invalid anchors leave the pool.
        auto& pool = state_[r].pool;
        engine::shuffle(pool.begin(), pool.end(), rng_);
        for (std::size_t i = 0; i < pool.size() && out.size() < limit;) {
          Match m;
          if (match_at(r, pool[i], m)) {
            out.push_back(std::move(m));
            ++i;
          } else {
            state_[r].pooled[pool[i]] = false;
            pool[i] = pool.back();
            pool.pop_back();
          }
        }
        continue;
      }
      std::vector<Entry> keep;
      Entry entry;
      Match m;
      while (out.size() < limit && pop_best(r, entry, m)) {
        bool seen = std::any_of(keep.begin(), keep.end(), [&](const Entry& e) { return e.anchor == entry.anchor; });
        keep.push_back(entry);
        if (!seen) out.push_back(m);
      }
      for (const Entry& e : keep) {
        if (!rule.order) state_[r].queued[e.anchor] = true;
        state_[r].queue.push(e);
      }
    }
    if (!out.empty()) return out;
  }
  return out;
}

void Engine::apply(Match m, Application* applied) { apply_rule(rule_index(m.rule), m, applied); }

void Engine::undo(Graph::Checkpoint c) {
  ++counters_.undos;
  log_.clear();
  g_.set_change_log(&log_);
  g_.rollback(c);
  g_.set_change_log(nullptr);
  // No element is new after a rollback: a slot that went with a dropped
  // element may have been what blocked a negative pattern.
  process_changes(no_element);
}

void Engine::apply_rule(std::size_t r, Match& m, Application* applied) {
  if (applied) {  // read only when the rewrite acts
    applied->matched = m;
    applied->first_new = g_.id_bound();
  }
  log_.clear();
  g_.set_change_log(&log_);
  const Id first_new = g_.id_bound();
  const Graph::Checkpoint before = g_.checkpoint();
  // The rewrite's changes reach the candidate queues only once it is kept,
  // so a rollback leaves them as they were.
  auto roll_back = [&] {
    g_.set_change_log(nullptr);
    g_.rollback(before);
    g_.release(before);
    log_.clear();
  };
  try {
    apply_rewrite(g_, m, actions_);
    check_application(rules_[r]);
  } catch (const std::bad_alloc&) {
    // Out of memory the graph may be half-updated; the run ends without it.
    g_.set_change_log(nullptr);
    throw;
  } catch (...) {
    roll_back();
    throw;
  }
  g_.set_change_log(nullptr);
  g_.release(before);
  ++counters_.steps;
  ++applications_[rules_[r].name];
  if (applied) {
    applied->step = counters_.steps;
    applied->rule = &rules_[r];
    applied->result = m;
  }
  if (full_rescan_) rescan();
  else process_changes(first_new);
}

void Engine::check_after(Invariant check, const std::vector<std::string>& rules) {
  invariant_ = std::move(check);
  checked_.assign(rules_.size(), rules.empty());
  for (const std::string& name : rules) {
    auto it = std::find_if(rules_.begin(), rules_.end(), [&](const Rule& r) { return r.name == name; });
    if (it == rules_.end()) throw std::invalid_argument(fmt::format("no rule '{}' is loaded to check", name));
    checked_[rule_index(&*it)] = true;
  }
}

void Engine::check_application(const Rule& rule) const {
  const Schema& schema = g_.schema();
  for (const Graph::Change& c : log_) {
    if ((c.kind != Graph::Change::Kind::out && c.kind != Graph::Change::Kind::created) || !g_.alive(c.element)) continue;
    const KindSpec& kind = schema.kind(g_.kind(c.element));
    for (PortId p : kind.ports) {
      const PortSpec& port = schema.port(p);
      if (port.presence != PortPresence::required) continue;
      for (unsigned i = 0; i < port.arity; ++i)
        if (g_.at(c.element, p, i) == no_element)
          throw RuleError(rule.file, rule.pos,
                          fmt::format("rule '{}' left {} {}'s {}[{}] empty, which must not be; the rewrite was rolled back",
                                      rule.name, kind.name, c.element, port.name, i));
    }
  }
  if (invariant_ && checked_[rule_index(&rule)])
    if (std::string broken = invariant_(g_); !broken.empty())
      throw RuleError(rule.file, rule.pos,
                      fmt::format("rule '{}' broke an invariant: {}; the rewrite was rolled back", rule.name, broken));
}

}  // namespace loom::engine
