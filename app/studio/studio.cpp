#include "pipeline/pavement.h"
#include "studio.h"
#include "number_rules.h"

#include "element_editing.h"
#include "map_frame.h"
#include "view3d_frame.h"

#include "map/lifting.h"

#include "io/mesh_formats.h"
#include "io/output_guard.h"
#include "io/stl_unit_warning.h"
#include "panels/panels.h"
#include "recent_files.h"
#include "core/stopwatch.h"
#include "pipeline/run_outputs.h"
#include "shortcuts.h"

#include "core/input_error.h"
#include "core/number_text.h"

#include <glm/geometric.hpp>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <chrono>
#include <cstdio>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;


void take_loaded_surface(Studio& s) {
  std::optional<SurfaceLoadOutcome> outcome = s.loader.take_outcome();
  if (!outcome) return;
  if (!outcome->surface) {
    report_error(s.doc, outcome->error, outcome->input_error);
    return;
  }
  OpenedSurface& opened = *outcome->surface;
  const SurfaceMap& map = *opened.map;
  remember_file(s, opened.path);
  std::string status = "opened " + opened.path.string() + ": " + std::to_string(map.mesh.vertex_count()) +
                       " vertices, " + std::to_string(map.mesh.face_count()) + " faces";
  for (const auto& warning : opened.warnings) status += "; warning: " + warning;
  set_surface(s.doc, Surface{opened.path, opened.map, std::move(opened.warnings), std::move(opened.timings)});
  frame_views(s);
  report_status(s.doc, status);
}

void take_cut_outcome(Studio& s) {
  std::optional<CutOutcome> outcome = s.cutter.take_outcome();
  if (!outcome) return;
  if (outcome->ok)
    report_status(s.doc, outcome->message);
  else
    report_error(s.doc, outcome->message);
}

void take_run_outcome(Studio& s) {
  std::optional<RunOutcome> outcome = s.live.take_outcome();
  if (!outcome || outcome->revision != s.doc.revision) return;  // an older design's: dropped
  if (!outcome->pavement) {
    report_run_error(s.doc, outcome->error, outcome->input_error);
    return;
  }
  const Pavement& p = *outcome->pavement;
  const std::shared_ptr<const Pavement> before = s.doc.result.pavement;
  set_result(s.doc, outcome->pavement, outcome->revision, outcome->milliseconds);
  // Ids name the elements of one pattern layout: a new layout drops the selection, and an element
  // an edit removed leaves it (Del must never reach an element the designer did not pick).
  if (before && changes_pattern_layout(before->design, p.design)) {
    clear_selection(s.ui);
  } else {
    if (s.ui.selected_element >= 0 && !find_element(p, s.ui.selected_element)) s.ui.selected_element = -1;
    std::erase_if(s.ui.box_selected, [&](int id) { return !find_element(p, id); });
    if (s.ui.selected_element < 0 && !s.ui.box_selected.empty()) {
      s.ui.selected_element = s.ui.box_selected.front();
      s.ui.box_selected.erase(s.ui.box_selected.begin());
    }
  }
  report_run_status(s.doc, run_status_text(s.doc.result));
}

}  // namespace

namespace {
// The right share of the large view that the inset covers, kept free when the views are framed.
double inset_share(const Studio& s) { return s.views.show_inset ? kInsetFraction : 0; }
}  // namespace

namespace {
// The turn the 2D map takes for the camera now: none when the designer switched it off.
double map_turn_for_camera(const Studio& s, const SurfaceMap& map) {
  return s.views.map_follows_3d ? render::map_turn_to_match(map, s.views.camera, s.views.map_aspect) : 0;
}

render::MapView framed_map(const Studio& s, const SurfaceMap& map, double turn) {
  return render::frame_map(map, s.views.map_aspect, s.views.large_3d ? 0 : inset_share(s), 0, turn);
}
}  // namespace

void fit_views_to_inset(Studio& s) {
  s.views.camera.screen_shift_x = s.views.large_3d ? float(-inset_share(s)) : 0;
  if (!s.doc.surface.map) return;
  const SurfaceMap& map = map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology);
  s.views.map_view = framed_map(s, map, map_turn_for_camera(s, map));
  s.views.map_turned_for = s.views.last_look = glm::vec2(s.views.camera.yaw, s.views.camera.pitch);
}

namespace {
void turn_map_now(Studio& s) {
  if (!s.doc.surface.map) return;
  s.views.map_turned_for = glm::vec2(s.views.camera.yaw, s.views.camera.pitch);
  const SurfaceMap& map = map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology);
  const double turn = map_turn_for_camera(s, map);
  const render::MapView before = framed_map(s, map, s.views.map_view.turn);
  render::MapView& view = s.views.map_view;
  const bool was_framed = glm::length(view.centre - before.centre) <= 1e-4f * before.half_height &&
                          std::abs(view.half_height - before.half_height) <= 1e-4f * before.half_height;
  if (was_framed) {
    view = framed_map(s, map, turn);
  } else {
    view.turn = float(turn);  // about the centre the designer chose, at their zoom
  }
}
}  // namespace

void turn_map_like_3d(Studio& s) {
  const glm::vec2 look(s.views.camera.yaw, s.views.camera.pitch);
  const bool resting = look == s.views.last_look;
  s.views.last_look = look;
  if (resting && look != s.views.map_turned_for) turn_map_now(s);
}

void set_map_follows_3d(Studio& s, bool follows) {
  s.views.map_follows_3d = follows;
  turn_map_now(s);
}

bool save_design_as(Studio& s, const fs::path& path) {
  if (!save_design_file(s.doc, path)) return false;
  s.ui.design_path = path.string();
  remember_file(s, path);
  return true;
}

fs::path browse_start(const Studio& s, BrowsePurpose purpose) {
  const fs::path design = s.ui.design_path.empty() ? s.doc.design_path : fs::path(s.ui.design_path);
  switch (purpose) {
    case BrowsePurpose::OpenSurface: return s.ui.surface_path.empty() ? s.doc.surface.path : fs::path(s.ui.surface_path);
    case BrowsePurpose::LoadDesign: return design;
    case BrowsePurpose::SaveDesign: return save_as_start(design);
    case BrowsePurpose::ExportFolder: return s.ui.export_dir;
    case BrowsePurpose::CustomShape:
      return s.ui.custom_shape_path.empty() ? fs::path(s.doc.design.elements.custom_shape) : fs::path(s.ui.custom_shape_path);
  }
  return {};
}

void frame_views(Studio& s) {
  if (!s.doc.surface.map) return;
  s.views.camera =
      render::frame_surface(s.doc.surface.map->mesh, s.views.map_aspect, s.views.large_3d ? inset_share(s) : 0);
  fit_views_to_inset(s);
}

void swap_views(Studio& s) {
  s.views.large_3d = !s.views.large_3d;
  fit_views_to_inset(s);
}

void remember_file(Studio& s, const fs::path& path) {
  remember_recent_file(s.recent, path);
  try {
    save_recent_files(recent_files_path(), s.recent);
  } catch (const std::exception& e) {
    report_status(s.doc, std::string("could not save the recent files: ") + e.what());  // not worth a dialog
  }
}


void open_surface(Studio& s, const fs::path& path) {
  s.loader.start(path, s.ui.cut_axis);
  s.ui.surface_path = path.string();
  report_status(s.doc, "opening " + path.string());
}

// The design says where a closed surface is cut (placement.cut_axis): a loaded design, an undo
// and the File panel's choice all end here, which maps the surface again across it. A load in
// flight is started again with the axis (it may be a closed surface); else the closed surface on
// screen is mapped again.
void follow_cut_axis(Studio& s) {
  const CutAxis axis = s.doc.design.placement.cut_axis;
  if (axis == s.ui.cut_axis) return;
  s.ui.cut_axis = axis;
  if (s.loader.busy())
    open_surface(s, fs::path(s.loader.path()));
  else if (s.doc.surface.map && is_atlas(*s.doc.surface.map))
    open_surface(s, s.doc.surface.path);
}

void set_cut_axis(Studio& s, CutAxis axis) {
  if (axis == s.doc.design.placement.cut_axis) return;
  Design next = s.doc.design;
  next.placement.cut_axis = axis;
  if (change_design(s.doc, next)) follow_cut_axis(s);
}

void open_any(Studio& s, const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".json") {
    if (open_design_file(s.doc, path)) {
      s.ui.design_path = path.string();
      remember_file(s, path);
    }
  } else {
    open_surface(s, path);
  }
}

void set_backend(Studio& s, const std::string& name) {
  try {
    s.run.choice = app::choose_backend(name, "", 0);
    s.run.backend = name;
    report_status(s.doc, "solver: " + s.run.choice.name +
                             (s.run.choice.device.empty() ? std::string() : " on " + s.run.choice.device));
    if (s.doc.surface.map) run_now(s);
  } catch (const std::exception& e) {
    report_error(s.doc, e);
  }
}

glm::vec2 map_to_window(const Studio& s, glm::dvec2 uv, bool strict) {
  const glm::vec2 origin = s.views.large_origin, size = s.views.large_size;
  if (s.views.large_3d || size.x < 16 || size.y < 16) {
    if (strict) throw InputError("the 2D map is not the large view: use view2d first");
    return origin + 0.5f * size;
  }
  const ImVec2 at = MapFrame{ImVec2(origin.x, origin.y), ImVec2(size.x, size.y), s.views.map_view}.to_screen(uv);
  return {at.x, at.y};
}

std::pair<glm::vec2, glm::vec2> element_drag_3d(const Studio& s, int id, glm::dvec2 to) {
  const glm::vec2 origin = s.views.large_origin, size = s.views.large_size;
  if (!s.views.large_3d || size.x < 16 || size.y < 16) throw InputError("the 3D view is not the large view: use view3d first");
  if (!s.doc.result.pavement || !s.doc.surface.map) throw InputError("there is no pavement on screen yet");
  const std::optional<std::size_t> i = find_element(*s.doc.result.pavement, id);
  if (!i) throw InputError("element " + std::to_string(id) + " is not in the pavement on screen");
  LiftedPoints lifted;
  lifted.resize(1);
  const glm::dvec2 target[] = {to};
  if (lift_points(map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology), target, lifted) > 0)
    throw InputError("map point (" + std::to_string(to.x) + ", " + std::to_string(to.y) + ") is off the surface");
  const View3dFrame frame(ImVec2(origin.x, origin.y), ImVec2(size.x, size.y), s.views.camera);
  const std::optional<ImVec2> a = frame.to_screen(s.doc.result.pavement->elements.position[*i]);
  const std::optional<ImVec2> b = frame.to_screen(lifted.position[0]);
  if (!a || !b) throw InputError("the drag is behind the camera");
  return {{a->x, a->y}, {b->x, b->y}};
}

void select_element(Studio& s, int id) {
  if (!s.doc.result.pavement) throw InputError("select: there is no pavement on screen yet");
  const std::string line = describe_element(s.doc.design, *s.doc.result.pavement, id);
  clear_selection(s.ui);
  s.ui.selected_element = id;
  report_status(s.doc, line);
}

void select_box(Studio& s, glm::dvec2 a, glm::dvec2 b, double turn) {
  if (!s.doc.result.pavement) throw InputError("select: there is no pavement on screen yet");
  std::vector<int> ids = elements_in_box(*s.doc.result.pavement, a, b, turn);
  clear_selection(s.ui);
  if (ids.empty()) return report_status(s.doc, "no element in the box");
  s.ui.selected_element = ids.front();
  s.ui.box_selected.assign(ids.begin() + 1, ids.end());
  report_status(s.doc, std::to_string(ids.size()) + " elements selected: Del deletes them, P pins them");
}

std::vector<int> selection(const UiState& ui) {
  std::vector<int> ids;
  if (ui.selected_element >= 0) ids.push_back(ui.selected_element);
  ids.insert(ids.end(), ui.box_selected.begin(), ui.box_selected.end());
  return ids;
}

void clear_selection(UiState& ui) {
  ui.selected_element = -1;
  ui.box_selected.clear();
}

namespace {

// An edit of the pavement on screen: refused (and said why) while there is none or it is stale.
template <class Edit>
bool edit_on_screen(Studio& s, const Edit& edit) {
  if (!s.doc.result.pavement) {
    report_status(s.doc, "wait for the pavement before editing its elements");
    return false;
  }
  try {
    return change_design(s.doc, edit(*s.doc.result.pavement));
  } catch (const InputError& e) {
    report_error(s.doc, e);
    return false;
  }
}

}  // namespace

// An edit of every selected element, one undo step. A single element that cannot take it says why;
// in a box, those that cannot (a bead, a stone the refill places anew) are left as they are and
// counted in the status line.
template <class EditOne>
bool edit_selection(Studio& s, const char* done, const EditOne& edit_one) {
  const std::vector<int> ids = selection(s.ui);
  if (ids.empty()) {
    report_status(s.doc, "select an element first (edit stones, then click one)");
    return false;
  }
  int skipped = 0;
  const bool taken = edit_on_screen(s, [&](const Pavement& p) {
    Design d = s.doc.design;
    for (const int id : ids) {
      if (ids.size() == 1) return edit_one(d, p, id);
      try {
        d = edit_one(d, p, id);
      } catch (const InputError&) {
        ++skipped;
      }
    }
    return d;
  });
  // Every edit says what it did: a silent toggle let a dragged stone slide back unnoticed.
  if (taken && ids.size() > 1)
    report_status(s.doc, std::string(done) + " " + std::to_string(ids.size() - std::size_t(skipped)) + " elements" +
                             (skipped ? ", left " + std::to_string(skipped) + " that cannot take it (beads, refill)" : ""));
  else if (taken)
    report_status(s.doc, std::string(done) + " element " + std::to_string(ids.front()));
  return taken;
}

void pin_selected(Studio& s, bool pinned) {
  edit_selection(s, pinned ? "pinned" : "unpinned", [&](const Design& d, const Pavement& p, int id) {
    return with_pinned(d, p, id, pinned);
  });
}

void delete_selected(Studio& s) {
  if (edit_selection(s, "deleted", [](const Design& d, const Pavement& p, int id) { return without_element(d, p, id); }))
    clear_selection(s.ui);
}

void move_selected(Studio& s, glm::dvec2 offset) {
  const int id = s.ui.selected_element;
  if (id < 0) return report_status(s.doc, "select an element first (edit stones, then click one)");
  edit_on_screen(s, [&](const Pavement& p) { return with_dragged(s.doc.design, p, id, offset); });
}

void add_element_at(Studio& s, glm::dvec2 uv) {
  int id = -1;
  edit_on_screen(s, [&](const Pavement& p) { return with_added_element(s.doc.design, p, uv, &id); });
  if (id < 0) return;
  clear_selection(s.ui);
  s.ui.selected_element = id;
}

void paint_guidance(Studio& s, glm::dvec2 uv, double radius, double strength, bool stroke) {
  const double spacing = s.doc.result.pavement ? s.doc.result.pavement->design.pattern.spacing : s.doc.design.pattern.spacing;
  if (!(spacing > 0)) return report_status(s.doc, "wait for the pavement before painting guidance");
  Design d = s.doc.design;
  // Only the lattice follows a painted field: an auto design keeps it.
  if (d.pattern.topology == Topology::Auto) d.pattern.topology = Topology::Lattice;
  d.guidance.push_back({uv, radius * spacing, strength});
  change_design(s.doc, d, stroke);
}

bool result_is_final(const Studio& s) {
  return s.doc.result.pavement && s.doc.result.revision == s.doc.revision && !s.loader.busy();
}

// The studio exports every format: a designer hands the set on and should not have to choose.
constexpr MeshFormats kStudioExportFormats{.ply = true, .obj = true, .stl = true, .glb = true, .threemf = true};

namespace {

// A view as the screen shows it, at the 3D view's size on screen (1280 x 800 before it was drawn):
// 0, the 3D view, centred (a PNG has no inset to make room for), with its legend; 1, the whole 2D
// map framed to fit (on screen it may be the small inset).
render::Image view_image(Studio& s, int view) {
  const std::vector<double>& shown = s.scene.rendered[0];
  const int width = shown.size() >= 2 ? int(shown[0]) : 1280, height = shown.size() >= 2 ? int(shown[1]) : 800;
  if (view == 0) {
    render::OrbitCamera centred = s.views.camera;
    centred.screen_shift_x = 0;
    s.renderer.render_3d(width, height, centred, s.views.style);
  } else {
    const render::MapView whole =
        render::frame_map(map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology),
                          double(width) / double(height), 0, 0, s.views.map_view.turn);  // turned as on screen
    s.renderer.render_2d(width, height, whole, s.views.style);
  }
  s.scene.rendered[std::size_t(view)].clear();  // the screen's view is drawn again next frame, whole
  s.scene.redraw_whole[std::size_t(view)] = true;
  render::Image image = s.renderer.read_back(view);
  if (view == 0 && s.views.show_legend && s.views.style.show_elements) {
    if (s.views.colour_mode == render::ColourMode::NeighbourRatio)
      render::draw_ratio_legend(image);
    else
      render::draw_type_legend(image);
  }
  return image;
}

}  // namespace

void export_outputs(Studio& s, const fs::path& folder) {
  if (!result_is_final(s))
    throw InputError("nothing to export yet: the pavement for this design is not finished (run it, or wait)");
  const Pavement& pavement = *s.doc.result.pavement;
  check_run_outputs(folder, kStudioExportFormats, {folder / "preview.png", folder / "param.png"},
                    {s.doc.surface.path, s.doc.design_path, s.doc.design.elements.custom_shape});
  StageTimings timings = s.doc.surface.timings;
  timings.insert(timings.end(), pavement.timings.begin(), pavement.timings.end());
  const RunInfo info{s.doc.surface.path.string(), s.doc.design_path.empty() ? "studio" : s.doc.design_path.string(),
                     s.doc.design.pattern.spacing <= 0, {}};
  // The pictures `paver run --png` writes, drawn by the studio's own renderer as the views show them;
  // before report.json and report.html, which embeds preview.png.
  const ExtraOutputs pictures = [&](const fs::path& staging, StageTimings& stages, nlohmann::json&) {
    const Stopwatch watch;
    render::write_png(staging / "preview.png", view_image(s, 0));
    render::write_png(staging / "param.png", view_image(s, 1));
    stages.emplace_back("png", watch.milliseconds());
  };
  const std::vector<std::string> untidy =
      write_run_outputs(folder, info, *s.doc.surface.map, pavement, timings,
                        {.custom = custom_shape(s.doc), .formats = kStudioExportFormats}, pictures);
  s.ui.export_dir = folder.string();  // the File panel shows where the files went (a script's export too)
  const std::string stl_units = stl_unit_warning(pavement.design.units, {"elements.stl"});
  std::string status = "exported to " + folder.string() + (stl_units.empty() ? "" : "; warning: " + stl_units);
  for (const std::string& w : untidy) status += "; warning: " + w;
  report_status(s.doc, status);
}

void cut_metal(Studio& s, const fs::path& folder, double thickness) {
  if (!result_is_final(s))
    throw InputError("nothing to cut yet: the pavement for this design is not finished (run it, or wait)");
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw InputError("metal thickness " + number_text(thickness) + ": it needs to be above 0 (surface units)");
  CutRequest request = s.ui.cut;
  request.thickness = thickness;
  for (const auto& [name, value] : {std::pair{"seat depth", request.seat_depth}, {"inside diameter", request.inside_diameter_mm},
                                    {"culet clearance", request.culet_clearance}, {"seat wall", request.seat_wall},
                                    {"table height", request.table_height}})
    if (!(value >= 0) || !std::isfinite(value))
      throw InputError(std::string(name) + " " + number_text(value) + ": 0 or more (0: " +
                       (std::string_view(name) == "seat depth"        ? "the girdles at the surface"
                        : std::string_view(name) == "inside diameter" ? "the metal follows the normals"
                                                                     : "no such rule") +
                       ")");
  const std::vector<fs::path> inputs = {s.doc.surface.path, s.doc.design_path, s.doc.design.elements.custom_shape};
  std::vector<fs::path> outputs;
  for (const std::string& name : cut_file_names()) outputs.push_back(folder / name);
  refuse_overwriting_inputs(inputs, outputs);
  check_output_folder(folder);
  s.cutter.start(s.doc.surface.map, s.doc.result.pavement, shared_custom_shape(s.doc), request, folder);
  report_status(s.doc, "cutting the seats into the metal...");
}

void save_view_png(Studio& s, const fs::path& path) {
  if (!s.doc.surface.map) throw InputError("nothing to save yet: open a surface first");
  const render::Image image = view_image(s, 0);
  prepare_output(s.doc, path);
  render::write_png(path, image);
  report_status(s.doc, "saved " + path.string());
}

bool within_budget(Studio& s) {
  const std::uint64_t revision = s.doc.revision;
  if (s.run.budget_granted == revision) return true;
  if (s.run.budget_asked == revision) return false;  // asked already; waiting for the answer
  const Design& d = s.doc.design;
  if (d.pattern.spacing <= 0) return true;  // derived from the surface: a sane size
  double points = 0;
  try {
    const UnitCell cell = make_design_cell(d.pattern);
    points = estimate_point_count(map_for_topology(*s.doc.surface.map, d.pattern.topology), cell, d.placement);
  } catch (const std::exception&) {
    return true;  // the run reports what is wrong with the design
  }
  if (!(points > s.run.point_budget)) return true;
  s.run.budget_asked = revision;
  s.run.budget_points = points;
  const std::string text = "D = " + significant_text(d.pattern.spacing, 4) + " would place about " +
                           large_design_text(s.run.budget_points, s.run.point_budget);
  if (s.script_mode)
    report_error(s.doc,
                 std::string(text) + "; a script does not ask: use a larger spacing, or `paver run` for the full design",
                 true);
  else
    report_status(s.doc, text);
  return false;
}

std::string large_design_text(double points, double budget) {
  return rounded_figure_text(points) + " elements, above the studio's budget of " + rounded_figure_text(budget) +
         ": about " + rounded_figure_text(points * kStudioBytesPerPoint / 1e9) + " GB of memory and " +
         duration_text(points * kStudioSecondsPerPoint) + " to solve on 2 cores";
}

void grant_budget(Studio& s) {
  s.run.budget_granted = s.doc.revision;
  run_now(s);
}

void decline_budget(Studio& s) {
  s.run.budget_asked = s.doc.revision;  // not asked again for this revision
  if (undo(s.doc))
    report_status(s.doc, "not run: the design is back to before that change");
  else
    report_status(s.doc, "not run: use a larger spacing");
}

void run_now(Studio& s, bool paused, int step) {
  if (!s.doc.surface.map) {
    report_status(s.doc, "open a surface first");
    return;
  }
  if (!within_budget(s)) return;
  // Run again for the same design (Run, Step, another backend): the latency counts from now.
  if (s.live.revision() == s.doc.revision) s.doc.edit_clock.restart(Clock::now());
  RunRequest request;
  request.map = s.doc.surface.map;
  request.design = s.doc.design;
  request.revision = s.doc.revision;
  request.solver = s.run.choice.factory;
  request.custom_shape = shared_custom_shape(s.doc);
  request.paused = paused;
  request.step = step;
  mark_run_started(s.doc);
  s.live.start(std::move(request));
}

void toggle_pause(Studio& s) {
  switch (s.live.state()) {
    case RunState::Running: s.live.pause(); break;
    case RunState::Paused: s.live.resume(); break;
    default: run_now(s);
  }
}

void step_run(Studio& s) {
  const RunState state = s.live.state();
  if (state == RunState::Running || state == RunState::Paused)
    s.live.step(s.run.step_iterations);
  else
    run_now(s, true, s.run.step_iterations);
}

void reset_run(Studio& s) {
  s.live.reset();
  report_status(s.doc, "run reset: Run starts the optimization again; the last result stays on screen until then");
}

void update_studio(Studio& s) {
  for (const std::string& path : s.window.take_dropped_paths()) open_any(s, path);
  take_loaded_surface(s);
  follow_cut_axis(s);
  take_run_outcome(s);
  take_cut_outcome(s);
  // A number field refused what was typed (its reason is under it too): said on the status line.
  for (const std::string& refusal : take_refusals()) report_status(s.doc, "refused: " + refusal);
  // The edit's clock stops while the run sits paused, whatever paused it (Space, a Step's end).
  if (s.live.state() == RunState::Paused)
    s.doc.edit_clock.pause(Clock::now());
  else
    s.doc.edit_clock.resume(Clock::now());
  if (!ImGui::IsAnyItemActive()) end_gesture(s.doc);
  if (s.run.auto_run && s.doc.surface.map && !s.loader.busy() && s.live.revision() != s.doc.revision &&
      Clock::now() >= s.doc.run_due)
    run_now(s);
  s.result_shown = sync_scene(s.scene, s.renderer, s.doc, s.live, s.views);
}

// What the status bar shows before its text ("[final, 257 ms from the edit] unsaved "), pixels.
constexpr float kStatusPrefixWidth = 300;

void draw_studio(Studio& s) {
  handle_shortcuts(s);
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  // The status line wraps onto up to three lines rather than run off the window (a verdict with its
  // problems and the bare spots is long); the views give up the height.
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float text_height =
      ImGui::CalcTextSize(s.doc.messages.status.c_str(), nullptr, false, viewport->WorkSize.x - kStatusPrefixWidth).y;
  const float status_height = ImGui::GetFrameHeightWithSpacing() + 4 + std::min(std::max(text_height - line, 0.0f), 2 * line);
  const ImVec2 origin = viewport->WorkPos, size = viewport->WorkSize;
  // The splitter keeps both sides usable: the panels at least 300 pixels, the views 40% of the window.
  const float side_width = s.views.side_width > 0
                               ? std::clamp(s.views.side_width, std::min(300.0f, size.x * 0.4f), std::max(300.0f, size.x * 0.6f))
                               : std::min(430.0f, size.x * 0.4f);
  side_panels(s, origin, ImVec2(side_width, size.y - status_height));
  views_area(s, ImVec2(origin.x + side_width, origin.y), ImVec2(size.x - side_width, size.y - status_height));
  panel_splitter(s, ImVec2(origin.x + side_width - 3, origin.y), size.y - status_height);
  status_bar(s, ImVec2(origin.x, origin.y + size.y - status_height), ImVec2(size.x, status_height));
  dialogs(s);
  file_dialog(s);
}

void after_present(Studio& s, const std::optional<render::Image>& frame) {
  SolvingFrames& f = s.solving_frames;
  const auto now = std::chrono::steady_clock::now();
  // This frame's time, present to present (none for the first frame).
  const std::optional<double> frame_ms =
      s.last_present == Clock::time_point{}
          ? std::nullopt
          : std::optional<double>(std::chrono::duration<double, std::milli>(now - s.last_present).count());
  s.last_present = now;
  if (s.live.state() == RunState::Running) {
    if (frame_ms) f.frame_ms.push_back(*frame_ms);
    f.solving = true;
  } else if (f.solving) {
    if (s.script_mode && !f.frame_ms.empty()) {
      std::printf("frames_while_solving %s, live images %d\n", describe(frame_pace(f.frame_ms)).c_str(),
                  f.images_drawn_in_slices);
      std::fflush(stdout);
    }
    f = {};
  }
  if (s.orbiting_frames && frame_ms) s.orbiting_frames->frame_ms.push_back(*frame_ms);
  if (s.result_shown && s.doc.result.latency_ms < 0) {
    s.doc.result.latency_ms = s.doc.edit_clock.ms(Clock::now());
    if (s.script_mode) {
      std::printf("latency_ms %.1f\n", s.doc.result.latency_ms);
      std::fflush(stdout);
    }
  }
  if (!s.ui.screenshot) return;
  if (!frame && s.window.can_capture()) return;  // the swapchain was being rebuilt: next frame
  try {
    if (!frame) throw InputError("screenshots are not possible here: the window's swapchain cannot be copied");
    prepare_output(s.doc, *s.ui.screenshot);
    render::write_png(*s.ui.screenshot, *frame);
    report_status(s.doc, "screenshot " + s.ui.screenshot->string());
  } catch (const std::exception& e) {
    report_error(s.doc, e);
  }
  s.ui.screenshot.reset();
}

void handle_close_request(Studio& s) {
  if (!s.window.close_requested()) return;
  if (s.script_mode || !s.doc.dirty) {
    s.quit = true;
    return;
  }
  s.window.cancel_close();
  s.ui.quit_dialog = true;
}

}  // namespace paver::studio
