#include "design/design.h"
#include "core/number_text.h"

#include <algorithm>

#include "core/input_error.h"

#include <cmath>
#include <optional>
#include <string>

namespace paver {

std::string_view topology_name(Topology t) {
  switch (t) {
    case Topology::Lattice: return "lattice";
    case Topology::Adaptive: return "adaptive";
    case Topology::Auto: return "auto";
  }
  return "lattice";
}

std::optional<Topology> topology_from_name(std::string_view name) {
  for (Topology t : {Topology::Lattice, Topology::Adaptive, Topology::Auto})
    if (name == topology_name(t)) return t;
  return std::nullopt;
}

std::string_view rim_rows_name(RimRows r) {
  switch (r) {
    case RimRows::None: return "none";
    case RimRows::Holes: return "holes";
    case RimRows::All: return "all";
  }
  return "none";
}

std::optional<RimRows> rim_rows_from_name(std::string_view name) {
  for (RimRows r : {RimRows::None, RimRows::Holes, RimRows::All})
    if (name == rim_rows_name(r)) return r;
  return std::nullopt;
}

std::string_view units_name(Units u) {
  switch (u) {
    case Units::Millimetre: return "mm";
    case Units::Centimetre: return "cm";
    case Units::Metre: return "m";
    case Units::Inch: return "in";
  }
  return "mm";
}

std::optional<Units> units_from_name(std::string_view name) {
  for (Units u : {Units::Millimetre, Units::Centimetre, Units::Metre, Units::Inch})
    if (name == units_name(u)) return u;
  return std::nullopt;
}

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

class Validator {
public:
  explicit Validator(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& message) const { throw InputError(source_ + ": " + message); }

  // `ok` is written as the allowed condition so that NaN, which fails every comparison, is
  // rejected too.
  void require(bool ok, const std::string& key, const std::string& allowed, double value) const {
    if (!ok) fail("'" + key + "' must be " + allowed + ", got " + number_text(value));
  }

  void finite(double value, const std::string& key) const {
    require(std::isfinite(value), key, "finite", value);
  }
  void non_negative(double value, const std::string& key) const {
    require(std::isfinite(value) && value >= 0, key, "finite and >= 0", value);
  }
  void unit_scale(double value, const std::string& key) const {
    require(value > 0 && value <= 1, key, "in (0, 1] (diameter = scale * D)", value);
  }
  void unit_interval(double value, const std::string& key) const {
    require(value >= 0 && value <= 1, key, "in [0, 1]", value);
  }

private:
  const std::string& source_;
};

void validate_pattern(const Validator& v, const PatternDesign& pattern) {
  v.require(std::isfinite(pattern.spacing) && pattern.spacing >= 0, "pattern.spacing",
            "finite and >= 0 (0 = derive from the surface)", pattern.spacing);
  for (size_t i = 0; i < pattern.operators.size(); ++i) {
    const EdgeOperator& op = pattern.operators[i];
    const std::string key = "pattern.operators[" + std::to_string(i) + "]";
    v.require(op.from >= 0, key + ".from", ">= 0 (a unit-cell vertex index)", op.from);
    v.require(op.to >= 0, key + ".to", ">= 0 (a unit-cell vertex index)", op.to);
    // An edge joins a vertex to one in a nearby cell. One a million cells away built a million-cell
    // spring and its lattice until memory ran out (23 GB).
    for (int k = 0; k < 2; ++k)
      v.require(std::abs(op.offset[k]) <= kMaxOperatorOffset, key + ".offset[" + std::to_string(k) + "]",
                "between -" + std::to_string(kMaxOperatorOffset) + " and " + std::to_string(kMaxOperatorOffset) +
                    " (cells away: an edge joins nearby vertices)",
                op.offset[k]);
    if (op.is_virtual && op.kind != EdgeOperator::Kind::Add)
      v.fail("'" + key + ".virtual' may only be true for an \"add\" operator; this one is \"" +
             std::string(operator_name(op.kind)) + "\"");
  }
}

void validate_elements(const Validator& v, const ElementsDesign& elements) {
  v.unit_scale(elements.vertex.scale, "elements.vertex.scale");
  v.require(std::isfinite(elements.gap) && elements.gap >= 0, "elements.gap", "finite and >= 0 (surface units)",
            elements.gap);
  v.require(std::isfinite(elements.margin) && elements.margin >= 0, "elements.margin",
            "finite and >= 0 (surface units)", elements.margin);
  v.require(std::isfinite(elements.beads.scale) && elements.beads.scale > 0 && elements.beads.scale <= 2,
            "elements.beads.scale", "in (0, 2]", elements.beads.scale);
  std::string custom_user;  // first key that asks for the custom shape
  if (elements.vertex.enabled && elements.vertex.shape == ShapeKind::Custom) custom_user = "elements.vertex.shape";
  for (size_t i = 0; i < elements.edge.size(); ++i) {
    const EdgeElementDesign& edge = elements.edge[i];
    const std::string key = "elements.edge[" + std::to_string(i) + "]";
    v.unit_interval(edge.t, key + ".t");
    v.unit_scale(edge.scale, key + ".scale");
    for (size_t j = 0; j < edge.cell_edges.size(); ++j)
      v.require(edge.cell_edges[j] >= 0, key + ".cell_edges[" + std::to_string(j) + "]",
                ">= 0 (a unit-cell edge index)", edge.cell_edges[j]);
    if (custom_user.empty() && edge.shape == ShapeKind::Custom) custom_user = key + ".shape";
  }
  if (!custom_user.empty() && elements.custom_shape.empty())
    v.fail("'" + custom_user + "' is \"custom\" but 'elements.custom_shape' is empty; set it to the path "
           "of a mesh file (OBJ, OFF, PLY or STL)");
}

void validate_placement(const Validator& v, const Placement& placement) {
  v.finite(placement.offset.x, "placement.offset[0]");
  v.finite(placement.offset.y, "placement.offset[1]");
  v.finite(placement.rotation_deg, "placement.rotation_deg");
  v.require(std::isfinite(placement.scale) && placement.scale > 0, "placement.scale", "finite and > 0",
            placement.scale);
}

void validate_solver(const Validator& v, const SolverParams& s) {
  for (const SolverParameter& p : solver_parameters()) {
    const std::string key = "solver." + std::string(p.name);
    if (const auto* real = std::get_if<double SolverParams::*>(&p.member))
      v.require(p.range.contains(s.**real), key, p.range.describe(), s.**real);
    else if (const auto* integer = std::get_if<int SolverParams::*>(&p.member))
      v.require(p.range.contains(s.**integer), key, p.range.describe(), s.**integer);
  }
  if (!(s.c + s.m >= 0))
    v.fail("c + m must be >= 0 (eq. 5: the further-apart distance cannot be negative); got c = " +
           number_text(s.c) + ", m = " + number_text(s.m));
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

void validate_edits(const Validator& v, const ElementEdits& edits, const ElementsDesign& elements) {
  const auto check_uv = [&](glm::dvec2 uv, const std::string& key) {
    v.finite(uv.x, key + ".uv[0]");
    v.finite(uv.y, key + ".uv[1]");
  };
  for (size_t i = 0; i < edits.moved.size(); ++i) {
    const std::string key = "edits.moved[" + std::to_string(i) + "]";
    v.require(edits.moved[i].id >= 0 && edits.moved[i].id < kFirstAddedId, key + ".id",
              "a pattern particle's id (>= 0, below " + std::to_string(kFirstAddedId) + ")", edits.moved[i].id);
    check_uv(edits.moved[i].uv, key);
  }
  if (const auto twice = repeated_id(edits.moved))
    v.fail("'edits.moved' names particle " + std::to_string(*twice) + " twice; keep one entry per particle");
  for (size_t i = 0; i < edits.added.size(); ++i) {
    const std::string key = "edits.added[" + std::to_string(i) + "]";
    v.require(edits.added[i].id >= kFirstAddedId, key + ".id",
              ">= " + std::to_string(kFirstAddedId) + " (the designer's own ids)", edits.added[i].id);
    check_uv(edits.added[i].uv, key);
  }
  if (const auto twice = repeated_id(edits.added))
    v.fail("'edits.added' uses id " + std::to_string(*twice) + " twice; every added element needs its own id");
  if (!edits.added.empty() && !elements.vertex.enabled)
    v.fail("'edits.added' adds vertex elements, but 'elements.vertex.enabled' is false; enable vertex elements or "
           "remove the added ones");
  for (size_t i = 0; i < edits.deleted.size(); ++i) {
    const std::string key = "edits.deleted[" + std::to_string(i) + "]";
    v.require(edits.deleted[i].id >= 0, key + ".id", ">= 0 (an element id)", edits.deleted[i].id);
    check_uv(edits.deleted[i].uv, key);
  }
  if (const auto twice = repeated_id(edits.deleted))
    v.fail("'edits.deleted' names element " + std::to_string(*twice) + " twice; keep one entry per element");
}

}  // namespace

void validate_design(const Design& design, const std::string& source) {
  const Validator v(source);
  validate_pattern(v, design.pattern);
  validate_elements(v, design.elements);
  validate_placement(v, design.placement);
  validate_solver(v, design.solver);
  validate_edits(v, design.edits, design.elements);
  for (size_t i = 0; i < design.guidance.size(); ++i) {
    const GuidanceDab& d = design.guidance[i];
    const std::string key = "guidance[" + std::to_string(i) + "]";
    v.finite(d.uv.x, key + ".uv[0]");
    v.finite(d.uv.y, key + ".uv[1]");
    v.require(std::isfinite(d.radius) && d.radius > 0, key + ".radius", "finite and > 0 (surface units)", d.radius);
    v.require(d.strength >= -0.5 && d.strength <= 1, key + ".strength",
              "in [-0.5, 1] (-0.5 = half the spacing, +1 = twice it)", d.strength);
  }
}

}  // namespace paver
