#pragma once
// Graph: a typed incidence graph with ordered ports, stable ids and O(1) local
// rewrites.
//
// Elements (the graph's vertices, in Boost.Graph words) have a kind from the
// Schema. Each element owns the slots of its kind's ports; a slot holds the id
// of the element it points at, or no_element. Every slot is one incidence (one
// directed graph edge, owner -> target). Each element also keeps a doubly linked
// ring of the slots that point at it, so reverse lookups ("which faces use this
// edge") cost the number of such slots, and linking, unlinking and redirecting
// cost O(1) per slot (GrGen.NET's ring lists).
//
// Ids are stable: remove() leaves a tombstone and never renumbers; compact()
// renumbers on request and returns the map.
//
// Invariants (checked by check_structure()):
//  - a slot's owner is alive, and its target is no_element or an alive element
//    of the port's target kind;
//  - a slot is in its target's incoming ring exactly when its target is set;
//  - ring links are mutually consistent (next->prev == this);
//  - the per-kind member lists hold exactly the alive elements of that kind.
#include <cstdint>
#include <deque>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "engine/schema.hpp"

namespace loom::engine {

using Id = std::uint32_t;      ///< element id, stable until compact()
using SlotId = std::uint32_t;  ///< incidence id, stable until compact()
inline constexpr Id no_element = UINT32_MAX;
inline constexpr SlotId no_slot = UINT32_MAX;

class Graph {
public:
  explicit Graph(std::shared_ptr<const Schema> schema);

  const Schema& schema() const { return *schema_; }
  const std::shared_ptr<const Schema>& schema_ptr() const { return schema_; }

  // --- elements -----------------------------------------------------------
  /// Adds an element of `kind` with every slot empty and default attributes.
  Id add(KindId kind);
  /// Empties every slot of `e` and every slot pointing at `e`, then tombstones it.
  void remove(Id e);
  bool alive(Id e) const { return e < elements_.size() && elements_[e].alive; }
  KindId kind(Id e) const { return elements_[e].kind; }
  /// Every id handed out so far is below this bound (tombstones included).
  Id id_bound() const { return static_cast<Id>(elements_.size()); }
  std::size_t size() const { return live_; }
  std::size_t size(KindId kind) const { return kind_live_.at(kind); }
  std::size_t incidence_count() const { return linked_; }
  /// Alive elements of `kind`, in id order (a snapshot).
  std::vector<Id> members(KindId kind) const;
  /// Changes whenever the graph does: a cheap test for caches of what is
  /// derived from it.
  std::uint64_t revision() const { return revision_; }

  // --- ports --------------------------------------------------------------
  Id at(Id e, PortId p, unsigned i = 0) const { return slots_[slot(e, p, i)].target; }
  SlotId slot(Id e, PortId p, unsigned i = 0) const {
    return elements_[e].first_slot + schema_->port(p).first_slot + i;
  }
  /// Points slot i of port p of e at `target` (no_element empties it).
  void link(Id e, PortId p, unsigned i, Id target) { set_slot(slot(e, p, i), target); }
  void set_slot(SlotId s, Id target);

  SlotId first_slot(Id e) const { return elements_[e].first_slot; }
  unsigned slot_count(Id e) const { return schema_->kind(elements_[e].kind).slot_count; }
  Id slot_owner(SlotId s) const { return slots_[s].owner; }
  Id slot_target(SlotId s) const { return slots_[s].target; }
  SlotId slot_bound() const { return static_cast<SlotId>(slots_.size()); }
  /// The port a slot belongs to, and its index within the port.
  PortId slot_port(SlotId s) const {
    const Element& owner = elements_[slots_[s].owner];
    return schema_->port_of_slot(owner.kind, s - owner.first_slot);
  }
  unsigned slot_index(SlotId s) const;

  // --- incoming incidences ------------------------------------------------
  class IncomingIterator;
  struct IncomingRange {
    const Graph* g;
    SlotId head;
    IncomingIterator begin() const;
    IncomingIterator end() const;
  };
  /// The slots that point at `e` (most recently linked first).
  IncomingRange incoming(Id e) const { return {this, elements_[e].in_head}; }
  unsigned in_degree(Id e) const { return elements_[e].in_count; }
  SlotId next_incoming(SlotId s) const { return slots_[s].next; }
  SlotId first_incoming(Id e) const { return elements_[e].in_head; }

  /// Makes every slot pointing at `from` point at `to` (identification of two
  /// elements of one kind); O(in-degree of from).
  void redirect_incoming(Id from, Id to);

  // --- attributes ---------------------------------------------------------
  std::int32_t get(Id e, AttrId a) const;
  void set(Id e, AttrId a, std::int32_t value);

  // --- change log -----------------------------------------------------------
  /// One change to the graph, as seen from one element: a slot of its own
  /// (`out`), a slot pointing at it (`in`), an attribute, its creation or removal.
  struct Change {
    enum class Kind : std::uint8_t { out, in, attribute, created, removed };
    Id element;
    Kind kind;
    std::uint16_t which;  ///< port (out, in) or attribute
    Id owner = no_element;  ///< in: the owner of the slot that changed
  };
  /// While set, every change is appended to `log` (nullptr stops logging).
  void set_change_log(std::vector<Change>* log) { log_ = log; }

  // --- undo -----------------------------------------------------------------
  /// A point to roll back to. While any checkpoint is open, every change is
  /// recorded; rollback() undoes the changes made since, newest first
  /// (elements created since are dropped, their ids given out again).
  using Checkpoint = std::size_t;
  Checkpoint checkpoint();
  void rollback(Checkpoint c);
  /// Closes the checkpoint and every later one: their changes are kept. Of
  /// checkpoints opened at one point (nothing changed between them), it
  /// closes the newest only, so nested transactions may start together.
  void release(Checkpoint c);
  /// Closes the oldest open checkpoint only, dropping the records that only
  /// it needed (so a window of recent checkpoints costs bounded memory).
  void release_oldest();
  /// Where a checkpoint opened now would be (nothing is opened). Positions
  /// only grow: a change made at or after position p is undone by a rollback
  /// to any checkpoint c <= p.
  Checkpoint position() const { return undo_base_ + undo_.size(); }
  /// The oldest open checkpoint, or position() when none is open: nothing
  /// before it can be undone any more.
  Checkpoint oldest_checkpoint() const { return open_.empty() ? position() : open_.front(); }

  // --- ids ----------------------------------------------------------------
  /// Drops tombstones and renumbers elements and slots, keeping their order.
  /// Returns old id -> new id (no_element for removed ones). Not allowed
  /// while a checkpoint is open.
  std::vector<Id> compact();

  /// Checks the invariants listed above; returns the first violation found,
  /// or an empty string.
  std::string check_structure() const;

private:
  struct Element {
    SlotId first_slot;
    SlotId in_head;
    std::uint32_t in_count;  ///< length of the incoming ring
    std::uint32_t local;  ///< index among the elements of its kind (attribute row)
    KindId kind;
    bool alive;
  };
  struct Slot {
    Id owner;
    Id target;
    SlotId next;  ///< next slot in the target's incoming ring
    SlotId prev;
  };
  void ring_insert(SlotId s);
  void ring_erase(SlotId s);
  void drop_last_element();

  struct UndoRecord {
    enum class Kind : std::uint8_t { slot, attribute, created, removed } kind;
    std::uint32_t where;    ///< slot, or element
    std::uint32_t old;      ///< previous target (slot) or value (attribute, as bits)
    AttrId attr;
  };
  std::deque<UndoRecord> undo_;
  std::size_t undo_base_ = 0;     ///< records dropped from the front of undo_
  std::vector<Checkpoint> open_;  ///< open checkpoints (absolute positions), oldest first
  std::uint64_t revision_ = 0;

  std::shared_ptr<const Schema> schema_;
  std::vector<Element> elements_;
  std::vector<Slot> slots_;
  std::vector<std::vector<Id>> kind_members_;  ///< per kind: local -> id (tombstones kept)
  std::vector<std::size_t> kind_live_;
  std::vector<std::vector<std::vector<std::int32_t>>> columns_;  ///< [kind][column][local]
  std::size_t live_ = 0, linked_ = 0;
  std::vector<Change>* log_ = nullptr;

  friend class IncomingIterator;
};

class Graph::IncomingIterator {
public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = SlotId;
  using difference_type = std::ptrdiff_t;
  using pointer = const SlotId*;
  using reference = SlotId;
  IncomingIterator() = default;
  IncomingIterator(const Graph* g, SlotId s) : g_(g), s_(s) {}
  SlotId operator*() const { return s_; }
  IncomingIterator& operator++() {
    s_ = g_->slots_[s_].next;
    return *this;
  }
  IncomingIterator operator++(int) {
    auto t = *this;
    ++*this;
    return t;
  }
  bool operator==(const IncomingIterator& o) const { return s_ == o.s_; }
  bool operator!=(const IncomingIterator& o) const { return s_ != o.s_; }

private:
  const Graph* g_ = nullptr;
  SlotId s_ = no_slot;
};

inline Graph::IncomingIterator Graph::IncomingRange::begin() const { return {g, head}; }
inline Graph::IncomingIterator Graph::IncomingRange::end() const { return {g, no_slot}; }

}  // namespace loom::engine
