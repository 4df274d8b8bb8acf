// The views: the 3D view (orbit with a left drag, pan with a right or middle drag, zoom with the
// wheel) and the 2D map view (pan, zoom; a left drag moves the pattern over the map, the round
// handle turns it, the square one scales it), one large and the other as an inset. With "edit
// stones" on, a left click selects the element under it (both views), a left drag in the 2D view
// moves it, and Ctrl+click there adds one. Each view is rendered only when what it shows or how it
// is looked at changed.
#include "panels.h"

#include "../studio.h"
#include "../view_images.h"
#include "../element_editing.h"
#include "../map_frame.h"
#include "../surface_pick.h"
#include "../view3d_frame.h"

#include "map/lifting.h"

#include "pipeline/pavement.h"
#include "core/input_error.h"
#include "core/stopwatch.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

namespace paver::studio {
namespace {

constexpr float kHandleRadius = 7;  // pixels

std::vector<double> style_inputs(const render::SceneStyle& st) {
  return {double(st.show_surface), double(st.show_elements), double(st.show_lattice), double(st.show_map_wireframe),
          st.background[0], st.background[1], st.background[2]};
}

// Adds a slice to the view's image being drawn; once complete it is shown.
void draw_more(Studio& s, int view) {
  if (!s.renderer.draw_more(view, kViewSliceBudgetMs)) return;
  s.scene.rendered[view] = std::move(s.scene.drawing[view]);
  s.scene.drawing[view].clear();
  ++s.scene.pace[view].images_in_slices;
  if (s.live.state() == RunState::Running) ++s.solving_frames.images_drawn_in_slices;
}

// `now`: its first slice this frame; else from the next, unless the view moves on before.
void start_drawing(Studio& s, int view, const render::ViewRequest& request, std::vector<double> inputs, bool now) {
  s.renderer.start_drawing(view, request);
  s.scene.drawing[view] = std::move(inputs);
  if (now) draw_more(s, view);
}

// Renders the view into the renderer's image unless it already shows exactly this. Where a whole
// image takes longer than a frame can spare (tens of thousands of elements on a software
// renderer), the full image is drawn a slice per frame and shown once complete:
// - while a run moves the elements, each new image of the same look (size, camera, style);
// - while the view moves, after a quick image without the elements and the pattern's lines,
//   which is shown at once, so that the view follows the mouse.
// A screenshot, or a view quick to draw, is drawn whole at once.
void render_if_changed(Studio& s, int view, int width, int height) {
  std::vector<double> inputs = {double(width), double(height)};
  if (view == 0) {
    const render::OrbitCamera& c = s.views.camera;
    inputs.insert(inputs.end(),
                  {c.target.x, c.target.y, c.target.z, c.distance, c.yaw, c.pitch, c.fov_deg, c.screen_shift_x});
  } else {
    const render::MapView& m = s.views.map_view;
    inputs.insert(inputs.end(), {m.centre.x, m.centre.y, m.half_height, m.turn});
  }
  const std::vector<double> style = style_inputs(s.views.style);
  inputs.insert(inputs.end(), style.begin(), style.end());
  inputs.push_back(double(s.scene.generation));  // last: the look is everything before it

  std::vector<double>& shown = s.scene.rendered[view];
  // A screenshot, or the view's image replaced by another (save_view_png), is drawn whole.
  const bool whole_now = s.ui.screenshot.has_value() || s.scene.redraw_whole[view];
  if (s.renderer.drawing(view) && s.scene.drawing[view] == inputs && !whole_now) return draw_more(s, view);
  s.renderer.stop_drawing(view);
  s.scene.drawing[view].clear();
  if (shown == inputs) return;
  const render::ViewRequest request{width, height, s.views.camera, s.views.map_view, s.views.style};
  const bool same_look = shown.size() == inputs.size() && std::equal(inputs.begin(), inputs.end() - 1, shown.begin());
  ViewPace& pace = s.scene.pace[view];
  if (!whole_now && same_look && s.live.state() == RunState::Running)
    return start_drawing(s, view, request, inputs, true);
  if (!whole_now && !same_look && pace.full_image_ms > kQuickImageAboveMs) {
    s.renderer.render_quick(view, request);
    shown = inputs;
    shown.push_back(kQuickImageMark);
    ++pace.quick_images;
    return start_drawing(s, view, request, inputs, false);
  }
  // Only a whole image measures the view: slices each add a load and store of the image.
  const Stopwatch watch;
  s.renderer.render(view, request);
  pace.full_image_ms = watch.milliseconds();
  shown = std::move(inputs);
  s.scene.redraw_whole[view] = false;
}

// --- 3D ---------------------------------------------------------------------------------------

// The element under `mouse` in the 3D view: among those whose projected footprint holds it, the
// nearest the camera; none when the cursor is over no element.
std::optional<std::size_t> element_under_3d(const Studio& s, const View3dFrame& f, ImVec2 mouse) {
  if (!s.doc.result.pavement) return std::nullopt;
  const Elements& e = s.doc.result.pavement->elements;
  std::optional<std::size_t> best;
  double nearest = 1e300;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::optional<ImVec2> centre = f.to_screen(e.position[i]);
    if (!centre) continue;
    const float radius = f.footprint_radius(e.position[i], e.normal[i], e.diameter[i], *centre);
    const float off = std::hypot(mouse.x - centre->x, mouse.y - centre->y);
    const double depth = glm::length(f.eye - e.position[i]);
    if (off <= std::max(radius, 4.0f) && depth < nearest) nearest = depth, best = i;
  }
  return best;
}

// A click (a press and release without a drag) on the 3D view selects the element under it, or
// clears the selection over bare surface.
void pick_3d(Studio& s, const View3dFrame& f) {
  const std::optional<std::size_t> i = element_under_3d(s, f, ImGui::GetIO().MousePos);
  if (!i) return clear_selection(s.ui);
  select_element(s, s.doc.result.pavement->elements.id[*i]);
}

// A stone dragged in the 3D view is dropped where the cursor's ray meets the surface: the map
// point there (eq. 1) less the stone's own is the move, as a drag in the 2D map makes it.
void drop_3d(Studio& s, const View3dFrame& f) {
  if (!s.doc.result.pavement || !s.doc.surface.map) return;
  const std::optional<std::size_t> i = find_element(*s.doc.result.pavement, s.ui.selected_element);
  if (!i) return;
  const SurfaceMap& map = map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology);
  const auto [origin, direction] = f.ray(ImGui::GetIO().MousePos);
  const std::optional<SurfaceHit> hit = first_hit(map.mesh, origin, direction);
  if (!hit) return report_status(s.doc, "dropped off the surface: the stone stays where it was");
  glm::dvec2 offset = map_point(map, hit->triangle, hit->bary) - s.doc.result.pavement->elements.uv[*i];
  if (map.period > 0) offset.x -= map.period * std::round(offset.x / map.period);  // a band: the short way round
  move_selected(s, offset);
}

void interact_3d(render::OrbitCamera& camera, ImVec2 size) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    camera.yaw -= io.MouseDelta.x * 0.008f;
    camera.pitch = std::clamp(camera.pitch + io.MouseDelta.y * 0.008f, -1.5f, 1.5f);
  }
  if (ImGui::IsItemActive() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))) {
    // Move the target so the point under the cursor follows it, at the target's depth.
    const glm::mat4 vp = camera.view_projection(size.x / size.y);
    const glm::vec4 clip = vp * glm::vec4(camera.target, 1);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    const glm::vec3 moved = ndc + glm::vec3(2 * io.MouseDelta.x / size.x, -2 * io.MouseDelta.y / size.y, 0);
    const glm::vec4 world = glm::inverse(vp) * glm::vec4(moved, 1);
    camera.target -= glm::vec3(world) / world.w - camera.target;
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0)
    camera.distance *= std::pow(0.88f, io.MouseWheel);
}

// The legends as the PNGs draw them (render::draw_ratio_legend, draw_type_legend): one title,
// one linear bar with the same ticks, the same type entries.
void ratio_legend(ImDrawList* draw, ImVec2 origin, ImVec2 size) {
  const float width = std::min(300.0f, size.x - 24), height = 12;
  const ImVec2 at(origin.x + 12, origin.y + size.y - 44);
  draw->AddRectFilled(ImVec2(at.x - 6, at.y - 20), ImVec2(at.x + width + 14, at.y + height + 22),
                      IM_COL32(0, 0, 0, 150), 4);
  draw->AddText(ImVec2(at.x, at.y - 17), IM_COL32(230, 230, 230, 255), render::kRatioLegendTitle);
  constexpr int kSegments = 60;
  const float step = width / kSegments;
  for (int i = 0; i < kSegments; ++i) {
    const double r = render::kRatioLegendMin + (render::kRatioLegendMax - render::kRatioLegendMin) * (i + 0.5) / kSegments;
    const std::array<std::uint8_t, 3> c = render::ratio_legend_colour(r);
    draw->AddRectFilled(ImVec2(at.x + step * i, at.y), ImVec2(at.x + step * (i + 1) + 0.5f, at.y + height),
                        IM_COL32(c[0], c[1], c[2], 255));
  }
  for (const double tick : render::ratio_legend_ticks()) {
    const float x = at.x + width * float(render::ratio_legend_position(tick));
    draw->AddLine(ImVec2(x, at.y + height), ImVec2(x, at.y + height + 3), IM_COL32(230, 230, 230, 255));
    char label[16];
    std::snprintf(label, sizeof label, "%.1f", tick);
    draw->AddText(ImVec2(x - 8, at.y + height + 3), IM_COL32(230, 230, 230, 255), label);
  }
}

void type_legend(ImDrawList* draw, ImVec2 origin, ImVec2 size) {
  const std::vector<render::TypeLegendEntry> entries = render::element_type_legend();
  const float rows = float(entries.size());
  const ImVec2 at(origin.x + 12, origin.y + size.y - 12 - 18 * rows);
  draw->AddRectFilled(ImVec2(at.x - 6, at.y - 6), ImVec2(at.x + 170, at.y + 18 * rows), IM_COL32(0, 0, 0, 150), 4);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::array<std::uint8_t, 3> c = entries[i].rgb;
    const ImVec2 row(at.x, at.y + 18.0f * float(i));
    draw->AddCircleFilled(ImVec2(row.x + 6, row.y + 7), 6, IM_COL32(c[0], c[1], c[2], 255));
    draw->AddText(ImVec2(row.x + 18, row.y), IM_COL32(230, 230, 230, 255), entries[i].label);
  }
}

// --- 2D ---------------------------------------------------------------------------------------

struct Handles {
  ImVec2 centre, rotation, scale;
  float radius;
  // Not on a band: its rows close around it, so the band sets their direction and scale (the ring
  // was larger than the band's strip and turned nothing).
  bool shown = true;
};

// The placement the last pavement used: with placement.align, the document's rotation plus the
// alignment's, and with placement.fit_offset the offset it found, so that the handles and the
// lattice preview show the lattice as laid.
double aligned_rotation_deg(const Document& doc) {
  const auto& pavement = doc.result.pavement;
  if (doc.design.placement.align == AlignAxis::None || !pavement || !pavement->row_alignment) return 0;
  return pavement->row_alignment->rotation_deg;
}

Placement shown_placement(const Document& doc) {
  Placement p = doc.design.placement;
  p.rotation_deg += aligned_rotation_deg(doc);
  const auto& pavement = doc.result.pavement;
  // The shift the fit found, on top of the offset being dragged now.
  if (p.fit_offset && pavement && pavement->offset_fit)
    p.offset += pavement->offset_fit->chosen.offset - pavement->offset_fit->at_design.offset;
  return p;
}

// The pattern as seen in the map turns by -rotation (q = R(-rotation) (p - offset) / scale), so
// the round handle sits at angle -rotation in the map (on screen, turned with the map): the
// lattice turns with it. The square handle's distance from the centre is proportional to the scale.
Handles placement_handles(const MapFrame& f, const SurfaceMap& map, const Placement& placement) {
  Handles h;
  h.shown = !map_wraps(map);
  h.centre = f.to_screen(0.5 * (map.uv_min + map.uv_max));
  h.radius = 0.3f * std::min(f.size.x, f.size.y);
  const double angle = f.screen_angle(-glm::radians(placement.rotation_deg));
  h.rotation = ImVec2(h.centre.x + h.radius * float(std::cos(angle)), h.centre.y - h.radius * float(std::sin(angle)));
  const float d = h.radius * float(std::min(placement.scale, 3.0)) * 0.7071f;
  h.scale = ImVec2(h.centre.x + d, h.centre.y - d);  // up and right: the inset covers down-right
  return h;
}

float distance(ImVec2 a, ImVec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// While the placement is dragged, the lattice it gives is drawn at once (the run waits for the
// drag to rest).
void lattice_preview(ImDrawList* draw, const MapFrame& f, const Design& design, double spacing) {
  UnitCell cell;
  try {
    PatternDesign pattern = design.pattern;
    pattern.spacing = spacing;
    cell = make_design_cell(pattern);
  } catch (const std::exception&) {
    return;
  }
  // The view's corners in the pattern plane, then in lattice coordinates.
  const glm::dmat2 basis(cell.a1, cell.a2), to_lattice = glm::inverse(basis);
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const ImVec2 corner : {f.origin, ImVec2(f.origin.x + f.size.x, f.origin.y), ImVec2(f.origin.x, f.origin.y + f.size.y),
                              ImVec2(f.origin.x + f.size.x, f.origin.y + f.size.y)}) {
    const glm::dvec2 l = to_lattice * design.placement.map_to_pattern(f.to_map(corner));
    lo = glm::min(lo, l), hi = glm::max(hi, l);
  }
  if ((hi.x - lo.x + 3) * (hi.y - lo.y + 3) * double(cell.edges.size()) > 30000) return;  // too fine to see
  for (int i = int(std::floor(lo.x)) - 1; i <= int(std::ceil(hi.x)); ++i)
    for (int j = int(std::floor(lo.y)) - 1; j <= int(std::ceil(hi.y)); ++j)
      for (const CellEdge& e : cell.edges) {
        if (e.is_virtual) continue;
        const glm::ivec2 at(i, j);
        const ImVec2 a = f.to_screen(design.placement.pattern_to_map(cell.position(e.from, at)));
        const ImVec2 b = f.to_screen(design.placement.pattern_to_map(cell.position(e.to, at + e.offset)));
        draw->AddLine(a, b, IM_COL32(255, 210, 90, 170), 1.0f);
      }
}

// Edit stones in the 2D view: a click selects (or, with Ctrl, adds), a drag moves the selected
// element, dropped where the button is let go.
void interact_elements_2d(Studio& s, const MapFrame& f) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!s.doc.result.pavement) return;
  if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const glm::dvec2 at = f.to_map(io.MousePos);
    if (io.KeyCtrl) return add_element_at(s, at);
    if (io.KeyShift) {  // a box selection, made when the button is let go
      s.ui.box_from = at;
      return;
    }
    const std::optional<int> id = element_at(*s.doc.result.pavement, at);
    if (!id) {
      clear_selection(s.ui);
      return;
    }
    try {
      select_element(s, *id);
    } catch (const InputError& e) {
      report_error(s.doc, e);
      return;
    }
    s.ui.dragging_element = true;
    s.ui.drag_from = at;
  }
  if (s.ui.box_from && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const glm::dvec2 from = *s.ui.box_from;
    s.ui.box_from.reset();
    try {
      select_box(s, from, f.to_map(io.MousePos), f.view.turn);
    } catch (const InputError& e) {
      report_error(s.doc, e);
    }
  }
  if (s.ui.dragging_element && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    s.ui.dragging_element = false;
    const glm::dvec2 offset = f.to_map(io.MousePos) - s.ui.drag_from;
    // A click that barely moved is a selection, not a move.
    if (glm::length(offset) * f.size.y / (2 * f.view.half_height) > 3) move_selected(s, offset);
  }
}

// A selected element: a ring around its footprint and, while it is dragged, the footprint where
// it would land and a line to it. The same in both views.
void draw_selected(ImDrawList* draw, ImVec2 centre, float radius, std::optional<ImVec2> dragged_to) {
  draw->AddCircle(centre, radius + 3, IM_COL32(0, 0, 0, 200), 48, 4);
  draw->AddCircle(centre, radius + 3, IM_COL32(90, 200, 250, 255), 48, 2);
  if (!dragged_to) return;
  draw->AddCircleFilled(*dragged_to, radius, IM_COL32(90, 200, 250, 110), 48);
  draw->AddLine(centre, *dragged_to, IM_COL32(90, 200, 250, 200), 1.5f);
}

// A held element (pinned, or added by the designer): an orange dot at its centre, in both views.
void draw_held(ImDrawList* draw, ImVec2 centre, float radius) {
  const float r = std::max(3.0f, 0.3f * radius);
  draw->AddCircleFilled(centre, r + 1.5f, IM_COL32(0, 0, 0, 220), 20);
  draw->AddCircleFilled(centre, r, IM_COL32(250, 160, 40, 255), 20);
}

// What the verdict's figures count, where the eye can find it: a bare spot (a stone of the size the
// spot measure asks would still fit there) as a dashed red ring of that size, and a stone that
// collision resolution took away as a grey ghost with a cross.
constexpr ImU32 kSpotColour = IM_COL32(255, 40, 90, 255), kGhostColour = IM_COL32(215, 215, 225, 230);

void draw_bare_spot(ImDrawList* draw, ImVec2 centre, float radius) {
  radius = std::max(radius, 4.0f);
  constexpr int kDashes = 12;
  for (int k = 0; k < kDashes; ++k) {
    const float a0 = glm::two_pi<float>() * float(k) / kDashes, a1 = a0 + glm::pi<float>() / kDashes;
    draw->PathArcTo(centre, radius, a0, a1, 6);
    draw->PathStroke(IM_COL32(0, 0, 0, 200), 0, 4.0f);
    draw->PathArcTo(centre, radius, a0, a1, 6);
    draw->PathStroke(kSpotColour, 0, 2.0f);
  }
}

void draw_ghost(ImDrawList* draw, ImVec2 centre, float radius) {
  radius = std::max(radius, 4.0f);
  draw->AddCircle(centre, radius, IM_COL32(0, 0, 0, 180), 32, 3.0f);
  draw->AddCircle(centre, radius, kGhostColour, 32, 1.5f);
  const float d = 0.5f * radius;
  draw->AddLine(ImVec2(centre.x - d, centre.y - d), ImVec2(centre.x + d, centre.y + d), kGhostColour, 1.5f);
  draw->AddLine(ImVec2(centre.x - d, centre.y + d), ImVec2(centre.x + d, centre.y - d), kGhostColour, 1.5f);
}

void draw_flaws_2d(const Studio& s, ImDrawList* draw, const MapFrame& f) {
  if (!s.views.show_flaws || !s.doc.result.pavement) return;
  const Pavement& p = *s.doc.result.pavement;
  const float pixels_per_unit = float(f.size.y / (2 * f.view.half_height));
  // As the stones are drawn there: the map keeps lengths (ARAP), so surface units are map units.
  const auto map_radius = [&](double diameter) { return float(0.5 * diameter) * pixels_per_unit; };
  for (const BareSpot& spot : p.after.edges.spots) draw_bare_spot(draw, f.to_screen(spot.uv), map_radius(spot.wanted));
  for (const RemovedElement& gone : s.doc.result.ghosts) draw_ghost(draw, f.to_screen(gone.uv), map_radius(gone.diameter));
}

void draw_flaws_3d(const Studio& s, ImDrawList* draw, const View3dFrame& f) {
  if (!s.views.show_flaws || !s.doc.result.pavement) return;
  const Pavement& p = *s.doc.result.pavement;
  // Drawn facing the camera: a spot has no normal of its own.
  const auto facing = [&](glm::dvec3 at) {
    const glm::dvec3 view = f.eye - at;
    return glm::normalize(glm::cross(view, std::abs(view.z) < 0.9 * glm::length(view) ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
  };
  for (const BareSpot& spot : p.after.edges.spots)
    if (const std::optional<ImVec2> c = f.to_screen(spot.position))
      draw_bare_spot(draw, *c, f.footprint_radius(spot.position, facing(spot.position), spot.wanted, *c));
  for (const RemovedElement& gone : s.doc.result.ghosts)
    if (const std::optional<ImVec2> c = f.to_screen(gone.position))
      draw_ghost(draw, *c, f.footprint_radius(gone.position, facing(gone.position), gone.diameter, *c));
}

// A length of 1, 2 or 5 times a power of ten that spans about `pixels_wanted` at `pixels_per_unit`.
double round_length(double pixels_per_unit, double pixels_wanted) {
  const double want = pixels_wanted / pixels_per_unit;
  const double decade = std::pow(10.0, std::floor(std::log10(want)));
  for (const double step : {5.0, 2.0, 1.0})
    if (step * decade <= want) return step * decade;
  return decade;
}

// A scale bar at `at` (its left end), `pixels_per_unit` long per surface unit, labelled in the
// design's unit and with what it measures.
void draw_scale_bar(ImDrawList* draw, ImVec2 at, double pixels_per_unit, const std::string& unit, const char* where) {
  if (!(pixels_per_unit > 0) || !std::isfinite(pixels_per_unit)) return;
  const double length = round_length(pixels_per_unit, 110);
  const float w = float(length * pixels_per_unit);
  const ImU32 ink = IM_COL32(235, 235, 240, 230), shadow = IM_COL32(0, 0, 0, 170);
  for (const auto& [colour, thick] : {std::pair{shadow, 4.0f}, std::pair{ink, 2.0f}}) {
    draw->AddLine(at, ImVec2(at.x + w, at.y), colour, thick);
    draw->AddLine(ImVec2(at.x, at.y - 5), ImVec2(at.x, at.y + 5), colour, thick);
    draw->AddLine(ImVec2(at.x + w, at.y - 5), ImVec2(at.x + w, at.y + 5), colour, thick);
  }
  char text[64];
  std::snprintf(text, sizeof text, "%g %s %s", length, unit.c_str(), where);
  draw->AddText(ImVec2(at.x + 1, at.y - 22 + 1), shadow, text);
  draw->AddText(ImVec2(at.x, at.y - 22), ink, text);
}

// The world axes as the camera sees them (x red, y green, z blue), the nearer drawn last.
void draw_axis_gizmo(ImDrawList* draw, ImVec2 centre, const render::OrbitCamera& camera) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
  glm::vec3 right = glm::cross(forward, glm::vec3(0, 0, 1));
  right = glm::length(right) > 1e-6f ? glm::normalize(right) : glm::vec3(1, 0, 0);
  const glm::vec3 up = glm::cross(right, forward);
  struct Axis {
    glm::vec3 direction;
    const char* name;
    ImU32 colour;
  };
  Axis axes[] = {{{1, 0, 0}, "x", IM_COL32(230, 80, 70, 255)},
                 {{0, 1, 0}, "y", IM_COL32(110, 200, 90, 255)},
                 {{0, 0, 1}, "z", IM_COL32(90, 140, 240, 255)}};
  std::sort(std::begin(axes), std::end(axes),
            [&](const Axis& a, const Axis& b) { return glm::dot(a.direction, forward) > glm::dot(b.direction, forward); });
  constexpr float kLength = 30;
  draw->AddCircleFilled(centre, kLength + 10, IM_COL32(20, 22, 26, 150), 32);
  for (const Axis& a : axes) {
    const ImVec2 tip(centre.x + kLength * glm::dot(a.direction, right), centre.y - kLength * glm::dot(a.direction, up));
    draw->AddLine(centre, tip, a.colour, 2.5f);
    draw->AddText(ImVec2(tip.x - 3, tip.y - 8), a.colour, a.name);
  }
}

// The selected elements (each as draw_selected shows it) and the box being drawn.
void draw_selection_2d(Studio& s, ImDrawList* draw, const MapFrame& f) {
  if (s.ui.box_from) {
    const ImVec2 a = f.to_screen(*s.ui.box_from), b = ImGui::GetIO().MousePos;
    const ImVec2 lo(std::min(a.x, b.x), std::min(a.y, b.y)), hi(std::max(a.x, b.x), std::max(a.y, b.y));
    draw->AddRectFilled(lo, hi, IM_COL32(90, 200, 250, 40));
    draw->AddRect(lo, hi, IM_COL32(90, 200, 250, 220), 0, 0, 1.5f);
  }
  if (!s.doc.result.pavement) return;
  const Pavement& p = *s.doc.result.pavement;
  const float pixels_per_unit = float(f.size.y / (2 * f.view.half_height));
  for (const std::size_t i : held_elements(s.doc.design, p))
    draw_held(draw, f.to_screen(p.elements.uv[i]), float(0.5 * p.elements.diameter[i]) * pixels_per_unit);
  for (const int id : selection(s.ui)) {
    const std::optional<std::size_t> i = find_element(p, id);
    if (!i) continue;
    const float radius = float(0.5 * p.elements.diameter[*i]) * pixels_per_unit;
    const ImVec2 c = f.to_screen(p.elements.uv[*i]);
    std::optional<ImVec2> to;  // moved by the drag so far: the offset of the press, not the cursor itself
    if (s.ui.dragging_element && id == s.ui.selected_element) {
      const ImVec2 m = ImGui::GetIO().MousePos, from = f.to_screen(s.ui.drag_from);
      to = ImVec2(c.x + m.x - from.x, c.y + m.y - from.y);
    }
    draw_selected(draw, c, radius, to);
  }
}

void draw_selection_3d(Studio& s, ImDrawList* draw, const View3dFrame& f) {
  if (!s.doc.result.pavement) return;
  const Pavement& p = *s.doc.result.pavement;
  for (const std::size_t i : held_elements(s.doc.design, p)) {
    const std::optional<ImVec2> c = f.to_screen(p.elements.position[i]);
    if (c) draw_held(draw, *c, f.footprint_radius(p.elements.position[i], p.elements.normal[i], p.elements.diameter[i], *c));
  }
  for (const int id : selection(s.ui)) {
    const std::optional<std::size_t> i = find_element(p, id);
    if (!i) continue;
    const std::optional<ImVec2> c = f.to_screen(p.elements.position[*i]);
    if (!c) continue;
    const float radius = f.footprint_radius(p.elements.position[*i], p.elements.normal[*i], p.elements.diameter[*i], *c);
    // Where it goes: under the cursor, where its ray meets the surface.
    const bool dragged = s.ui.dragging_element_3d && id == s.ui.selected_element;
    draw_selected(draw, *c, radius, dragged ? std::optional<ImVec2>(ImGui::GetIO().MousePos) : std::nullopt);
  }
}

// The guidance brush: a left drag lays dabs a third of the brush apart, one undo step per stroke.
void interact_brush_2d(Studio& s, const MapFrame& f) {
  const ImGuiIO& io = ImGui::GetIO();
  const double spacing = s.doc.result.pavement ? s.doc.result.pavement->design.pattern.spacing : 0;
  if (!(spacing > 0)) return;
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    const glm::dvec2 at = f.to_map(io.MousePos);
    if (!s.ui.last_dab || glm::length(at - *s.ui.last_dab) > s.ui.brush_radius * spacing / 3) {
      const double strength = s.ui.brush == Brush::Looser ? s.ui.brush_strength : -s.ui.brush_strength;
      paint_guidance(s, at, s.ui.brush_radius, strength, true);
      s.ui.last_dab = at;
    }
  } else {
    s.ui.last_dab.reset();
  }
}

void draw_brush_2d(const Studio& s, ImDrawList* draw, const MapFrame& f) {
  const double spacing = s.doc.result.pavement ? s.doc.result.pavement->design.pattern.spacing : 0;
  if (!(spacing > 0) || !ImGui::IsItemHovered()) return;
  const float radius = float(s.ui.brush_radius * spacing * f.size.y / (2 * f.view.half_height));
  const ImU32 colour = s.ui.brush == Brush::Looser ? IM_COL32(120, 220, 120, 220) : IM_COL32(240, 150, 90, 220);
  draw->AddCircle(ImGui::GetIO().MousePos, radius, IM_COL32(0, 0, 0, 160), 64, 3);
  draw->AddCircle(ImGui::GetIO().MousePos, radius, colour, 64, 1.5f);
}

void interact_2d(Studio& s, const MapFrame& f, const Handles& h, bool with_handles) {
  const ImGuiIO& io = ImGui::GetIO();
  render::MapView& view = s.views.map_view;
  if (s.ui.brush != Brush::Off && with_handles) {
    interact_brush_2d(s, f);
  } else if (s.ui.edit_elements && with_handles) {
    interact_elements_2d(s, f);
  } else if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const auto near = [&](ImVec2 handle) {
      return with_handles && h.shown && distance(io.MousePos, handle) < kHandleRadius + 3;
    };
    s.ui.map_drag = near(h.rotation) ? MapDrag::Rotation : near(h.scale) ? MapDrag::Scale : MapDrag::Offset;
  }
  if (!ImGui::IsItemActive()) s.ui.map_drag = MapDrag::None;
  const bool left = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  if (ImGui::IsItemActive() && left && s.ui.map_drag != MapDrag::None &&
      (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
    Design d = s.doc.design;
    Placement& p = d.placement;
    if (s.ui.map_drag == MapDrag::Offset) {
      // The pattern follows the cursor: q' = q + delta for its points means offset -= R(s delta).
      const glm::dvec2 delta = f.to_map(io.MousePos) - f.to_map(ImVec2(io.MousePos.x - io.MouseDelta.x,
                                                                         io.MousePos.y - io.MouseDelta.y));
      p.offset -= p.map_to_pattern(delta) - p.map_to_pattern(glm::dvec2(0));
    } else if (s.ui.map_drag == MapDrag::Rotation) {
      const double angle = std::atan2(-(io.MousePos.y - h.centre.y), io.MousePos.x - h.centre.x);
      p.rotation_deg = -glm::degrees(angle - f.view.turn) - aligned_rotation_deg(s.doc);
    } else {
      const float along = ((io.MousePos.x - h.centre.x) - (io.MousePos.y - h.centre.y)) * 0.7071f;
      p.scale = std::clamp(double(along / (h.radius * 0.7071f)), 0.05, 3.0);
    }
    change_design(s.doc, d, true);
  }
  if (ImGui::IsItemActive() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle))) {
    // The map point under the cursor follows it, whichever way the map is turned.
    const ImVec2 before(io.MousePos.x - io.MouseDelta.x, io.MousePos.y - io.MouseDelta.y);
    view.centre -= glm::vec2(f.to_map(io.MousePos) - f.to_map(before));
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
    // Zoom about the point under the cursor.
    const glm::dvec2 anchor = f.to_map(io.MousePos);
    const float factor = std::pow(0.88f, io.MouseWheel);
    view.half_height *= factor;
    view.centre = glm::vec2(anchor + (glm::dvec2(view.centre) - anchor) * double(factor));
  }
}

void draw_handles(ImDrawList* draw, const Handles& h, MapDrag active) {
  // Dark under light, so the handles show on the pale map as on the dark background.
  const ImU32 shadow = IM_COL32(0, 0, 0, 150), line = IM_COL32(255, 255, 255, 200);
  for (const auto& [colour, width] : {std::pair{shadow, 3.0f}, std::pair{line, 1.0f}}) {
    draw->AddCircle(h.centre, h.radius, colour, 96, width);
    draw->AddLine(h.centre, h.rotation, colour, width);
    draw->AddLine(h.centre, h.scale, colour, width);
  }
  const ImU32 rotation = active == MapDrag::Rotation ? IM_COL32(90, 200, 250, 255) : IM_COL32(250, 250, 250, 255);
  const ImU32 scale = active == MapDrag::Scale ? IM_COL32(90, 200, 250, 255) : IM_COL32(250, 250, 250, 255);
  draw->AddCircleFilled(h.rotation, kHandleRadius + 1.5f, shadow);
  draw->AddCircleFilled(h.rotation, kHandleRadius, rotation);
  const ImVec2 r(kHandleRadius, kHandleRadius), border(1.5f, 1.5f);
  draw->AddRectFilled(ImVec2(h.scale.x - r.x - border.x, h.scale.y - r.y - border.y),
                      ImVec2(h.scale.x + r.x + border.x, h.scale.y + r.y + border.y), shadow);
  draw->AddRectFilled(ImVec2(h.scale.x - r.x, h.scale.y - r.y), ImVec2(h.scale.x + r.x, h.scale.y + r.y), scale);
}

// --- both -------------------------------------------------------------------------------------

// One view as an image item filling `size` at the cursor, with its interaction and overlays.
void view(Studio& s, int which, ImVec2 size, bool large) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  render_if_changed(s, which, std::max(1, int(size.x * scale.x)), std::max(1, int(size.y * scale.y)));
  s.window.view_images().image(s.renderer, which, size);
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton(which == 0 ? "##view3d" : "##view2d", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (which == 0) {
    const View3dFrame frame(origin, size, s.views.camera);
    const ImGuiIO& io = ImGui::GetIO();
    // Edit stones: a press on a stone selects it and drags it along the surface; elsewhere a drag
    // orbits and a click clears the selection.
    if (s.ui.edit_elements && large && ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      if (const std::optional<std::size_t> i = element_under_3d(s, frame, io.MousePos)) {
        select_element(s, s.doc.result.pavement->elements.id[*i]);
        s.ui.dragging_element_3d = true;
      }
    }
    if (!s.ui.dragging_element_3d) interact_3d(s.views.camera, size);
    const bool moved = io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] >= 9;
    if (s.ui.dragging_element_3d && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      s.ui.dragging_element_3d = false;
      if (moved) drop_3d(s, frame);
    } else if (s.ui.edit_elements && ImGui::IsItemDeactivated() && !moved) {
      pick_3d(s, frame);
    }
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    draw_flaws_3d(s, draw, frame);
    draw_selection_3d(s, draw, frame);
    if (large) {
      // Where the camera looks: the target's depth is what the bar measures.
      const render::OrbitCamera& camera = s.views.camera;
      glm::vec3 side = glm::cross(camera.target - camera.eye(), glm::vec3(0, 0, 1));
      side = glm::length(side) > 1e-6f ? glm::normalize(side) : glm::vec3(1, 0, 0);
      const std::optional<ImVec2> a = frame.to_screen(glm::dvec3(camera.target)),
                                  b = frame.to_screen(glm::dvec3(camera.target + side));
      const ImVec2 corner(origin.x + size.x - 60, origin.y + 60);
      draw_axis_gizmo(draw, corner, camera);
      if (a && b)
        draw_scale_bar(draw, ImVec2(origin.x + 12, origin.y + 48), std::hypot(b->x - a->x, b->y - a->y),
                       std::string(enum_name(s.doc.design.units)), "at the view's centre");
    }
    draw->PopClipRect();
  } else {
    const MapFrame frame{origin, size, s.views.map_view};
    // The handles on the map the view shows (a band's seamless one).
    const SurfaceMap& shown_map = map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology);
    const Handles handles = placement_handles(frame, shown_map, shown_placement(s.doc));
    interact_2d(s, frame, handles, large);
    if (large) {
      draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
      if (s.ui.map_drag != MapDrag::None) {
        const double spacing = s.doc.design.pattern.spacing > 0 ? s.doc.design.pattern.spacing
                               : s.doc.result.pavement  ? s.doc.result.pavement->design.pattern.spacing
                                                        : 0;
        if (spacing > 0) {
          Design shown = s.doc.design;
          shown.placement = shown_placement(s.doc);
          lattice_preview(draw, frame, shown, spacing);
        }
      }
      if (s.ui.brush != Brush::Off) draw_brush_2d(s, draw, frame);
      if (!s.ui.edit_elements && s.ui.brush == Brush::Off)
        if (handles.shown) draw_handles(draw, handles, s.ui.map_drag);
      draw_flaws_2d(s, draw, frame);
      draw_selection_2d(s, draw, frame);
      if (large)
        draw_scale_bar(draw, ImVec2(origin.x + 12, origin.y + 48), frame.size.y / (2 * frame.view.half_height),
                       std::string(enum_name(s.doc.design.units)), "in the map");
      draw->PopClipRect();
    }
  }
  if (large && s.views.show_legend && s.views.style.show_elements) {
    if (s.views.colour_mode == render::ColourMode::NeighbourRatio)
      ratio_legend(draw, origin, size);
    else
      type_legend(draw, origin, size);
  }
  draw->AddText(ImVec2(origin.x + 8, origin.y + 6), IM_COL32(220, 220, 220, 200), which == 0 ? "3D" : "2D map");
}

// The next toolbar item on this line when it fits, else on the next (the toolbar wraps rather
// than running off a narrow window).
void next_item(const char* label, float extra = 0) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + extra;
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

void toolbar(Studio& s) {
  render::SceneStyle& st = s.views.style;
  ImGui::Checkbox("surface", &st.show_surface);
  next_item("elements");
  ImGui::Checkbox("elements", &st.show_elements);
  next_item("lattice (L)");
  ImGui::Checkbox("lattice (L)", &st.show_lattice);
  next_item("map mesh");
  ImGui::Checkbox("map mesh", &st.show_map_wireframe);
  next_item("", 170);
  int mode = int(s.views.colour_mode);
  ImGui::SetNextItemWidth(170);
  const char* modes[] = {"colour: NN ratio", "colour: element type"};
  if (ImGui::Combo("##colour", &mode, modes, 2)) s.views.colour_mode = render::ColourMode(mode);
  next_item("legend");
  ImGui::Checkbox("legend", &s.views.show_legend);
  next_item("bare spots (B) (?)");
  ImGui::Checkbox("bare spots (B)", &s.views.show_flaws);
  help_marker("Marks, in both views, each bare spot of the final pavement (a dashed red ring: a stone of that size "
              "would still fit there, keeping the gap) and each stone removed because it still collided (a grey "
              "ghost). The status line counts both.");
  next_item("edit stones (E) (?)");
  ImGui::Checkbox("edit stones (E)", &s.ui.edit_elements);
  help_marker("Click a stone to select it (either view); drag it to move it, in 3D along the surface (it stays where you "
              "drop it, its neighbours make room), Ctrl+click to add one, Shift+drag a box to select many. Del "
              "deletes the selected stones, P pins them, Shift+P lets them go. Every edit is undoable and saved with the design.");
  next_item("swap views (V)");
  if (ImGui::Button("swap views (V)")) swap_views(s);
  next_item("inset (I)");
  if (ImGui::Checkbox("inset (I)", &s.views.show_inset)) fit_views_to_inset(s);
  next_item("map as 3D (M) (?)");
  bool follows = s.views.map_follows_3d;
  if (ImGui::Checkbox("map as 3D (M)", &follows)) set_map_follows_3d(s, follows);
  help_marker("Turns the 2D map to show the surface the way the 3D view does, each time the 3D view comes to rest. "
              "Off, the map's u axis runs across the screen.");
  next_item("reset view (R)");
  if (ImGui::Button("reset view (R)") && s.doc.surface.map) frame_views(s);
}

}  // namespace

void views_area(Studio& s, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  ImGui::Begin("Views", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();
  toolbar(s);
  const ImVec2 area = ImGui::GetContentRegionAvail();
  if (area.x >= 16 && area.y >= 16) s.views.map_aspect = area.x / area.y;
  if (!s.doc.surface.map || area.x < 16 || area.y < 16) {
    const char* text = s.loader.busy() ? "opening the surface..." : "Open a surface (File), or drop one on the window.";
    ImGui::SetCursorPos(ImVec2(ImGui::GetCursorPosX() + area.x * 0.5f - ImGui::CalcTextSize(text).x * 0.5f,
                               ImGui::GetCursorPosY() + area.y * 0.45f));
    ImGui::TextUnformatted(text);
    if (s.loader.busy()) {
      ImGui::SetCursorPosX(ImGui::GetCursorPosX() + area.x * 0.3f);
      ImGui::ProgressBar(s.loader.progress(), ImVec2(area.x * 0.4f, 0), s.loader.stage().c_str());
    }
    ImGui::End();
    return;
  }
  turn_map_like_3d(s);
  const int large = s.views.large_3d ? 0 : 1;
  if (!s.ui.edit_elements || s.views.large_3d) s.ui.box_from.reset();  // a box is drawn in the large 2D view only
  if (!s.ui.edit_elements || !s.views.large_3d) s.ui.dragging_element_3d = false;
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  s.views.large_origin = {corner.x, corner.y};
  s.views.large_size = {area.x, area.y};
  view(s, large, area, true);

  // The other view as an inset in the bottom-right corner, in a child window so that the mouse
  // over it does not reach the large view; I hides it when it is in the way.
  if (!s.views.show_inset) {
    s.renderer.stop_drawing(1 - large);  // an image it would never finish
    s.scene.drawing[1 - large].clear();
    ImGui::End();
    return;
  }
  const ImVec2 inset(std::max(80.0f, area.x * kInsetFraction), std::max(60.0f, area.y * kInsetFraction));
  ImGui::SetCursorScreenPos(ImVec2(corner.x + area.x - inset.x - 6, corner.y + area.y - inset.y - 6));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::BeginChild("inset", inset, true, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  view(s, 1 - large, ImGui::GetContentRegionAvail(), false);
  ImGui::EndChild();
  ImGui::PopStyleVar();
  ImGui::End();
}

}  // namespace paver::studio
