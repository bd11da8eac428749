// Incremental matching: which anchors a change to the graph makes candidates
// again. Each change (an element created, a port or attribute written) is
// traced back from the variables it can concern to the anchors whose match
// could read it; only those are matched again.
#include <algorithm>
#include <tuple>

#include "engine/engine.hpp"

namespace loom::engine {

// For each rule, which variables a change (element kind, change kind, port or
// attribute) can concern: looked up once per change instead of searched.
// Variables a change reaches only through a negative pattern are listed
// apart: an element the step created, or a slot it added, can only make a
// negative pattern match, so it cannot give the rule a match it had not.
void Engine::index_relevance() {
  const Schema& schema = g_.schema();
  width_ = std::max(schema.port_count(), schema.attribute_count()) + 1;
  for (std::size_t r = 0; r < rules_.size(); ++r) {
    auto& table = state_[r].relevant;
    auto& negative = state_[r].relevant_to_negatives;
    table.assign(schema.kind_count() * 3 * width_, {});
    negative.assign(table.size(), {});
    const Rule& rule = rules_[r];
    for (int v = 0; v < static_cast<int>(rule.vars.size()); ++v) {
      const Variable& var = rule.vars[v];
      if (var.created || var.nac == -2) continue;
      auto& own = var.nac >= 0 ? negative : table;
      for (PortId p : var.out_ports) own[relevance_key(var.kind, 0, p)].push_back(v);
      for (AttrId a : var.attrs) own[relevance_key(var.kind, 2, a)].push_back(v);
      for (PortId p : var.in_ports) table[relevance_key(var.kind, 1, p)].push_back(v);
      for (PortId p : var.negative_in_ports) negative[relevance_key(var.kind, 1, p)].push_back(v);
    }
  }
}

void Engine::trace(const Rule& rule, int var, Id element) {
  current_.assign(1, element);
  while (var != rule.anchor) {
    const Variable& v = rule.vars[var];
    if (v.parent < 0) return;
    next_.clear();
    for (Id e : current_) {
      if (!g_.alive(e)) continue;
      if (v.via == Variable::Via::lookup) {  // parent.port -> e: the owners of such slots
        for (SlotId s : g_.incoming(e))
          if (g_.slot_port(s) == v.via_port) next_.push_back(g_.slot_owner(s));
      } else {  // e.port -> parent
        const PortSpec& p = g_.schema().port(v.via_port);
        for (unsigned i = 0; i < p.arity; ++i)
          if (Id t = g_.at(e, v.via_port, i); t != no_element) next_.push_back(t);
      }
    }
    std::swap(current_, next_);
    var = v.parent;
  }
  anchors_.insert(anchors_.end(), current_.begin(), current_.end());
}

void Engine::process_changes(Id first_new) {
  auto fields = [](const Graph::Change& c) { return std::tie(c.element, c.kind, c.which, c.owner); };
  std::sort(log_.begin(), log_.end(), [&](const Graph::Change& a, const Graph::Change& b) { return fields(a) < fields(b); });
  log_.erase(std::unique(log_.begin(), log_.end(),
                         [&](const Graph::Change& a, const Graph::Change& b) { return fields(a) == fields(b); }),
             log_.end());
  using Kind = Graph::Change::Kind;
  for (std::size_t r = 0; r < rules_.size(); ++r) {
    if (!state_[r].use_queue && !state_[r].use_pool) continue;
    const Rule& rule = rules_[r];
    if (rule.global) {
      ++counters_.rescans;
      for (Id a : g_.members(rule.vars[rule.anchor].kind)) offer(r, a);
      continue;
    }
    // A match that only a negative pattern stops is found again when chosen;
    // only an order key (which a lost match may lower) or a random pool
    // (whose size the draws read) needs the anchor offered again.
    const bool skip_new_negatives = !rule.order && !state_[r].use_pool;
    anchors_.clear();
    seeds_.clear();  // (variable, element) pairs to trace, each once
    for (const Graph::Change& c : log_) {
      if (c.element >= g_.id_bound()) continue;  // created, then rolled back
      KindId k = g_.kind(c.element);
      if (c.kind == Kind::created) {
        if (k == rule.vars[rule.anchor].kind) anchors_.push_back(c.element);
        continue;
      }
      if (c.kind == Kind::removed) continue;
      int ck = c.kind == Kind::out ? 0 : c.kind == Kind::in ? 1 : 2;
      const std::size_t key = relevance_key(k, ck, c.which);
      for (int v : state_[r].relevant[key]) seeds_.push_back({v, c.element});
      const bool from_new = (c.kind == Kind::in ? c.owner : c.element) >= first_new;
      if (!(skip_new_negatives && from_new))
        for (int v : state_[r].relevant_to_negatives[key]) seeds_.push_back({v, c.element});
      for (const CountWatch& w : rule.count_watches) {
        bool reads = (c.kind == Kind::attribute && std::count(w.attrs.begin(), w.attrs.end(), c.which)) ||
                     (c.kind == Kind::out && std::count(w.ports.begin(), w.ports.end(), c.which));
        if (!reads || w.kind != k || !g_.alive(c.element)) continue;
        for (unsigned i = 0; i < g_.schema().port(w.port).arity; ++i)
          if (Id t = g_.at(c.element, w.port, i); t != no_element) seeds_.push_back({w.target, t});
      }
    }
    std::sort(seeds_.begin(), seeds_.end());
    seeds_.erase(std::unique(seeds_.begin(), seeds_.end()), seeds_.end());
    for (auto [v, e] : seeds_) trace(rule, v, e);
    if (stamp_.size() < g_.id_bound()) stamp_.resize(g_.id_bound() + 1024, 0);
    ++stamp_now_;
    for (Id a : anchors_)
      if (stamp_[a] != stamp_now_) {
        stamp_[a] = stamp_now_;
        offer(r, a);
      }
  }
}

}  // namespace loom::engine
