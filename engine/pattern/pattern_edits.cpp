#include "pattern/pattern_edits.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "elements/contact_rule.h"
#include "elements/element_hash.h"
#include "map/lifting.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <limits>
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

// Stones the designer holds in place (added ones, and pinned moves) that overlap each other cannot
// both stay: one was dropped at the end as "still colliding" while the verdict said ok, and three
// thousand stacked on one spot took minutes. Refused, naming the first pair. Lifted to 3D and
// hashed: linear in the edits.
void refuse_held_edits_on_each_other(const SurfaceMap& map, const ElementEdits& edits, double diameter, double gap) {
  struct Held {
    std::string name;
    glm::dvec2 uv;
  };
  std::vector<Held> held;
  for (std::size_t i = 0; i < edits.moved.size(); ++i)
    if (edits.moved[i].pinned) held.push_back({"edits.moved[" + std::to_string(i) + "]", edits.moved[i].uv});
  for (std::size_t i = 0; i < edits.added.size(); ++i)
    held.push_back({"edits.added[" + std::to_string(i) + "]", edits.added[i].uv});
  if (held.size() < 2 || !(diameter > 0)) return;
  std::vector<glm::dvec2> uv;
  for (const Held& h : held) uv.push_back(h.uv);
  LiftedPoints lifted;
  lifted.resize(uv.size());
  lift_points(map, uv, lifted);
  const double contact = contact_distance(diameter, diameter, gap);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : lifted.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  ElementHash near(lifted.position, CellGrid(lo, hi, contact), ElementHash::Fill::None);
  for (int k = 0; k < int(held.size()); ++k) {
    near.for_each_near(lifted.position[k], [&](int j) {
      const double distance = glm::length(lifted.position[k] - lifted.position[j]);
      if (elements_collide(distance, diameter, diameter, gap))
        throw InputError(held[j].name + " and " + held[k].name + " hold two stones " + number_text(distance) +
                         " apart, closer than their diameter plus the gap (" + number_text(contact) +
                         "); move or remove one of them");
    });
    near.insert(k);
  }
}

}  // namespace

std::vector<EditedParticle> add_edited_points(const SurfaceMap& map, Pattern& pattern, const ElementEdits& edits,
                                              double held_diameter, double gap) {
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
  refuse_held_edits_on_each_other(map, edits, held_diameter, gap);
  return edited;
}

}  // namespace paver
