#include "undo_history.h"

#include <utility>

namespace paver::studio {

void UndoHistory::record(const Design& before) {
  undo_.push_back(before);
  if (undo_.size() > limit_) undo_.erase(undo_.begin());
  redo_.clear();
}

namespace {
// The last design of `from`, with `current` kept in `to` to go back to.
std::optional<Design> step(std::vector<Design>& from, std::vector<Design>& to, const Design& current) {
  if (from.empty()) return std::nullopt;
  Design taken = std::move(from.back());
  from.pop_back();
  to.push_back(current);
  return taken;
}
}  // namespace

std::optional<Design> UndoHistory::undo(const Design& current) { return step(undo_, redo_, current); }

std::optional<Design> UndoHistory::redo(const Design& current) { return step(redo_, undo_, current); }

void UndoHistory::clear() {
  undo_.clear();
  redo_.clear();
}

}  // namespace paver::studio
