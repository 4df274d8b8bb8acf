#include "design/design.h"

#include "core/number_text.h"
#include "design/design_keys.h"

#include <algorithm>

#include "core/input_error.h"

#include <cmath>
#include <optional>
#include <string>

namespace paver {

double millimetres_per_unit(Units u) {
  switch (u) {
    case Units::Millimetre: return 1;
    case Units::Centimetre: return 10;
    case Units::Metre: return 1000;
    case Units::Inch: return 25.4;
  }
  return 1;
}

void set_stone_size(Design& design, double stone) {
  if (design.elements.vertex.enabled && !design.elements.edge.empty()) {
    // Edge stones sit between the vertex ones: at D = stone + gap they would collide with them. The
    // design's proportions are kept instead, and its vertex stones get this size.
    design.pattern.spacing = stone / design.elements.vertex.scale;
    return;
  }
  design.elements.vertex.enabled = true;
  design.elements.vertex.shape = ShapeKind::Gem;
  set_gap_keeping_stone_size(design, design.elements.gap, stone);
}

void set_gap_keeping_stone_size(Design& design, double gap, double stone) {
  design.elements.gap = gap;
  if (stone <= 0 || !design.elements.vertex.enabled || !design.elements.edge.empty()) return;
  design.pattern.spacing = stone + gap;
  design.elements.vertex.scale = stone / design.pattern.spacing;
}

bool keeps_stone_sizes(const ElementsDesign& e) {
  if (e.vertex.enabled && e.vertex.shape == ShapeKind::Gem) return true;
  return std::any_of(e.edge.begin(), e.edge.end(), [](const auto& s) { return s.shape == ShapeKind::Gem; });
}

void keep_stone_sizes(ElementsDesign& e, double spacing_before, double spacing_after) {
  const double ratio = spacing_before / spacing_after;
  if (e.vertex.shape == ShapeKind::Gem) e.vertex.scale *= ratio;
  for (EdgeElementDesign& s : e.edge)
    if (s.shape == ShapeKind::Gem) s.scale *= ratio;
}

bool uses_custom_shape(const ElementsDesign& e) {
  if (e.vertex.enabled && e.vertex.shape == ShapeKind::Custom) return true;
  return std::any_of(e.edge.begin(), e.edge.end(), [](const auto& s) { return s.shape == ShapeKind::Custom; });
}

namespace {

// The checks that span keys; every key's own range is the table's (key_range_problem).
[[noreturn]] void fail(const std::string& source, const std::string& message) {
  throw InputError(source + ": " + message);
}

// An id that `items` (anything with an `id`) lists twice, if any.
template <class Items>
std::optional<int> repeated_id(const Items& items) {
  std::vector<int> ids;
  for (const auto& item : items) ids.push_back(item.id);
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  return twice == ids.end() ? std::nullopt : std::optional<int>(*twice);
}

void check_operators(const std::string& source, const PatternDesign& pattern) {
  for (size_t i = 0; i < pattern.operators.size(); ++i) {
    const EdgeOperator& op = pattern.operators[i];
    if (!op.is_virtual || op.kind == EdgeOperator::Kind::Add) continue;
    std::string message = "'";  // built in steps: GCC 12 warns falsely (-Wrestrict) on "'" + a temporary
    message += key_path(Key::operator_virtual, i);
    fail(source, message + "' may only be true for an \"add\" operator; this one is \"" + std::string(enum_name(op.kind)) + "\"");
  }
}

void check_custom_shape(const std::string& source, const ElementsDesign& elements) {
  std::string custom_user;  // first key that asks for the custom shape
  if (elements.vertex.enabled && elements.vertex.shape == ShapeKind::Custom) custom_user = key_path(Key::vertex_shape);
  for (size_t i = 0; i < elements.edge.size() && custom_user.empty(); ++i)
    if (elements.edge[i].shape == ShapeKind::Custom) custom_user = key_path(Key::edge_shape, i);
  if (!custom_user.empty() && elements.custom_shape.empty())
    fail(source, "'" + custom_user + "' is \"custom\" but '" + key_path(Key::custom_shape) +
                     "' is empty; set it to the path of a mesh file (OBJ, OFF, PLY or STL)");
}

void check_edits(const std::string& source, const ElementEdits& edits, const ElementsDesign& elements) {
  if (const auto twice = repeated_id(edits.moved))
    fail(source, "'" + key_path(Key::edits_moved) + "' names particle " + std::to_string(*twice) +
                     " twice; keep one entry per particle");
  if (const auto twice = repeated_id(edits.added))
    fail(source, "'" + key_path(Key::edits_added) + "' uses id " + std::to_string(*twice) +
                     " twice; every added element needs its own id");
  if (!edits.added.empty() && !elements.vertex.enabled)
    fail(source, "'" + key_path(Key::edits_added) + "' adds vertex elements, but '" + key_path(Key::vertex_enabled) +
                     "' is false; enable vertex elements or remove the added ones");
  if (const auto twice = repeated_id(edits.deleted))
    fail(source, "'" + key_path(Key::edits_deleted) + "' names element " + std::to_string(*twice) +
                     " twice; keep one entry per element");
}

}  // namespace

// Fill sizes are smaller stocked stones than the main one (when the spacing gives its size now).
void check_fill_sizes(const std::string& source, const Design& design) {
  const ElementsDesign& e = design.elements;
  if (e.fill_sizes.empty()) return;
  // The key quoted, built by appending: GCC 12 misreads "'" + a string here as an overlapping copy.
  std::string key = "'";
  key += key_path(Key::fill_sizes);
  if (e.fill_sizes.size() > kMaxFillSizes)
    fail(source, key + "' lists " + std::to_string(e.fill_sizes.size()) + " sizes; at most " +
                     std::to_string(kMaxFillSizes) + " (a supplier's sieve sizes): list fewer");
  if (!e.vertex.enabled || !(design.pattern.spacing > 0)) return;  // no main stone to fill around (yet)
  const double main = e.vertex.scale * design.pattern.spacing;
  for (std::size_t k = 0; k < e.fill_sizes.size(); ++k) {
    const double size = e.fill_sizes[k];
    if (size < main && size >= kLeastFillShare * main) continue;
    std::string message = key + "[" + std::to_string(k) + "]' " + number_text(size);
    message += size >= main ? " is not smaller than the main stone (" + number_text(main) +
                                  "): list the smaller stocked sizes only"
                            : " is less than a quarter of the main stone (" + number_text(main) +
                                  "), too small to set beside it (and to search for room at): list larger sizes";
    fail(source, message);
  }
}

std::optional<std::string> grade_problem(const Design& design) {
  const ElementsDesign& e = design.elements;
  const GradeDesign& g = e.grade;
  if (g.by == GradeBy::None) return std::nullopt;
  // The keys quoted, built by appending (as check_fill_sizes, for GCC 12).
  std::string by = "'";
  by += key_path(Key::grade_by);
  by += "' \"";
  by += enum_name(g.by);
  by += "\"";
  std::string smallest = "'";
  smallest += key_path(Key::grade_smallest);
  smallest += "'";
  if (design.pattern.tessellation != Tessellation::Triangle)
    return by + ": only a tri pattern's stones are graded yet (its particles are the stones); set " +
           key_path(Key::pattern_tessellation) + " \"tri\"";
  if (!e.vertex.enabled || !e.edge.empty() || e.face.enabled)
    return by + ": only vertex elements are graded, alone; " +
           (!e.vertex.enabled  ? "enable " + key_path(Key::vertex_enabled)
            : e.face.enabled ? "set " + key_path(Key::face_enabled) + " false"
                             : "remove " + key_path(Key::elements_edge)) +
           " or set " + key_path(Key::grade_by) + " \"none\"";
  if (design.pattern.topology == Topology::Lattice)
    return by + ": the lattice cannot grade its stones (it has one spacing); use " + key_path(Key::pattern_topology) +
           " \"adaptive\" (or \"auto\", which grows the pattern when stones are graded)";
  if (g.by == GradeBy::Point &&
      (g.point.size() != 3 || !std::all_of(g.point.begin(), g.point.end(), [](double x) { return std::isfinite(x); }))) {
    std::string point = "'";
    point += key_path(Key::grade_point);
    point += "'";
    return by + " needs the point the stones grow smaller towards: give " + point + " as [x, y, z] of the surface (" +
           std::to_string(g.point.size()) + " numbers given)";
  }
  if (!(g.smallest > 0))
    return smallest + " is 0, and " + by + " grades towards it: give the smallest graded stone (surface units)";
  if (!(design.pattern.spacing > 0)) return std::nullopt;  // no main stone to compare with yet
  const double main = e.vertex.scale * design.pattern.spacing;
  if (!(g.smallest < main))
    return smallest + " " + number_text(g.smallest) + " is not smaller than the main stone (" + number_text(main) +
           "): the grade falls off from the main size; give a smaller one";
  if (g.smallest < kLeastFillShare * main)
    return smallest + " " + number_text(g.smallest) + " is less than a quarter of the main stone (" +
           number_text(main) + "), too small to set beside it: give a larger one";
  return std::nullopt;
}

void validate_design(const Design& design, const std::string& source) {
  // Every pair of edge elements is checked for overlap on every cell edge: 10,000 of them took 35 s
  // to be refused. No cell has use for more than a few per edge.
  if (design.elements.edge.size() > kMaxEdgeElements)
    fail(source, "'" + key_path(Key::elements_edge) + "' lists " + std::to_string(design.elements.edge.size()) +
                     " edge elements; a design holds at most " + std::to_string(kMaxEdgeElements) +
                     " (a few per cell edge): remove some");
  if (const std::optional<std::string> problem = key_range_problem(design)) fail(source, *problem);
  check_operators(source, design.pattern);
  check_custom_shape(source, design.elements);
  const SolverParams& s = design.solver;
  if (!(s.c + s.m >= 0))
    fail(source, "c + m must be >= 0 (eq. 5: the further-apart distance cannot be negative); got c = " +
                     number_text(s.c) + ", m = " + number_text(s.m));
  check_edits(source, design.edits, design.elements);
  check_fill_sizes(source, design);
  if (const std::optional<std::string> problem = grade_problem(design)) fail(source, *problem);
}

}  // namespace paver
