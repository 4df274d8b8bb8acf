#pragma once
// Editing single elements of the pavement on screen (select, pin, drag, delete, add), shared by
// the views' mouse actions and the script: each returns the design with the edit recorded in
// design.edits (so it is undoable, saved with the design and reproduced by `paver run`), or
// throws InputError saying why the element cannot take it. Elements are named by their stable
// ids (elements/element_ids.h), as placements.csv lists them.
#include "design/design.h"
#include "pipeline/pavement.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace paver::studio {

// The index of element `id` in the pavement's elements, or none.
std::optional<std::size_t> find_element(const Pavement& pavement, int id);

// The element nearest to `uv` (map units) whose footprint covers it, or none.
std::optional<int> element_at(const Pavement& pavement, glm::dvec2 uv);

// The ids of the elements whose centres lie in the box with corners `a` and `b` (map units, any
// order), in the pavement's order: a box selection. The box's sides run along the screen of a 2D
// view turned by `turn` (render::MapView::turn), as the designer drew it.
std::vector<int> elements_in_box(const Pavement& pavement, glm::dvec2 a, glm::dvec2 b, double turn = 0);

// One line about element `id`: kind, where it is, whether it is pinned or the designer's.
std::string describe_element(const Design& design, const Pavement& pavement, int id);

// Whether element `id` is held where it is: pinned (a vertex element's particle, both ends of an
// edge element's edge) or one the designer added.
bool is_pinned(const Design& design, const Pavement& pavement, int id);

// The indices (into pavement.elements) of every element is_pinned holds, in one pass: the views
// mark them, so a designer sees what stays put.
std::vector<std::size_t> held_elements(const Design& design, const Pavement& pavement);

// Holds element `id` where it is (pinned) or lets it relax again. A vertex element pins its
// particle, an edge element the two ends of its edge.
Design with_pinned(Design design, const Pavement& pavement, int id, bool pinned);

// Moves element `id` by `offset` (map units); it is held where it is dropped. Its neighbours
// within reach make room when the pavement re-runs (solver/edit_relaxation.h).
Design with_dragged(Design design, const Pavement& pavement, int id, glm::dvec2 offset);

// Removes element `id`; its place stays empty.
Design without_element(Design design, const Pavement& pavement, int id);

// Adds a vertex element (the design's vertex size and shape) at `uv`, held there; returns the
// design, with the new element's id in `added_id`.
Design with_added_element(Design design, const Pavement& pavement, glm::dvec2 uv, int* added_id = nullptr);

// Whether a change from `before` to `after` lays the pattern out anew, so that element ids name
// other elements and the edits must go.
bool changes_pattern_layout(const Design& before, const Design& after);

}  // namespace paver::studio
