#include "undo_history.h"

#include <utility>

namespace paver::studio {

void UndoHistory::record(const Design& before) {
  undo_.push_back(before);
  if (undo_.size() > limit_) undo_.erase(undo_.begin());
  redo_.clear();
}

std::optional<Design> UndoHistory::undo(const Design& current) {
  if (undo_.empty()) return std::nullopt;
  Design previous = std::move(undo_.back());
  undo_.pop_back();
  redo_.push_back(current);
  return previous;
}

std::optional<Design> UndoHistory::redo(const Design& current) {
  if (redo_.empty()) return std::nullopt;
  Design next = std::move(redo_.back());
  redo_.pop_back();
  undo_.push_back(current);
  return next;
}

void UndoHistory::clear() {
  undo_.clear();
  redo_.clear();
}

}  // namespace paver::studio
