#pragma once
// A designer's edits of single elements (the studio's pin, drag, delete and add; design.json
// "edits"), which make_pavement applies to the pattern it builds, so that a saved design
// reproduces the edited pavement. Elements are named by their stable ids (elements/element_ids.h).
#include <glm/vec2.hpp>

#include <vector>

namespace paver {

// Ids from here up are the designer's own elements (`ElementEdits::added`); the pattern's and the
// refill's ids lie below (a pattern has at most 4e6 points and about 3 edges per point).
inline constexpr int kFirstAddedId = 1'000'000'000;

// A pattern particle (its id is its vertex element's) that starts at `uv`, in the frame of the
// map the pattern is laid on, instead of its lattice position; held there when pinned, else free
// to relax from there.
struct MovedParticle {
  int id = 0;
  glm::dvec2 uv{0};
  bool pinned = true;
};

// A vertex element the designer added at `uv`, held there; its neighbours make room.
struct AddedElement {
  int id = kFirstAddedId;
  glm::dvec2 uv{0};
};

// An element removed from the result. A pattern element or an added one is found by its id; an
// element the refill added is found by `uv` (the refill places anew after every edit upstream).
struct DeletedElement {
  int id = 0;
  glm::dvec2 uv{0};
};

struct ElementEdits {
  std::vector<MovedParticle> moved;
  std::vector<DeletedElement> deleted;
  std::vector<AddedElement> added;

  bool empty() const { return moved.empty() && deleted.empty() && added.empty(); }
  int pinned_count() const;  // moved particles held where they were put
  // The id the next added element gets: ids are never reused, even after an added one is deleted.
  int next_added_id() const;
};

}  // namespace paver
