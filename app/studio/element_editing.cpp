#include "element_editing.h"

#include "core/input_error.h"
#include "elements/element_ids.h"
#include "io/design_io.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <cstdio>
#include <limits>

namespace paver::studio {
namespace {

std::string id_text(int id) { return "element " + std::to_string(id); }

std::size_t require_element(const Pavement& pavement, int id) {
  const std::optional<std::size_t> index = find_element(pavement, id);
  if (!index) throw InputError(id_text(id) + " is not in the pavement on screen (placements.csv lists the ids)");
  return *index;
}

// Ids name one pattern layout: an auto design keeps the topology its pavement was laid with, a band
// the way its rows were laid (auto is not chosen under edits: pipeline/pavement.cpp), and a fitted
// offset stays where the fit put it (a fit is not made under edits: pipeline/offset_fit.h).
void fix_layout(Design& design, const Pavement& pavement) {
  if (design.pattern.topology == Topology::Auto) design.pattern.topology = pavement.design.pattern.topology;
  if (design.placement.band_rows == BandRows::Auto && pavement.band_closure)
    design.placement.band_rows = pavement.band_closure->rows_across ? BandRows::Across : BandRows::Along;
  if (design.placement.fit_offset && pavement.offset_fit) {
    design.placement.offset = pavement.offset_fit->chosen.offset;
    design.placement.fit_offset = false;
  }
}

MovedParticle* moved_entry(Design& design, int particle) {
  for (MovedParticle& m : design.edits.moved)
    if (m.id == particle) return &m;
  return nullptr;
}

AddedElement* added_entry(Design& design, int id) {
  for (AddedElement& a : design.edits.added)
    if (a.id == id) return &a;
  return nullptr;
}

// The pattern particles that carry element `index`: its point, or both ends of its edge; none
// for elements no particle of the design carries (refill, boundary filling, added, beads).
std::vector<int> pattern_particles(const Pavement& pavement, std::size_t index) {
  const Elements& e = pavement.elements;
  const Pattern& pattern = pavement.pattern;
  const int source = e.source[index];
  if (e.kind[index] == ElementKind::Vertex && source >= 0 && source < pattern.designed_point_count()) return {source};
  if (e.kind[index] == ElementKind::Edge && source >= 0)
    return {pattern.edge_a[std::size_t(source)], pattern.edge_b[std::size_t(source)]};
  if (e.kind[index] == ElementKind::Face && source >= 0 && source < pattern.face_count())
    return {pattern.face_corner.begin() + pattern.face_start[std::size_t(source)],
            pattern.face_corner.begin() + pattern.face_start[std::size_t(source) + 1]};
  return {};
}

// The same, for an edit that needs them: throws saying why an element has none.
std::vector<int> carriers(const Design& design, const Pavement& pavement, std::size_t index, const char* action) {
  std::vector<int> particles = pattern_particles(pavement, index);
  if (!particles.empty()) return particles;
  const int id = pavement.elements.id[index];
  if (pavement.elements.kind[index] == ElementKind::Edge)
    throw InputError(id_text(id) + " was added by the boundary filling, which places anew on every run; " + action +
                     " a pattern element, or add one there");
  if (design.pattern.topology == Topology::Adaptive)
    throw InputError(std::string("cannot ") + action + " " + id_text(id) +
                     ": the adaptive pattern cannot hold elements in place yet; use the lattice topology");
  throw InputError(id_text(id) + " was placed by the refill, which places anew on every run; " + action +
                   " a pattern element, or add one there (add U V)");
}

void refuse_adaptive(const Design& design, const Pavement& pavement, const char* action) {
  if (pavement.design.pattern.topology == Topology::Adaptive || design.pattern.topology == Topology::Adaptive)
    throw InputError(std::string("cannot ") + action +
                     " elements of the adaptive pattern yet (its relaxation cannot hold them); "
                     "set the topology to lattice, or delete elements instead");
}

}  // namespace

std::optional<std::size_t> find_element(const Pavement& pavement, int id) {
  const std::vector<int>& ids = pavement.elements.id;
  const auto it = std::find(ids.begin(), ids.end(), id);
  if (it == ids.end()) return std::nullopt;
  return std::size_t(it - ids.begin());
}

std::optional<int> element_at(const Pavement& pavement, glm::dvec2 uv) {
  const Elements& e = pavement.elements;
  std::optional<int> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double distance = glm::length(e.uv[i] - uv);
    if (distance <= 0.5 * e.diameter[i] && distance < nearest) nearest = distance, best = e.id[i];
  }
  return best;
}

std::vector<int> elements_in_box(const Pavement& pavement, glm::dvec2 a, glm::dvec2 b, double turn) {
  const double c = std::cos(turn), s = std::sin(turn);
  const auto on_screen = [&](glm::dvec2 q) { return glm::dvec2(c * q.x - s * q.y, s * q.x + c * q.y); };
  const glm::dvec2 lo = glm::min(on_screen(a), on_screen(b)), hi = glm::max(on_screen(a), on_screen(b));
  const Elements& e = pavement.elements;
  std::vector<int> ids;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const glm::dvec2 q = on_screen(e.uv[i]);
    if (q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y) ids.push_back(e.id[i]);
  }
  return ids;
}

std::string describe_element(const Design& design, const Pavement& pavement, int id) {
  const std::size_t i = require_element(pavement, id);
  const Elements& e = pavement.elements;
  const char* kind = e.kind[i] == ElementKind::Vertex ? "vertex"
                     : e.kind[i] == ElementKind::Edge ? "edge"
                     : e.kind[i] == ElementKind::Face ? "face"
                                                      : "bead";
  std::string origin;
  if (id >= kFirstAddedId)
    origin = ", added by you";
  else if (e.kind[i] == ElementKind::Vertex && e.source[i] < 0)
    origin = ", placed by the refill";
  else if (e.kind[i] == ElementKind::Edge && e.source[i] < 0)
    origin = ", placed by the boundary filling";
  const bool pinned = is_pinned(design, pavement, id);
  char text[256];
  std::snprintf(text, sizeof text, "%s: %s element, diameter %.4g, at u %.4g v %.4g%s%s", id_text(id).c_str(), kind,
                e.diameter[i], e.uv[i].x, e.uv[i].y, origin.c_str(), pinned ? ", pinned" : "");
  return text;
}

namespace {

std::unordered_set<int> pinned_particles(const Design& design) {
  std::unordered_set<int> pinned;
  for (const MovedParticle& m : design.edits.moved)
    if (m.pinned) pinned.insert(m.id);
  return pinned;
}

// The one rule: the designer's own, or every particle carrying it pinned.
bool holds(const std::unordered_set<int>& pinned, const Pavement& pavement, std::size_t index) {
  if (pavement.elements.id[index] >= kFirstAddedId) return true;
  const std::vector<int> particles = pattern_particles(pavement, index);
  return !particles.empty() &&
         std::all_of(particles.begin(), particles.end(), [&](int particle) { return pinned.count(particle) > 0; });
}

}  // namespace

bool is_pinned(const Design& design, const Pavement& pavement, int id) {
  if (id >= kFirstAddedId) return true;
  const std::optional<std::size_t> index = find_element(pavement, id);
  return index && holds(pinned_particles(design), pavement, *index);
}

std::vector<std::size_t> held_elements(const Design& design, const Pavement& pavement) {
  const std::unordered_set<int> pinned = pinned_particles(design);
  std::vector<std::size_t> held;
  for (std::size_t i = 0; i < pavement.elements.size(); ++i)
    if (holds(pinned, pavement, i)) held.push_back(i);
  return held;
}

Design with_pinned(Design design, const Pavement& pavement, int id, bool pinned) {
  refuse_adaptive(design, pavement, pinned ? "pin" : "unpin");
  const std::size_t index = require_element(pavement, id);
  if (id >= kFirstAddedId) {
    if (!pinned) throw InputError(id_text(id) + " is one you added: it stays where you put it; drag or delete it");
    return design;
  }
  fix_layout(design, pavement);
  for (const int particle : carriers(design, pavement, index, pinned ? "pin" : "unpin")) {
    if (MovedParticle* m = moved_entry(design, particle)) {
      m->pinned = pinned;
    } else if (pinned) {
      design.edits.moved.push_back({particle, pavement.points[std::size_t(particle)], true});
    }
  }
  return design;
}

Design with_dragged(Design design, const Pavement& pavement, int id, glm::dvec2 offset) {
  refuse_adaptive(design, pavement, "drag");
  const std::size_t index = require_element(pavement, id);
  if (id >= kFirstAddedId) {
    AddedElement* a = added_entry(design, id);
    if (!a) throw InputError(id_text(id) + " is not among the design's added elements");
    a->uv = pavement.elements.uv[index] + offset;
    return design;
  }
  fix_layout(design, pavement);
  for (const int particle : carriers(design, pavement, index, "drag")) {
    const glm::dvec2 to = pavement.points[std::size_t(particle)] + offset;
    if (MovedParticle* m = moved_entry(design, particle))
      m->uv = to, m->pinned = true;
    else
      design.edits.moved.push_back({particle, to, true});
  }
  return design;
}

Design without_element(Design design, const Pavement& pavement, int id) {
  const std::size_t index = require_element(pavement, id);
  if (pavement.elements.kind[index] == ElementKind::Bead)
    throw InputError(id_text(id) + " is a bead: beads follow the stones; turn them off in the elements panel");
  fix_layout(design, pavement);
  design.edits.deleted.push_back({id, pavement.elements.uv[index]});
  return design;
}

Design with_added_element(Design design, const Pavement& pavement, glm::dvec2 uv, int* added_id) {
  refuse_adaptive(design, pavement, "add");
  if (!design.elements.vertex.enabled)
    throw InputError("an added element is a vertex element, but vertex elements are off; turn them on first");
  fix_layout(design, pavement);
  const int id = design.edits.next_added_id();
  design.edits.added.push_back({id, uv});
  if (added_id) *added_id = id;
  return design;
}

bool changes_pattern_layout(const Design& before, const Design& after) {
  const nlohmann::json a = design_to_json(before), b = design_to_json(after);
  return a["pattern"] != b["pattern"] || a["placement"] != b["placement"];
}

}  // namespace paver::studio
