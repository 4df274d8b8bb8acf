// The elements panel: the V-element (on/off, shape, s), the list of E-elements (t, s, shape, the
// cell edges they sit on) and the custom shape's mesh file.
#include "panels.h"

#include "../design_edits.h"
#include "../studio.h"

#include "elements/element_shape.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "design/design_keys.h"
#include "pattern/grade_field.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace paver::studio {
namespace {

bool shape_combo(const char* label, ShapeKind& shape) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::string(enum_name(shape)).c_str())) {
    for (const ShapeKind kind : enum_values<ShapeKind>())
      if (ImGui::Selectable(std::string(enum_name(kind)).c_str(), kind == shape)) {
        changed = kind != shape;
        shape = kind;
      }
    ImGui::EndCombo();
  }
  return changed;
}

// A slider whose change is a design change; held, it is one undo step and the run waits for it.
bool fraction_slider(Document& doc, Design& d, const char* label, double& value, double lo, double hi) {
  if (!ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, "%.3f")) return false;
  return change_design(doc, d, ImGui::IsItemActive());
}

// A length typed in the surface's unit that applies on Enter or when the field loses focus
// (never on every keystroke: typing 1.5 must not pave at 1 first).
bool length_field(const char* label, double& value, const char* unit, const NumberRule& rule) {
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
  const bool changed = typed_number(label, value, "%.4g", rule);
  ImGui::SameLine();
  ImGui::TextUnformatted(unit);
  return changed;
}

// The same, for a design key: its range from the key table, in the surface's unit.
bool length_field(const char* label, double& value, const char* unit, Key key) {
  return length_field(label, value, unit, NumberRule::of(key, unit));
}

std::string sizes_text(const std::vector<double>& sizes) {
  std::string text;
  for (const double size : sizes) text += (text.empty() ? "" : ", ") + number_text(size);
  return text;
}

// Stocked sizes typed as a list ("1.3, 1.1, 0.9"), applied on Enter and checked as design.json's
// key is; a list that is not taken says why under the field and stays as typed.
void fill_sizes_field(Document& doc, Design& d, UiState& ui, const char* unit) {
  if (!ui.fill_sizes_editing && ui.fill_sizes_problem.empty()) ui.fill_sizes_text = sizes_text(d.elements.fill_sizes);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
  const bool entered = ImGui::InputTextWithHint("fill sizes", "none", &ui.fill_sizes_text,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ui.fill_sizes_editing = ImGui::IsItemActive() && !entered;
  ImGui::SameLine();
  ImGui::TextUnformatted(unit);
  if (entered) {
    std::string compact;
    for (const char c : ui.fill_sizes_text)
      if (c != ' ') compact += c;
    Design next = d;
    ui.fill_sizes_problem.clear();
    if (const std::optional<std::string> problem = set_key_from_text(next, Key::fill_sizes, compact)) {
      ui.fill_sizes_problem = "fill sizes " + *problem;
    } else {
      try {
        validate_design(next, "the studio");
        d = next;
        change_design(doc, d);
      } catch (const InputError& e) {
        ui.fill_sizes_problem = e.what();
      }
    }
  }
  if (!ui.fill_sizes_problem.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", ui.fill_sizes_problem.c_str());
}

// Graded stones (pattern/grade_field.h): picking a grade with no smallest size yet starts it a
// quarter under the stone, in the ladder's 0.05 mm steps, so that the first run already grades.
void grade_fields(Document& doc, Design& d, double stone, const char* unit) {
  GradeDesign& grade = d.elements.grade;
  if (enum_combo("graded by", grade.by, {"none (one size)", "curvature (smaller where it bends)",
                                         "rim (smaller towards the edges)", "point (smaller towards a tip)"})) {
    if (grade.by != GradeBy::None && !(grade.smallest > 0) && stone > 0) {
      const double step = kGradeStepMm / millimetres_per_unit(d.units);
      grade.smallest = stone - step * std::round(0.25 * stone / step);
    }
    // A new point grade starts at the surface's highest point, a tip on most pendants drawn upright.
    if (grade.by == GradeBy::Point && grade.point.size() != 3 && doc.surface.map &&
        !doc.surface.map->mesh.positions.empty()) {
      const auto& positions = doc.surface.map->mesh.positions;
      const glm::dvec3 top = *std::max_element(positions.begin(), positions.end(),
                                               [](const glm::dvec3& a, const glm::dvec3& b) { return a.y < b.y; });
      grade.point = {top.x, top.y, top.z};
    }
    change_design(doc, d);
  }
  help_marker("Stones that fall off from the stone size towards a smaller one, as a setter grades them: where "
              "the surface bends most, towards every rim and hole, or towards a point (a pendant's tip). The pattern is grown (topology auto) so "
              "that the smaller stones lie closer; each stone is a stocked size (the fill sizes between, else "
              "0.05 mm steps).");
  if (grade.by == GradeBy::None) return;
  if (length_field("smallest graded", grade.smallest, unit, Key::grade_smallest)) change_design(doc, d);
  help_marker("The smallest stone of the grade: under the stone size, and at least a quarter of it.");
  if (grade.by == GradeBy::Point) {
    if (grade.point.size() == 3) {
      double xyz[3] = {grade.point[0], grade.point[1], grade.point[2]};
      ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14);
      // Taken on Enter or when the field is left, never at each keystroke (as length_field).
      const bool entered = ImGui::InputScalarN("towards the point", ImGuiDataType_Double, xyz, 3, nullptr, nullptr,
                                               "%.4g", ImGuiInputTextFlags_EnterReturnsTrue);
      if (entered || ImGui::IsItemDeactivatedAfterEdit()) {
        if (std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])) {
          grade.point = {xyz[0], xyz[1], xyz[2]};
          change_design(doc, d);
        }
      }
      remember_field_place("towards the point");
      help_marker("Where the stones are smallest, as x, y, z of the surface (its highest point to begin with); "
                  "they grow back to the stone size over the grade width from it.");
    }
  }
  if (grade.by == GradeBy::Rim || grade.by == GradeBy::Point) {
    if (length_field("grade width", grade.width, unit, Key::grade_width)) change_design(doc, d);
    help_marker(grade.by == GradeBy::Rim ? "How far in from the edge margin the stones grow back to the stone size (0 = three stones)."
                                         : "How far from the point the stones grow back to the stone size (0 = three stones).");
  }
}

void jewellery_section(Document& doc, Design& d, UiState& ui) {
  section("Stones (jewellery)");
  const std::string unit(enum_name(d.units));
  if (ImGui::BeginCombo("units", unit.c_str())) {
    for (const Units u : {Units::Millimetre, Units::Centimetre, Units::Metre, Units::Inch})
      if (ImGui::Selectable(std::string(enum_name(u)).c_str(), u == d.units) && u != d.units) {
        d.units = u;
        change_design(doc, d);
      }
    ImGui::EndCombo();
  }
  help_marker("The unit of the surface's coordinates, and so of D, the gap, the margin and the stone "
              "size; the bill of stones and carats are given in millimetres from it.");
  // D as the last run resolved it when the design derives it from the surface (spacing 0).
  const double spacing = d.pattern.spacing > 0 ? d.pattern.spacing
                         : doc.result.pavement ? doc.result.pavement->design.pattern.spacing
                                               : 0;
  double stone = d.elements.vertex.enabled ? d.elements.vertex.scale * spacing : 0;
  // D = stone + gap: both fields refuse what would make D larger than the surface, each in its words.
  const double widest = largest_spacing(doc);
  char across[96];
  std::snprintf(across, sizeof across, "the surface is about %.4g %s across", widest, unit.c_str());
  NumberRule stone_rule{ValueRange::above(0), unit};
  stone_rule.below(widest - d.elements.gap, "D = stone + gap would be larger than the surface: " + std::string(across));
  if (length_field("stone diameter", stone, unit.c_str(), stone_rule)) {
    set_stone_size(d, stone);
    change_design(doc, d);
  }
  help_marker("Round brilliants (gems) of this girdle diameter on the vertices: D becomes stone + gap. "
              "Type a size and press Enter.");
  double gap = d.elements.gap;
  NumberRule gap_rule = NumberRule::of(Key::gap, unit);
  if (stone > 0) gap_rule.below(widest - stone, "D = stone + gap would be larger than the surface: " + std::string(across));
  if (length_field("gap##stones", gap, unit.c_str(), gap_rule)) {
    set_gap_keeping_stone_size(d, gap, stone);
    change_design(doc, d);
  }
  help_marker("Required free space between neighbouring elements (0 = touching): two collide when their "
              "centres are closer than the sum of their radii plus the gap. JewelCraft's default is 0.2 mm. "
              "With a stone size, D grows with it so the stones keep their size; with stones on the edges too, "
              "D and the proportions stay.");
  if (length_field("edge margin", d.elements.margin, unit.c_str(), Key::margin)) change_design(doc, d);
  help_marker("No stone comes nearer the surface's edge than this (0 = its edge may touch the rim).");
  if (enum_combo("rim rows", d.elements.rim_rows, {"none (trimmed)", "around the holes", "along every rim", "auto (every rim for tri pave)"}))
    change_design(doc, d);
  help_marker("A row of stones that follows the surface's rims, so a hole's edge looks designed, not "
              "trimmed: around the holes (every rim but the outer edge) or along every rim; auto lines every rim "
              "of a tri lattice of stones (pave) and trims other patterns. The pattern's "
              "stones that the row would touch make way. A closed surface has no rims.");
  if (ImGui::Checkbox("close bare spots", &d.elements.close_spots)) change_design(doc, d);
  help_marker("After the pass, a stone of the design's size pushed into every place where one still fits, its "
              "neighbours moving to make room (on by default; the verdict names the spots left).");
  if (ImGui::Checkbox("beads between stones", &d.elements.beads.enabled)) change_design(doc, d);
  help_marker("Small beads of metal (shared prongs) that hold every stone from at least three sides: one in the "
              "gap between every three stones in contact, more around the stones that need them (rim stones, "
              "grids).");
  if (d.elements.beads.enabled) {
    if (length_field("least bead", d.elements.beads.min_diameter, "mm", Key::beads_min_diameter)) change_design(doc, d);
    help_marker("No bead is smaller: a cast bead is about 0.5-0.6 mm.");
    if (length_field("bead over girdle", d.elements.beads.over, "mm", Key::beads_over)) change_design(doc, d);
    help_marker("How far each bead reaches over the girdle of every stone it holds.");
    fraction_slider(doc, d, "bead size", d.elements.beads.scale, 0.5, 2.0);
  }
  fill_sizes_field(doc, d, ui, unit.c_str());
  help_marker("Stocked sizes smaller than the stone, as a supplier sells melee (1.3, 1.1, 0.9): after the "
              "pass, every place where one fits gets the largest that fits. Type the list and press Enter.");
  grade_fields(doc, d, stone, unit.c_str());
}

}  // namespace

void elements_panel(Document& doc, UiState& ui) {
  Design d = doc.design;
  jewellery_section(doc, d, ui);
  section("V-elements (on the pattern's vertices)");
  if (ImGui::Checkbox("enabled", &d.elements.vertex.enabled)) change_design(doc, d);
  fraction_slider(doc, d, "size (x D)##vertex", d.elements.vertex.scale, 0.05, 1.0);
  help_marker("The stone's diameter over D, in (0, 1]: 1 = stones that touch along every edge.");
  if (shape_combo("shape##vertex", d.elements.vertex.shape)) change_design(doc, d);

  section("E-elements (on the pattern's edges)");
  UnitCell cell;
  try {
    cell = design_cell_shape(d.pattern);
  } catch (const InputError&) {
    // The pattern panel says why; the cell-edge checkboxes are left out meanwhile.
  }
  int remove = -1;
  for (int i = 0; i < int(d.elements.edge.size()); ++i) {
    EdgeElementDesign& e = d.elements.edge[i];
    ImGui::PushID(i);
    if (ImGui::TreeNodeEx("##edge", ImGuiTreeNodeFlags_DefaultOpen, "E-element %d", i)) {
      fraction_slider(doc, d, "along the edge", e.t, 0.0, 1.0);
      help_marker("Position along the edge, 0 = its first vertex, 1 = its second.");
      fraction_slider(doc, d, "size (x D)", e.scale, 0.05, 1.0);
      help_marker("The stone's diameter over D, in (0, 1].");
      if (shape_combo("shape", e.shape)) change_design(doc, d);
      ImGui::TextUnformatted(e.cell_edges.empty() ? "on every cell edge; tick to keep to:" : "only on cell edges:");
      for (int c = 0; c < int(cell.edges.size()); ++c) {
        if (cell.edges[c].is_virtual) continue;
        bool on = std::find(e.cell_edges.begin(), e.cell_edges.end(), c) != e.cell_edges.end();
        ImGui::SameLine();
        if (ImGui::Checkbox((std::to_string(c) + "##cell_edge").c_str(), &on)) {
          if (on)
            e.cell_edges.push_back(c);
          else
            std::erase(e.cell_edges, c);
          std::sort(e.cell_edges.begin(), e.cell_edges.end());
          change_design(doc, d);
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("cell edge %d (numbered in the unit cell)", c);
      }
      if (ImGui::SmallButton("remove")) remove = i;
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (remove >= 0) {
    d.elements.edge.erase(d.elements.edge.begin() + remove);
    change_design(doc, d);
  }
  if (ImGui::Button("add E-element")) {
    d.elements.edge.push_back({});
    change_design(doc, d);
  }

  section("F-elements (in the pattern's faces)");
  if (ImGui::Checkbox("enabled##face", &d.elements.face.enabled)) change_design(doc, d);
  help_marker("One element at the centre of every face of the pattern (the mean of its corners), carried by "
              "them as the pattern is optimized; a face the map squeezes too much for it loses it.");
  fraction_slider(doc, d, "size (x D)##face", d.elements.face.scale, 0.05, 1.0);
  help_marker("The diameter over D, in (0, 1]. A triangle's centre is 0.577 D from its corners, a Cairo "
              "pentagon's 0.694 D: with V-elements of size 1, the size here is at most 0.15 and 0.38.");
  if (shape_combo("shape##face", d.elements.face.shape)) change_design(doc, d);

  section("Custom shape");
  if (ui.custom_shape_path.empty()) ui.custom_shape_path = d.elements.custom_shape;
  ImGui::InputText("shape file", &ui.custom_shape_path);
  if (ImGui::Button("Browse...##shape")) start_browsing(ui.browser, BrowsePurpose::CustomShape, ui.custom_shape_path);
  ImGui::SameLine();
  if (ImGui::Button("use this mesh")) {
    try {
      load_custom_shape(ui.custom_shape_path);  // refuse a bad file here, not at the next run
      d.elements.custom_shape = ui.custom_shape_path;
      change_design(doc, d);
    } catch (const std::exception& e) {
      report_error(doc, e);
    }
  }
  help_marker("Elements whose shape is 'custom' use this mesh (OBJ, OFF, PLY or STL), normalised to unit width.");
  if (ImGui::Checkbox("allow overlapping elements", &d.elements.allow_overlap)) change_design(doc, d);
  help_marker("Designs whose elements intersect on purpose (paper Fig. 15): no overlap check, no "
              "collision resolution.");
}

}  // namespace paver::studio
