#include "pattern/pattern_edits.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "map/lifting.h"

#include <string>

namespace paver {

namespace {

// An edit whose point lies off the map would be dropped without a word (a hand-written file, or
// one made for another surface or placement): refused, naming it.
void refuse_edits_off_the_map(const SurfaceMap& map, const ElementEdits& edits) {
  std::vector<glm::dvec2> uv;
  for (const MovedParticle& m : edits.moved) uv.push_back(m.uv);
  for (const AddedElement& a : edits.added) uv.push_back(a.uv);
  LiftedPoints lifted;
  lifted.resize(uv.size());
  if (lift_points(map, uv, lifted) == 0) return;
  for (std::size_t k = 0; k < uv.size(); ++k) {
    if (lifted.triangle[k] >= 0) continue;
    const bool moved = k < edits.moved.size();
    const std::size_t i = moved ? k : k - edits.moved.size();
    const int id = moved ? edits.moved[i].id : edits.added[i].id;
    throw InputError(std::string("edits.") + (moved ? "moved[" : "added[") + std::to_string(i) + "] (id " +
                     std::to_string(id) + "): its uv (" + number_text(uv[k].x) + ", " + number_text(uv[k].y) +
                     ") is off this surface's map; remove it, or give a uv on the map (placements.csv's u, v)");
  }
}

}  // namespace

std::vector<EditedParticle> add_edited_points(const SurfaceMap& map, Pattern& pattern, const ElementEdits& edits) {
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
  refuse_edits_off_the_map(map, edits);
  return edited;
}

}  // namespace paver
