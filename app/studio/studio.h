#pragma once
// Paver Studio's parts, side by side: the document, the background work (surface loading, the
// live pavement), the views and the UI's own state. Each part keeps to itself; the functions
// here move data between them once per frame, and the panels are free functions of the parts.
#include "app_window.h"
#include "backend_choice.h"
#include "document.h"
#include "file_browser.h"
#include "live_pavement.h"
#include "scene.h"
#include "solving_frames.h"
#include "surface_loader.h"
#include "metal_cutter.h"
#include "view_settings.h"

#include "renderer.h"

#include <glm/vec2.hpp>

#include <chrono>
#include <deque>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace paver::studio {

struct RunSettings {
  std::string backend = "auto";  // cpu, vulkan or auto, as `paver run --backend`
  // The solver the runs use. A Vulkan solver gets a device context of its own: it runs on the
  // background thread, and VulkanContext::submit_and_wait (its command pool and queue) is not
  // synchronised, so sharing the window's context with the renderer on the UI thread would race.
  app::BackendChoice choice;
  int step_iterations = 10;       // iterations per press of Step
  bool auto_run = true;           // every design change re-runs the pavement
  // A design predicted to place more particles than this asks before it runs (the studio keeps
  // every particle, element and instance in memory and the UI waits on none of them, but a
  // 2.7M-element pendant still takes 5 GB and minutes).
  double point_budget = 300000;
  std::uint64_t budget_granted = 0;   // the document revision the designer said "run anyway" for
  std::uint64_t budget_asked = 0;     // the revision the question is (or was) asked for
  double budget_points = 0;           // and the points it predicted
};

// The measured cost of a particle in the studio (docs/benchmarks.md: the lily at 1M, 2 cores):
// memory and solve time, for the question asked above the budget.
inline constexpr double kStudioBytesPerPoint = 2000;
inline constexpr double kStudioSecondsPerPoint = 7e-5;

// The unit-cell editor's mode: what a click does.
enum class CellEditMode { Flip, Remove, Add };
// What a left drag in the 2D view changes.
enum class MapDrag { None, Offset, Rotation, Scale };
// The guidance brush (design/guidance.h): off, or painting the pattern looser or denser.
enum class Brush { Off, Looser, Denser };

struct UiState {
  std::string surface_path, design_path, export_dir = "out", png_path = "view3d.png", custom_shape_path;
  CellEditMode cell_mode = CellEditMode::Flip;
  int add_from_vertex = -1;            // Add: the first vertex clicked, -1 = none yet
  glm::ivec2 add_from_cell{0, 0};      // and its lattice cell
  bool add_virtual = false;            // Add makes a virtual edge
  MapDrag map_drag = MapDrag::None;
  bool quit_dialog = false;            // asking Save / Discard / Cancel
  std::string quit_message;            // why the Quit dialog's Save did not save
  std::string fill_sizes_text;         // the stocked sizes field as typed (applied on Enter)
  std::string fill_sizes_problem;      // why the last list typed there was not taken
  bool fill_sizes_editing = false;
  std::optional<std::filesystem::path> screenshot;  // write the next presented frame here
  std::string select_panel;            // a script's `panel NAME`: selected on the next frame
  CutRequest cut;                      // Cut metal: the thickness, seat depth, ring size and rules
  CutAxis cut_axis = CutAxis::Auto;    // the axis the surface on screen was cut across (the design's placement.cut_axis follows)
  int selected_element = -1;           // the element id selected in the views or by `select`; -1 = none
  std::vector<int> box_selected;       // more elements, from a Shift+drag box (or `select_box`): Del and P take all
  std::optional<glm::dvec2> box_from;  // the corner where a box selection's drag started, map units
  bool edit_elements = false;          // the views' left button selects, drags and adds single elements
  bool dragging_element = false;       // the selected element is being dragged in the 2D view
  bool dragging_element_3d = false;    // ... in the 3D view, along the surface
  glm::dvec2 drag_from{0};             // where that drag started, map units
  glm::dvec2 move_by{0};               // the elements panel's move, in spacings D
  Brush brush = Brush::Off;            // a left drag in the 2D map paints guidance
  double brush_radius = 3;             // x D
  double brush_strength = 0.2;         // the spacing's change at a dab's centre
  std::optional<glm::dvec2> last_dab;  // where the stroke being painted put its last dab
  FileBrowser browser;                 // the file dialog (open, load, save as, export folder, shape)
  std::optional<std::filesystem::path> confirm_replace;  // Save as onto this existing file: asking
};



struct Studio {
  Studio(AppWindow& w, render::Renderer& r) : window(w), renderer(r) {}

  AppWindow& window;
  render::Renderer& renderer;
  Document doc;
  SurfaceLoader loader;
  MetalCutter cutter;
  LivePavement live;
  RunSettings run;
  ViewSettings views;
  Scene scene;
  UiState ui;
  std::vector<std::filesystem::path> recent;
  bool script_mode = false;  // quitting does not ask; results are logged to stdout
  bool quit = false;
  bool result_shown = false; // the final pavement was uploaded this frame
  SolvingFrames solving_frames;
  std::optional<SolvingFrames> orbiting_frames;  // a script's orbit in progress: its frames
  std::chrono::steady_clock::time_point last_present{};
  std::deque<InputFrame> input_queue;  // a script's mouse and keys, played one per frame
};

// Frames both views on the surface: the whole map in the 2D view and the whole surface in the 3D
// view; with the inset shown, a large 2D view keeps the map left of it.
void frame_views(Studio& s);
// The views made room for the inset (or not) after a swap or a toggle: the 2D view framed again,
// the 3D view's target moved left of it (the camera stays where the designer put it).
void fit_views_to_inset(Studio& s);
// Once the 3D camera rests after it moved (a drag, a script's orbit, a reset), the 2D map turns
// to show the surface the same way round: framed again if it was framed, else turned in place.
void turn_map_like_3d(Studio& s);
void set_map_follows_3d(Studio& s, bool follows);  // M: the map turned like the 3D view, or u across
void swap_views(Studio& s);      // the large view and the inset trade places; the map is framed again
// Starts loading a surface in the background; the design stays.
void open_surface(Studio& s, const std::filesystem::path& path);
// Sets the plane a closed surface is cut across; the surface being opened, or the closed surface
// on screen, is opened again with it.
void set_cut_axis(Studio& s, CutAxis axis);  // a design change (placement.cut_axis), undoable
void follow_cut_axis(Studio& s);             // maps the surface again when the design's axis changed
// Save as: the design written to `path` (never over a bundled design or an input: the error dialog
// says so), then the design's path and a recent file. False when refused.
bool save_design_as(Studio& s, const std::filesystem::path& path);
// Where the file dialog opens for `purpose`: the surface's, the design's (a bundled design's Save
// as under a new name in the working folder), the export folder's or the custom shape's path.
std::filesystem::path browse_start(const Studio& s, BrowsePurpose purpose);
// Puts a file opened or saved at the top of the recent files (and saves the list).
void remember_file(Studio& s, const std::filesystem::path& path);
// A dropped or recent file: a .json design is loaded, anything else opened as a surface.
void open_any(Studio& s, const std::filesystem::path& path);
// Chooses the solver backend (cpu, vulkan, auto); reports when it cannot.
void set_backend(Studio& s, const std::string& name);
// Writes placements.csv, stones.csv, elements.ply/.obj/.stl/.glb, paved.3mf, design.json and
// report.json into `folder`,
// as `paver run` does. Throws InputError (nothing to export yet, a bad folder).
void export_outputs(Studio& s, const std::filesystem::path& folder);
// Starts cutting the final pavement's seats into metal `thickness` thick (MetalCutter), with the
// File panel's seat depth, ring size and rules (UiState::cut); cut.stl, cut.3mf and stones.3mf go
// into `folder` when it is done. Throws InputError (nothing to cut yet, a bad thickness, depth,
// diameter or rule, a bad folder, an input in the way).
void cut_metal(Studio& s, const std::filesystem::path& folder, double thickness);
// The 3D view as a PNG, at its current size. Throws InputError.
void save_view_png(Studio& s, const std::filesystem::path& path);

// Whether the current design may run: within RunSettings::point_budget, or granted. Above it, the
// question is asked once per revision (a script stops with an error instead).
bool within_budget(Studio& s);
// The designer's answer: run it anyway, or go back to the design before.
// "2,670,000 elements, above the studio's budget of 500,000: about 5,340 GB of memory and 3.1
// minutes to solve on 2 cores": what a design over the run budget would cost, in plain figures.
std::string large_design_text(double points, double budget);
void grant_budget(Studio& s);
void decline_budget(Studio& s);

// Run control for the optimization panel and the shortcuts.
void run_now(Studio& s, bool paused = false, int step = 0);
void toggle_pause(Studio& s);
void step_run(Studio& s);
void reset_run(Studio& s);

// Where map point `uv` shows in the window, in the large 2D view as last drawn. Throws InputError
// when the 2D view is not the large one (`strict`), else gives the large view's middle.
glm::vec2 map_to_window(const Studio& s, glm::dvec2 uv, bool strict = true);
// A drag of element `id` in the large 3D view to the surface point at map point `to`: the window
// pixels where it starts and ends. Throws InputError when the 3D view is not the large one, the
// element is not on screen or `to` is off the map.
std::pair<glm::vec2, glm::vec2> element_drag_3d(const Studio& s, int id, glm::dvec2 to);
// Selects element `id` of the pavement on screen and says what it is in the status line. Throws
// InputError when there is no such element.
void select_element(Studio& s, int id);
// Selects every element in the box with map corners `a` and `b` (none: the selection is cleared),
// its sides along the map's axes turned by `turn`: a Shift+drag gives the 2D view's turn, so the
// box is the one drawn on screen; the script's select_box the map's own axes (0).
void select_box(Studio& s, glm::dvec2 a, glm::dvec2 b, double turn = 0);
// The selected elements: the one clicked, then the box's.
std::vector<int> selection(const UiState& ui);
void clear_selection(UiState& ui);

// The edits the views, the elements panel and the shortcuts make on the selected elements (pin
// and delete take the whole selection, as one undo step; a move takes the one clicked).
void pin_selected(Studio& s, bool pinned);
void delete_selected(Studio& s);
void move_selected(Studio& s, glm::dvec2 offset);  // map units
void add_element_at(Studio& s, glm::dvec2 uv);
// One dab of the guidance brush at `uv` (radius in spacings D, strength as GuidanceDab's);
// `stroke`: part of a drag, so one undo step for the whole stroke.
void paint_guidance(Studio& s, glm::dvec2 uv, double radius, double strength, bool stroke = false);

// Whether the pavement on screen is final for the current design.
bool result_is_final(const Studio& s);

// Once per frame, before the panels: files dropped, the loader and the run's results taken in,
// the next run started when due, the renderer's scene updated.
void update_studio(Studio& s);
// Once per frame: the whole UI (panels, views, dialogs, shortcuts).
void draw_studio(Studio& s);
// After the frame was presented: the latency of a result just shown, the screenshot.
void after_present(Studio& s, const std::optional<render::Image>& frame);
// The window's close button: quits, or asks first when the design has unsaved changes.
void handle_close_request(Studio& s);

}  // namespace paver::studio
