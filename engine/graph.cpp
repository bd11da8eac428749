#include "engine/graph.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace loom::engine {

Graph::Graph(std::shared_ptr<const Schema> schema)
    : schema_(std::move(schema)),
      kind_members_(schema_->kind_count()),
      kind_live_(schema_->kind_count(), 0),
      columns_(schema_->kind_count()) {
  for (std::size_t k = 0; k < schema_->kind_count(); ++k)
    columns_[k].resize(schema_->kind(static_cast<KindId>(k)).attributes.size());
}

Id Graph::add(KindId kind) {
  const KindSpec& spec = schema_->kind(kind);
  Id id = static_cast<Id>(elements_.size());
  auto local = static_cast<std::uint32_t>(kind_members_[kind].size());
  elements_.push_back(Element{static_cast<SlotId>(slots_.size()), no_slot, 0, local, kind, true});
  for (unsigned i = 0; i < spec.slot_count; ++i) slots_.push_back(Slot{id, no_element, no_slot, no_slot});
  kind_members_[kind].push_back(id);
  for (std::size_t c = 0; c < spec.attributes.size(); ++c)
    columns_[kind][c].push_back(schema_->attribute(spec.attributes[c]).default_value);
  ++kind_live_[kind];
  ++live_;
  ++revision_;
  if (log_) log_->push_back({id, Change::Kind::created, 0});
  if (!open_.empty()) undo_.push_back({UndoRecord::Kind::created, id, 0, 0});
  return id;
}

void Graph::remove(Id e) {
  Element& el = elements_[e];
  if (!el.alive) return;
  for (SlotId s = el.first_slot, end = s + slot_count(e); s < end; ++s) set_slot(s, no_element);
  while (el.in_head != no_slot) set_slot(el.in_head, no_element);
  el.alive = false;
  ++revision_;
  if (log_) log_->push_back({e, Change::Kind::removed, 0});
  if (!open_.empty()) undo_.push_back({UndoRecord::Kind::removed, e, 0, 0});
  kind_members_[el.kind][el.local] = no_element;
  --kind_live_[el.kind];
  --live_;
}

std::vector<Id> Graph::members(KindId kind) const {
  std::vector<Id> out;
  out.reserve(kind_live_[kind]);
  for (Id id : kind_members_[kind])
    if (id != no_element) out.push_back(id);
  return out;
}

void Graph::set_slot(SlotId s, Id target) {
  Slot& sl = slots_[s];
  if (sl.target == target) return;
  ++revision_;
  if (log_) {
    auto port = slot_port(s);
    log_->push_back({sl.owner, Change::Kind::out, port});
    if (sl.target != no_element) log_->push_back({sl.target, Change::Kind::in, port, sl.owner});
    if (target != no_element) log_->push_back({target, Change::Kind::in, port, sl.owner});
  }
  if (!open_.empty()) undo_.push_back({UndoRecord::Kind::slot, s, sl.target, 0});
  if (sl.target != no_element) {
    ring_erase(s);
    --linked_;
  }
  sl.target = target;
  if (target != no_element) {
    ring_insert(s);
    ++linked_;
  }
}

void Graph::ring_insert(SlotId s) {
  Slot& sl = slots_[s];
  SlotId& head = elements_[sl.target].in_head;
  sl.prev = no_slot;
  sl.next = head;
  if (head != no_slot) slots_[head].prev = s;
  head = s;
  ++elements_[sl.target].in_count;
}

void Graph::ring_erase(SlotId s) {
  Slot& sl = slots_[s];
  if (sl.prev != no_slot) slots_[sl.prev].next = sl.next;
  else elements_[sl.target].in_head = sl.next;
  if (sl.next != no_slot) slots_[sl.next].prev = sl.prev;
  sl.next = sl.prev = no_slot;
  --elements_[sl.target].in_count;
}

unsigned Graph::slot_index(SlotId s) const {
  return s - elements_[slots_[s].owner].first_slot - schema_->port(slot_port(s)).first_slot;
}

void Graph::redirect_incoming(Id from, Id to) {
  if (from == to) return;
  while (elements_[from].in_head != no_slot) set_slot(elements_[from].in_head, to);
}

std::int32_t Graph::get(Id e, AttrId a) const {
  const Element& el = elements_[e];
  return columns_[el.kind][schema_->attribute(a).column][el.local];
}

void Graph::set(Id e, AttrId a, std::int32_t value) {
  const Element& el = elements_[e];
  std::int32_t& cell = columns_[el.kind][schema_->attribute(a).column][el.local];
  if (cell == value) return;
  ++revision_;
  if (!open_.empty()) undo_.push_back({UndoRecord::Kind::attribute, e, static_cast<std::uint32_t>(cell), a});
  cell = value;
  if (log_) log_->push_back({e, Change::Kind::attribute, a});
}

std::vector<Id> Graph::compact() {
  if (!open_.empty()) throw std::logic_error("Graph::compact: a checkpoint is open");
  ++revision_;
  std::vector<Id> remap(elements_.size(), no_element);
  Id next = 0;
  for (Id e = 0; e < elements_.size(); ++e)
    if (elements_[e].alive) remap[e] = next++;

  Graph fresh(schema_);
  fresh.elements_.reserve(next);
  for (Id e = 0; e < elements_.size(); ++e) {
    if (!elements_[e].alive) continue;
    const Element& el = elements_[e];
    Id ne = fresh.add(el.kind);
    const KindSpec& spec = schema_->kind(el.kind);
    for (std::size_t c = 0; c < spec.attributes.size(); ++c)
      fresh.columns_[el.kind][c][fresh.elements_[ne].local] = columns_[el.kind][c][el.local];
  }
  // Link in old slot order so incoming rings keep a reproducible order.
  for (SlotId s = 0; s < slots_.size(); ++s) {
    const Slot& sl = slots_[s];
    if (sl.target == no_element || !elements_[sl.owner].alive) continue;
    SlotId ns = fresh.elements_[remap[sl.owner]].first_slot + (s - elements_[sl.owner].first_slot);
    fresh.set_slot(ns, remap[sl.target]);
  }
  *this = std::move(fresh);
  return remap;
}

std::string Graph::check_structure() const {
  std::size_t live = 0, linked = 0;
  std::vector<std::size_t> per_kind(schema_->kind_count(), 0);
  for (Id e = 0; e < elements_.size(); ++e) {
    const Element& el = elements_[e];
    if (!el.alive) {
      if (el.in_head != no_slot) return fmt::format("removed element {} is still pointed at", e);
      continue;
    }
    ++live;
    ++per_kind[el.kind];
    if (kind_members_[el.kind][el.local] != e) return fmt::format("element {} is missing from its kind list", e);
    const KindSpec& spec = schema_->kind(el.kind);
    for (PortId p : spec.ports) {
      const PortSpec& ps = schema_->port(p);
      for (unsigned i = 0; i < ps.arity; ++i) {
        SlotId s = el.first_slot + ps.first_slot + i;
        const Slot& sl = slots_[s];
        if (sl.owner != e) return fmt::format("slot {} of element {} names owner {}", s, e, sl.owner);
        if (sl.target == no_element) continue;
        ++linked;
        if (!alive(sl.target))
          return fmt::format("{} {}.{}[{}] points at removed element {}", spec.name, e, ps.name, i, sl.target);
        if (elements_[sl.target].kind != ps.target)
          return fmt::format("{} {}.{}[{}] points at a {} (expected {})", spec.name, e, ps.name, i,
                             schema_->kind(elements_[sl.target].kind).name, schema_->kind(ps.target).name);
      }
    }
    SlotId prev = no_slot;
    std::uint32_t ring = 0;
    for (SlotId s = el.in_head; s != no_slot; s = slots_[s].next, ++ring) {
      if (slots_[s].target != e) return fmt::format("incoming ring of {} holds slot {} aimed elsewhere", e, s);
      if (slots_[s].prev != prev) return fmt::format("incoming ring of {} is broken at slot {}", e, s);
      prev = s;
    }
    if (ring != el.in_count) return fmt::format("element {} counts {} incoming slots but its ring has {}", e, el.in_count, ring);
  }
  std::size_t ringed = 0;
  for (Id e = 0; e < elements_.size(); ++e) ringed += elements_[e].alive ? in_degree(e) : 0;
  if (ringed != linked) return fmt::format("{} slots are linked but {} are in incoming rings", linked, ringed);
  if (live != live_ || linked != linked_) return "element or incidence counters are off";
  for (std::size_t k = 0; k < per_kind.size(); ++k)
    if (per_kind[k] != kind_live_[k]) return fmt::format("kind {} count is off", schema_->kind(static_cast<KindId>(k)).name);
  return {};
}

}  // namespace loom::engine
