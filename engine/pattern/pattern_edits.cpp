#include "pattern/pattern_edits.h"

#include "core/input_error.h"

#include <string>

namespace paver {

std::vector<EditedParticle> add_edited_points(Pattern& pattern, const ElementEdits& edits) {
  std::vector<EditedParticle> edited;
  const int designed = pattern.designed_point_count();
  for (std::size_t i = 0; i < edits.moved.size(); ++i) {
    const MovedParticle& m = edits.moved[i];
    if (m.id >= designed)
      throw InputError("edits.moved[" + std::to_string(i) + "]: particle " + std::to_string(m.id) +
                       " is not in this pattern, which has " + std::to_string(designed) + " (ids 0.." +
                       std::to_string(designed - 1) +
                       "); the edits were made for another spacing, pattern or placement: remove them");
    edited.push_back({m.id, m.uv, m.pinned, false});
  }
  for (const AddedElement& a : edits.added) {
    edited.push_back({pattern.point_count(), a.uv, true, true});
    pattern.points.push_back(a.uv);
    pattern.point_cell_vertex.push_back(-1);
    pattern.point_cell.push_back(glm::ivec2(0));
    ++pattern.added_points;
  }
  return edited;
}

}  // namespace paver
