#pragma once
// The studio's document: the surface, the design being edited with its undo history, and what
// is derived from them (the last final pavement and its report figures). A plain struct: panels
// read it and change the design only through change_design, so every change is undoable, marks
// the design unsaved and re-runs the pavement.
#include "edit_clock.h"
#include "undo_history.h"

#include "design/design.h"
#include "elements/element_shape.h"
#include "pipeline/pavement.h"
#include "report/bill_of_stones.h"
#include "report/verdict.h"
#include "map/surface_map.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <exception>
#include <string>
#include <vector>

namespace paver::studio {

using Clock = std::chrono::steady_clock;

struct Surface {
  std::filesystem::path path;
  std::shared_ptr<const SurfaceMap> map;  // null until one is open; shared with background runs
  std::vector<std::string> warnings;      // repairs made while loading
  StageTimings timings;                   // load and parameterize, for report.json
};

// The last final pavement, and the figures the report panel shows of it.
struct PavementResult {
  std::shared_ptr<const Pavement> pavement;
  std::uint64_t revision = 0;             // the document revision it was made for
  std::vector<double> neighbour_ratios;   // per element: nearest-neighbour distance / (r_i + r_j)
  std::vector<float> ratio_histogram;     // element counts per bin over [kHistogramMin, kHistogramMax]
  BillOfStones bill;                      // the report panel's bill of stones, made once per result
  Verdict verdict;                        // fit to use, or the problems with their figures (report.json's)
  // Where collision resolution took a stone away and none stands now: a ghost in both views.
  std::vector<RemovedElement> ghosts;
  double run_ms = 0;                      // the background run, wall time
  double latency_ms = -1;                 // design change to this result on screen; -1 until shown
};
inline constexpr double kHistogramMin = 0.8, kHistogramMax = 1.6;
inline constexpr int kHistogramBins = 32;

// The status line a finished run leaves: the verdict with its problems, then what the eye should
// find in the views (the bare spots and the stones removed, both marked there).
std::string run_status_text(const PavementResult& result);

struct Messages {
  std::string status;                     // the status line
  std::string error;                      // the error dialog's text; empty when none is open
  int error_count = 0;                    // errors reported so far (a script stops on a new one)
  bool error_kept_design = false;         // the error refused a design change (so the design is unchanged)
  bool error_is_input = false;            // the last error was the user's input (a script exits 2), not a bug (1)
  // The status line (and the error dialog) tell of a run's outcome: a newer run makes them stale.
  bool status_from_run = false;
  bool error_from_run = false;
};

struct Document {
  Surface surface;
  Design design;
  std::filesystem::path design_path;      // where the design was last loaded from or saved to
  bool dirty = false;                     // differs from the design last loaded or saved (or the default)
  std::string saved_json;                 // that design, as JSON text; empty = the default design
  UndoHistory history;

  std::uint64_t revision = 1;             // bumps whenever the design or the surface changes
  Clock::time_point changed_at = Clock::now();  // when it last did
  EditClock edit_clock;                   // from that change to its result on screen, pauses left out
  Clock::time_point run_due = Clock::now();     // debounce: the run for this revision starts then
  bool gesture_open = false;              // a drag is changing the design: one undo step for it all

  std::shared_ptr<const ShapeMesh> custom_shape;  // elements.custom_shape, loaded (shared with runs)
  std::optional<std::string> custom_shape_source;  // the path last tried

  PavementResult result;
  Messages messages;
};

// How long a dragged slider must rest before the pavement re-runs.
inline constexpr auto kDragDebounce = std::chrono::milliseconds(200);

// Makes `next` the design if it is valid (else reports why and changes nothing): an undo step
// (one per drag gesture), unsaved, a new revision. `dragging`: the change comes from a widget
// still held, so the run waits for it to rest.
bool change_design(Document& doc, const Design& next, bool dragging = false);
void end_gesture(Document& doc);  // the held widget was let go
bool undo(Document& doc);
bool redo(Document& doc);

// A new surface: a new revision (the design stays).
void set_surface(Document& doc, Surface surface);
// A finished run for the current revision becomes the result.
void set_result(Document& doc, std::shared_ptr<const Pavement> pavement, std::uint64_t revision, double run_ms);

// design.json in and out. Loading is an undoable change; both report errors instead of throwing.
bool open_design_file(Document& doc, const std::filesystem::path& path);
bool save_design_file(Document& doc, const std::filesystem::path& path);

// The design's custom shape when an element uses it, loaded once per path; null otherwise or
// when it cannot be loaded (reported).
const ShapeMesh* custom_shape(Document& doc);
// The same, shared: what the live runs get, so they do not read the file again.
std::shared_ptr<const ShapeMesh> shared_custom_shape(Document& doc);

// Before writing `path`: refuses (InputError) when it is the open surface, the custom shape or,
// unless `may_be_design` (Save), the design file; creates its folder.
void prepare_output(const Document& doc, const std::filesystem::path& path, bool may_be_design = false);

void report_status(Document& doc, std::string text);
// A run's outcome: its verdict, or why it failed. Made stale by the next run (mark_run_started).
// The largest spacing D the surface takes (the engine refuses one as large as its map is across,
// pattern/pattern.h): infinite with no surface open.
double largest_spacing(const Document& doc);

void report_run_status(Document& doc, std::string text);
void report_run_error(Document& doc, std::string text, bool input);
// A new run began: a previous run's status gives way to "solving", its error dialog closes.
void mark_run_started(Document& doc);
void report_error(Document& doc, std::string text, bool input = false);  // status line and the error dialog
void report_error(Document& doc, const std::exception& e);  // an InputError is the user's input

// Whether `path` is one of the designs bundled with Paver (assets/designs/ beside assets/surfaces/):
// Save refuses to overwrite one.
bool is_bundled_design(const std::filesystem::path& path);
// Where Save as starts: the design's own file, or for a bundled design a new name in the working
// folder (<name>_mine.json), since the bundled file itself is refused.
std::filesystem::path save_as_start(const std::filesystem::path& current);

}  // namespace paver::studio
