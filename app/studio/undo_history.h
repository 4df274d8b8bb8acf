#pragma once
// Undo and redo over whole designs. A Design is small (a few hundred numbers), so each step keeps
// a full copy: no command objects to invert, and every change, whatever panel made it, undoes the
// same way.
#include "design/design.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace paver::studio {

class UndoHistory {
public:
  UndoHistory() = default;
  explicit UndoHistory(std::size_t limit) : limit_(limit) {}

  // Call before changing the design, with the design as it was. Forgets what could be redone.
  void record(const Design& before);
  // The design to go back to, given the current one (which becomes redoable); empty at the start.
  std::optional<Design> undo(const Design& current);
  // The design undone last, given the current one (which becomes undoable again).
  std::optional<Design> redo(const Design& current);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  std::size_t undo_count() const { return undo_.size(); }
  std::size_t redo_count() const { return redo_.size(); }
  void clear();

private:
  std::size_t limit_ = 200;        // oldest steps are dropped beyond this many
  std::vector<Design> undo_, redo_;
};

}  // namespace paver::studio
