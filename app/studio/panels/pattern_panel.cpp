// The pattern panel: tessellation, D, bracing, the edge operators, and the unit-cell editor
// drawn with ImGui's draw list. The editor shows the cell (bright, edge numbers as E-elements use
// them) and its propagation to the neighbouring cells (dim), so an operator's effect on the
// whole lattice is visible at once. Flip / Remove: click an edge. Add: click two vertices.
#include "panels.h"

#include "../design_edits.h"
#include "../studio.h"

#include "core/input_error.h"
#include "design/design_keys.h"
#include "elements/elements.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace paver::studio {
namespace {

constexpr int kRange = 1;  // cells drawn around the unit cell: (2 kRange + 1)^2

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

// Tries an edit of the pattern; a refusal (the cell cannot take it) is shown, nothing changes.
template <class Edit>
void try_edit(Document& doc, Edit&& edit) {
  try {
    change_design(doc, edit(doc.design));
  } catch (const InputError& e) {
    report_error(doc, e);
  }
}

void unit_cell_editor(Document& doc, UiState& ui) {
  UnitCell cell;
  try {
    cell = design_cell_shape(doc.design.pattern);
  } catch (const InputError& e) {
    ImGui::TextWrapped("The unit cell cannot be built: %s", e.what());
    return;
  }
  const float side = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("unit_cell", ImVec2(side, side));
  const bool hovered = ImGui::IsItemHovered(), clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + side, origin.y + side), IM_COL32(24, 26, 30, 255));

  const glm::dvec2 centre = cell_view_centre(cell);  // still under the cursor as edges change
  const double extent = std::max({glm::length(cell.a1 + cell.a2), glm::length(cell.a1 - cell.a2), 1.0});
  const float scale = float(side / (2.2 * extent));
  const auto to_screen = [&](glm::dvec2 p) {
    const glm::dvec2 q = p - centre;
    return glm::vec2(origin.x + side * 0.5f + float(q.x) * scale, origin.y + side * 0.5f - float(q.y) * scale);
  };
  const ImVec2 mouse_im = ImGui::GetIO().MousePos;
  const glm::vec2 mouse(mouse_im.x, mouse_im.y);
  const auto im = [](glm::vec2 v) { return ImVec2(v.x, v.y); };
  draw->PushClipRect(origin, ImVec2(origin.x + side, origin.y + side), true);

  // The cell's parallelogram.
  const glm::vec2 c0 = to_screen({0, 0}), c1 = to_screen(cell.a1), c2 = to_screen(cell.a1 + cell.a2),
                  c3 = to_screen(cell.a2);
  draw->AddQuadFilled(im(c0), im(c1), im(c2), im(c3), IM_COL32(60, 70, 90, 90));

  // Edges of every drawn cell; the hovered one (by distance to the mouse) is highlighted.
  struct Hit {
    int edge = -1;
    float distance = 8;  // pixels
  } hit;
  for (int pass = 0; pass < 2; ++pass)
    for (int i = -kRange; i <= kRange; ++i)
      for (int j = -kRange; j <= kRange; ++j)
        for (int e = 0; e < int(cell.edges.size()); ++e) {
          const CellEdge& edge = cell.edges[e];
          const glm::ivec2 at(i, j);
          const glm::vec2 a = to_screen(cell.position(edge.from, at)), b = to_screen(cell.position(edge.to, at + edge.offset));
          const bool central = at == glm::ivec2(0, 0);
          if (pass == 0) {
            if (hovered && !edge.is_virtual && ui.cell_mode != CellEditMode::Add) {
              const float d = distance_to_segment(mouse, a, b);
              if (d < hit.distance) hit = {e, d};
            }
            continue;
          }
          ImU32 colour = edge.is_virtual ? IM_COL32(110, 110, 120, central ? 150 : 70)
                                         : central ? IM_COL32(240, 200, 90, 255) : IM_COL32(150, 140, 110, 150);
          if (e == hit.edge) colour = ui.cell_mode == CellEditMode::Remove ? IM_COL32(240, 80, 70, 255)
                                                                           : IM_COL32(90, 200, 250, 255);
          draw->AddLine(im(a), im(b), colour, edge.is_virtual ? 1.0f : central ? 2.5f : 1.5f);
          if (central && !edge.is_virtual)
            draw->AddText(im(0.5f * (a + b) + glm::vec2(3, -14)), IM_COL32(240, 220, 160, 255),
                          std::to_string(e).c_str());
        }

  // Vertices; in Add mode the hovered one is highlighted and the first pick stays marked.
  int hovered_vertex = -1;
  glm::ivec2 hovered_cell(0);
  for (int i = -kRange; i <= kRange; ++i)
    for (int j = -kRange; j <= kRange; ++j)
      for (int v = 0; v < int(cell.vertices.size()); ++v) {
        const glm::ivec2 at(i, j);
        const glm::vec2 p = to_screen(cell.position(v, at));
        const bool central = at == glm::ivec2(0, 0);
        const bool near = hovered && ui.cell_mode == CellEditMode::Add && glm::length(p - mouse) < 9;
        if (near) hovered_vertex = v, hovered_cell = at;
        const bool picked = ui.cell_mode == CellEditMode::Add && ui.add_from_vertex == v && ui.add_from_cell == at;
        draw->AddCircleFilled(im(p), near || picked ? 6.0f : central ? 4.5f : 3.0f,
                              picked ? IM_COL32(90, 220, 120, 255)
                              : near ? IM_COL32(90, 200, 250, 255)
                              : central ? IM_COL32(250, 250, 250, 255) : IM_COL32(170, 170, 170, 160));
        if (central) draw->AddText(im(p + glm::vec2(5, 2)), IM_COL32(200, 200, 220, 255), std::to_string(v).c_str());
      }
  // F-elements: a dot at each face's centre, where the pattern's will sit, in their colour.
  if (doc.design.elements.face.enabled) {
    const std::array<std::uint8_t, 3> c = kind_colour(ElementKind::Face);
    const std::vector<CellFace> faces = cell_faces(cell);
    for (int i = -kRange; i <= kRange; ++i)
      for (int j = -kRange; j <= kRange; ++j)
        for (const CellFace& face : faces) {
          const bool central = i == 0 && j == 0;
          draw->AddCircleFilled(im(to_screen(face_centre(cell, face, {i, j}))), central ? 4.0f : 2.5f,
                                IM_COL32(c[0], c[1], c[2], central ? 255 : 140));
        }
  }
  draw->PopClipRect();

  if (!clicked) return;
  if (ui.cell_mode == CellEditMode::Add) {
    if (hovered_vertex < 0) return;
    if (ui.add_from_vertex < 0) {
      ui.add_from_vertex = hovered_vertex, ui.add_from_cell = hovered_cell;
      return;
    }
    EdgeOperator op;
    op.kind = EdgeOperator::Kind::Add;
    op.from = ui.add_from_vertex;
    op.to = hovered_vertex;
    op.offset = hovered_cell - ui.add_from_cell;
    op.is_virtual = ui.add_virtual;
    ui.add_from_vertex = -1;
    try_edit(doc, [&](const Design& d) { return with_operator(d, op); });
  } else if (hit.edge >= 0) {
    const CellEdge& edge = cell.edges[hit.edge];
    EdgeOperator op;
    op.kind = ui.cell_mode == CellEditMode::Flip ? EdgeOperator::Kind::Flip : EdgeOperator::Kind::Remove;
    op.from = edge.from;
    op.to = edge.to;
    op.offset = edge.offset;
    try_edit(doc, [&](const Design& d) { return with_operator(d, op); });
  }
}

constexpr double kBrushRadiusMin = 1, kBrushRadiusMax = 15, kBrushStrengthMin = 0.05, kBrushStrengthMax = 0.5;

// Number fields for what the 2D view's handles do (section 4.2: p = R(rotation) (scale q) + offset),
// applied on Enter or focus loss like every typed value.
void placement_section(Document& doc, Design& d) {
  section("Placement (the pattern over the map)");
  Placement& p = d.placement;
  // A finite number, as design.json takes them.
  const NumberRule any = NumberRule{ValueRange::any()};
  bool changed = typed_number("offset u", p.offset.x, "%.4g", any);
  changed |= typed_number("offset v", p.offset.y, "%.4g", any);
  help_marker("Moves the pattern over the map, in surface units (the left drag in the 2D view).");
  changed |= enum_combo("rows along axis", p.align, {"x", "y", "z", "none (the map's)"});
  help_marker("Turns the pattern so that its rows follow a world axis (x, y or z) as it lies on the surface, "
              "on average over the surface: rows level on a facade. The rotation below is then added to it. "
              "Not on a band, whose rows close around it.");
  if (p.align != AlignAxis::None && doc.result.pavement && doc.result.pavement->row_alignment)
    ImGui::TextDisabled("turned %.1f degrees to follow %s", doc.result.pavement->row_alignment->rotation_deg,
                        std::string(enum_name(p.align)).c_str());
  if (ImGui::Checkbox("fit offset", &p.fit_offset)) changed = true;
  help_marker("Shifts the pattern within one cell, on top of the offset above, to where the most elements fit: "
              "with rows along an axis, whole rows meet a window's edge or miss it. Lays out up to 64 shifts and, "
              "for a pattern of up to 20,000 points, paves the best few in full.");
  if (p.fit_offset && doc.result.pavement && doc.result.pavement->offset_fit) {
    const OffsetFit& f = *doc.result.pavement->offset_fit;
    if (f.chosen.kept >= 0)
      ImGui::TextDisabled("laid at (%.4g, %.4g): %ld elements kept, %ld at the offset above", f.chosen.offset.x,
                          f.chosen.offset.y, f.chosen.kept, f.at_design.kept);
    else
      ImGui::TextDisabled("laid at (%.4g, %.4g): %zu elements laid out, %zu at the offset above", f.chosen.offset.x,
                          f.chosen.offset.y, f.chosen.laid_out, f.at_design.laid_out);
  }
  changed |= typed_number("rotation (degrees)", p.rotation_deg, "%.4g", NumberRule::of(Key::rotation_deg, "degrees"));
  help_marker("Turns the pattern counter-clockwise over the map (the round handle in the 2D view); with rows "
              "along an axis, on top of that. On a band the band sets the rows' direction instead.");
  changed |= typed_number("scale", p.scale, "%.4g", NumberRule::of(Key::placement_scale));
  help_marker("Scales the map under the pattern, no unit: above 1 the map grows and more elements fit at the same "
              "D (the square handle). It must stay above 0.");
  if (changed) change_design(doc, d);  // validates: a scale <= 0 is refused with the field named
}

}  // namespace

void pattern_panel(Document& doc, UiState& ui) {
  Design d = doc.design;
  Tessellation tessellation = d.pattern.tessellation;
  if (enum_combo("tessellation", tessellation,
                 {"triangles (tri)", "squares (grid)", "hexagons (hex)", "Cairo pentagons (cairo)",
                  "prismatic pentagons (prismatic)", "drawn cell (cell)"})) {
    change_design(doc, with_tessellation(d, tessellation));
    ui.add_from_vertex = -1;
  }
  help_marker("The tessellation: the paper's three (section 4.1), two pentagonal ones, or a drawn cell, which "
              "starts as the cell shown before (operators applied) and is then edited by adding and removing "
              "edges. Changing it clears the edge operators and the E-elements' cell edges, which name the old "
              "cell's edges.");

  // Typing 0.5 must not pave at 0 first (nor ask about it): the value applies when the field lets go.
  const std::string unit(enum_name(d.units));
  NumberRule spacing_rule = NumberRule::of(Key::pattern_spacing, unit);
  char across[96];
  std::snprintf(across, sizeof across, "no two elements fit: the surface is about %.4g %s across", largest_spacing(doc),
                unit.c_str());
  spacing_rule.below(largest_spacing(doc), across);
  if (typed_number("D (spacing)", d.pattern.spacing, "%.4g", spacing_rule)) change_design(doc, d);
  help_marker("Edge length of the tessellation in surface units; type it and press Enter (or Tab). 0 = derived from the "
              "surface (about 1000 points). A spacing that would place more elements than the studio's budget "
              "asks before it runs.");
  if (doc.result.pavement && d.pattern.spacing <= 0)
    ImGui::TextDisabled("derived: D = %.4g", doc.result.pavement->design.pattern.spacing);

  if (enum_combo("topology", d.pattern.topology, {"lattice (the paper's)", "adaptive (point defects)", "auto"}))
    change_design(doc, d);
  help_marker("Lattice: the regular tessellation laid over the map. Adaptive: stones grown on the surface "
              "at the same spacing, with a few 5- and 7-neighbour defects where the map distorts the "
              "lattice (tri and hex). Auto: the lattice, unless it tears or leaves bare patches and the "
              "adaptive pattern does better.");
  if (doc.surface.map && is_band(*doc.surface.map)) {
    if (enum_combo("band rows", d.placement.band_rows,
                   {"along the band", "across the band", "auto (the better of the two)"}))
      change_design(doc, d);
    help_marker("On a ring or bangle the lattice closes around the band: a whole number of stones goes "
                "round (D changes a little to make it so). Rows across the band or along it, or auto (the "
                "default): both are paved and the better kept, so a row of large stones goes all round a ring.");
  }

  placement_section(doc, d);

  bool bracing = d.pattern.bracing;
  if (ImGui::Checkbox("bracing (virtual edges across faces)", &bracing)) {
    d.pattern.bracing = bracing;
    change_design(doc, d);
  }

  section("Unit cell");
  if (radio_buttons(ui.cell_mode,
                    {{"flip", CellEditMode::Flip}, {"remove", CellEditMode::Remove}, {"add", CellEditMode::Add}}))
    ui.add_from_vertex = -1;
  if (ui.cell_mode == CellEditMode::Add) {
    ImGui::SameLine();
    ImGui::Checkbox("virtual", &ui.add_virtual);
    ImGui::TextDisabled(ui.add_from_vertex < 0 ? "click the first vertex" : "click the second vertex");
  } else {
    ImGui::TextDisabled("click an edge to %s it", ui.cell_mode == CellEditMode::Flip ? "flip" : "remove");
  }
  unit_cell_editor(doc, ui);

  section("Operators (in order)");
  if (d.pattern.operators.empty()) ImGui::TextDisabled("none: the regular tessellation");
  for (int i = 0; i < int(d.pattern.operators.size()); ++i) {
    const EdgeOperator& op = d.pattern.operators[i];
    ImGui::PushID(i);
    if (ImGui::SmallButton("x")) try_edit(doc, [&](const Design& design) { return without_operator(design, i); });
    ImGui::SameLine();
    ImGui::Text("%d. %s %d->%d @ (%d,%d)%s", i, std::string(enum_name(op.kind)).c_str(), op.from, op.to,
                op.offset.x, op.offset.y, op.is_virtual ? " virtual" : "");
    ImGui::PopID();
  }

  section("Guidance brush");
  radio_buttons(ui.brush, {{"off", Brush::Off}, {"paint looser", Brush::Looser}, {"paint denser", Brush::Denser}});
  help_marker("Drag in the 2D map to paint where the pattern should be looser (stones farther apart) or denser. "
              "Each dab changes the spacing by up to the strength at its centre, fading to nothing at its radius; "
              "dabs add up, from half to twice D. Denser stops where the stones touch. Only the lattice follows "
              "a painted field. Undo takes back a whole stroke.");
  ImGui::SliderScalar("radius (x D)", ImGuiDataType_Double, &ui.brush_radius, &kBrushRadiusMin, &kBrushRadiusMax, "%.1f");
  ImGui::SliderScalar("strength", ImGuiDataType_Double, &ui.brush_strength, &kBrushStrengthMin, &kBrushStrengthMax,
                      "%.2f");
  help_marker("How much one dab changes the spacing at its centre: 0.2 = 20% looser (or denser).");
  ImGui::Text("dabs painted: %zu", d.guidance.size());
  if (!d.guidance.empty()) {
    ImGui::SameLine();
    if (ImGui::SmallButton("clear guidance")) {
      d.guidance.clear();
      change_design(doc, d);
    }
  }
}

}  // namespace paver::studio
