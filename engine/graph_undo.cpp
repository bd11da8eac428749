// Checkpoints and rollback of an engine::Graph: an undo log of slot,
// attribute, creation and removal records, replayed newest first.
#include <stdexcept>

#include "engine/graph.hpp"

namespace loom::engine {

Graph::Checkpoint Graph::checkpoint() {
  open_.push_back(undo_base_ + undo_.size());
  return open_.back();
}

void Graph::release(Checkpoint c) {
  while (!open_.empty() && open_.back() > c) open_.pop_back();
  if (!open_.empty() && open_.back() == c) open_.pop_back();
  if (open_.empty()) {
    undo_base_ += undo_.size();
    undo_.clear();
  }
}

void Graph::release_oldest() {
  if (open_.empty()) return;
  open_.erase(open_.begin());
  std::size_t keep_from = open_.empty() ? undo_base_ + undo_.size() : open_.front();
  undo_.erase(undo_.begin(), undo_.begin() + static_cast<std::ptrdiff_t>(keep_from - undo_base_));
  undo_base_ = keep_from;
}

void Graph::drop_last_element() {
  Element& el = elements_.back();
  kind_members_[el.kind].pop_back();
  for (auto& column : columns_[el.kind]) column.pop_back();
  slots_.resize(el.first_slot);
  if (el.alive) --kind_live_[el.kind], --live_;
  elements_.pop_back();
}

void Graph::rollback(Checkpoint c) {
  if (c < undo_base_ || c > undo_base_ + undo_.size()) throw std::logic_error("Graph::rollback: unknown checkpoint");
  // Nothing to undo leaves the graph, and the caches keyed on its revision, as they are.
  if (c == undo_base_ + undo_.size()) {
    while (!open_.empty() && open_.back() > c) open_.pop_back();
    return;
  }
  ++revision_;
  auto saved = std::move(open_);
  open_.clear();  // replaying must not record
  while (undo_base_ + undo_.size() > c) {
    UndoRecord r = undo_.back();
    undo_.pop_back();
    switch (r.kind) {
      case UndoRecord::Kind::slot: set_slot(r.where, r.old); break;
      case UndoRecord::Kind::attribute: set(r.where, r.attr, static_cast<std::int32_t>(r.old)); break;
      case UndoRecord::Kind::removed: {
        Element& el = elements_[r.where];
        el.alive = true;
        kind_members_[el.kind][el.local] = r.where;
        ++kind_live_[el.kind];
        ++live_;
        if (log_) log_->push_back({r.where, Change::Kind::created, 0});
        break;
      }
      case UndoRecord::Kind::created:
        // Later records are undone already: the element is the last one, empty.
        if (r.where + 1 != elements_.size()) throw std::logic_error("Graph::rollback: creations out of order");
        if (log_) log_->push_back({r.where, Change::Kind::removed, 0});
        drop_last_element();
        break;
    }
  }
  open_ = std::move(saved);
  while (!open_.empty() && open_.back() > c) open_.pop_back();
}

}  // namespace loom::engine
