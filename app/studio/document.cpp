#include "document.h"

#include "field_names.h"

#include "element_editing.h"

#include "io/output_guard.h"
#include "io/design_io.h"
#include "elements/element_proximity.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "report/verdict.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace paver::studio {
namespace {

// The stones collision resolution removed whose place no stone took since (a refill, an edit):
// within half its diameter of a stone standing now, a removal is no hole.
std::vector<RemovedElement> uncovered_removals(const Pavement& p) {
  const std::vector<RemovedElement>& removed = p.resolution.removed_places;
  // All pairs: a handful of removals as a rule; past this many the ghosts are shown unfiltered.
  constexpr double kMostPairs = 5e7;
  if (double(removed.size()) * double(p.elements.size()) > kMostPairs) return removed;
  std::vector<RemovedElement> ghosts;
  for (const RemovedElement& gone : removed) {
    const double reach = 0.5 * gone.diameter;
    bool covered = false;
    for (std::size_t i = 0; i < p.elements.size() && !covered; ++i)
      covered = glm::length(p.elements.position[i] - gone.position) < reach;
    if (!covered) ghosts.push_back(gone);
  }
  return ghosts;
}

void new_revision(Document& doc, bool dragging) {
  ++doc.revision;
  doc.changed_at = Clock::now();
  doc.edit_clock.restart(doc.changed_at);
  doc.run_due = doc.changed_at + (dragging ? std::chrono::duration_cast<Clock::duration>(kDragDebounce)
                                           : Clock::duration::zero());
}

// Unsaved means different from what was last loaded or saved, so undoing back to it is saved again.
void refresh_dirty(Document& doc) {
  const std::string now = design_to_json(doc.design).dump();
  doc.dirty = now != (doc.saved_json.empty() ? design_to_json(Design{}).dump() : doc.saved_json);
}

}  // namespace

bool change_design(Document& doc, const Design& next, bool dragging) {
  try {
    validate_design(next, "this change");
  } catch (const InputError& e) {
    report_error(doc, in_studio_words(e.what()), true);  // the panel and field to fix, then the key
    doc.messages.error_kept_design = true;
    return false;
  }
  // Design has no operator==; its JSON form is complete and small.
  if (design_to_json(next) == design_to_json(doc.design)) return true;  // nothing to undo or re-run
  // Element ids name the elements of one pattern layout: edits carried over to another layout
  // would go to other elements. (A design that brings its own edits, a loaded file, keeps them.)
  Design changed = next;
  if (!changed.edits.empty() && design_to_json(changed)["edits"] == design_to_json(doc.design)["edits"] &&
      changes_pattern_layout(doc.design, changed)) {
    changed.edits = {};
    report_status(doc, "element edits cleared: they named elements of the pattern before this change (undo brings "
                       "them back)");
  }
  if (!doc.gesture_open) doc.history.record(doc.design);
  doc.gesture_open = dragging;
  doc.design = std::move(changed);
  refresh_dirty(doc);
  new_revision(doc, dragging);
  return true;
}

void end_gesture(Document& doc) { doc.gesture_open = false; }

namespace {
// The design the history gave back (none: nothing to undo or redo) becomes the document's.
bool take_from_history(Document& doc, std::optional<Design> design, const char* status) {
  if (!design) return false;
  doc.design = std::move(*design);
  refresh_dirty(doc);
  new_revision(doc, false);
  report_status(doc, status);
  return true;
}
}  // namespace

bool undo(Document& doc) {
  end_gesture(doc);
  return take_from_history(doc, doc.history.undo(doc.design), "undone");
}

bool redo(Document& doc) {
  end_gesture(doc);
  return take_from_history(doc, doc.history.redo(doc.design), "redone");
}

void set_surface(Document& doc, Surface surface) {
  doc.surface = std::move(surface);
  doc.result = {};
  new_revision(doc, false);
}

void set_result(Document& doc, std::shared_ptr<const Pavement> pavement, std::uint64_t revision, double run_ms) {
  PavementResult& r = doc.result;
  r = {};
  r.revision = revision;
  r.run_ms = run_ms;
  r.neighbour_ratios = nearest_neighbor_ratios(pavement->elements, pavement->design.elements.gap);
  r.ratio_histogram.assign(kHistogramBins, 0.0f);
  for (const double ratio : r.neighbour_ratios) {
    if (!std::isfinite(ratio)) continue;
    const double t = (ratio - kHistogramMin) / (kHistogramMax - kHistogramMin);
    r.ratio_histogram[std::clamp(int(t * kHistogramBins), 0, kHistogramBins - 1)] += 1;
  }
  r.bill = bill_of_stones(pavement->elements, pavement->design.units);
  r.verdict = judge_pavement(pavement->after);
  r.ghosts = uncovered_removals(*pavement);
  r.pavement = std::move(pavement);
}

double largest_spacing(const Document& doc) {
  if (!doc.surface.map) return std::numeric_limits<double>::infinity();
  const SurfaceMap& map = map_for_topology(*doc.surface.map, doc.design.pattern.topology);
  const glm::dvec2 extent = map.uv_max - map.uv_min;
  return std::max(extent.x, extent.y) * doc.design.placement.scale;
}

std::string run_status_text(const PavementResult& r) {
  if (!r.pavement) return {};
  const Pavement& p = *r.pavement;
  std::string text = r.verdict.ok ? "ok: " : "NOT OK: ";
  for (const std::string& problem : r.verdict.problems) text += problem + "; ";
  text += count_text(long(p.elements.size()), "element", "elements") + ", " +
          count_text(p.after.contact_violations, "contact violation", "contact violations");
  // The views mark the bare spots; for pave the verdict names them (count, the widest, where), for
  // other patterns this line does.
  const EdgeQuality& edges = p.after.edges;
  const bool spots = edges.measured && edges.bare_spots > 0;
  if (spots && !has_bare_spots(p.after)) {
    char size[32];
    std::snprintf(size, sizeof size, "%.3g", edges.spot_stone);
    text += "; " + count_text(edges.bare_spots, "bare spot", "bare spots") + " where a " +
            (p.grade.ladder.empty() ? std::string(size) + " " + std::string(enum_name(p.design.units)) + " stone"
                                    : std::string("graded stone")) +
            " still fits";
  }
  if (!r.ghosts.empty())
    text += "; " + count_text(long(r.ghosts.size()), "stone", "stones") + " removed where they still collided";
  if (spots || !r.ghosts.empty()) text += " (marked in the views)";
  text += "; " + count_text(p.solve.iterations, "iteration", "iterations") + " (" +
          std::string(enum_name(p.solve.reason)) + ")";
  // Said where a script's log and the eye see it, not only in the Elements panel.
  if (p.deletions_missed > 0)
    text += "; " + count_text(p.deletions_missed, "deletion", "deletions") +
            " found no element (refilled stones an edit moved away): re-delete them";
  return text;
}

bool open_design_file(Document& doc, const std::filesystem::path& path) {
  try {
    std::vector<std::string> notes;
    const Design loaded = load_design(path, &notes);
    end_gesture(doc);
    if (!change_design(doc, loaded)) return false;
    doc.design_path = path;
    doc.saved_json = design_to_json(doc.design).dump();
    refresh_dirty(doc);
    std::string status = "loaded design " + path.string();
    for (const std::string& note : notes) status += "; note: " + note;
    report_status(doc, status);
    return true;
  } catch (const std::exception& e) {
    report_error(doc, e);
    return false;
  }
}

void prepare_output(const Document& doc, const std::filesystem::path& path, bool may_be_design) {
  std::vector<std::filesystem::path> inputs = {doc.surface.path, doc.design.elements.custom_shape};
  if (!may_be_design) inputs.push_back(doc.design_path);
  refuse_overwriting_inputs(inputs, {path});
  if (path.has_parent_path()) make_output_folder(path.parent_path());
}

bool save_design_file(Document& doc, const std::filesystem::path& path) {
  try {
    if (is_bundled_design(path))
      throw InputError(path.string() + " is a design bundled with Paver: save yours under another name (File, design "
                                       "file, Save)");
    prepare_output(doc, path, true);
    save_design(path, doc.design);
    doc.design_path = path;
    doc.saved_json = design_to_json(doc.design).dump();
    refresh_dirty(doc);
    report_status(doc, "saved design " + path.string());
    return true;
  } catch (const std::exception& e) {
    report_error(doc, e);
    return false;
  }
}

std::shared_ptr<const ShapeMesh> shared_custom_shape(Document& doc) {
  const std::string& path = doc.design.elements.custom_shape;
  if (!uses_custom_shape(doc.design.elements)) return nullptr;
  if (doc.custom_shape_source == path) return doc.custom_shape;
  doc.custom_shape.reset();
  doc.custom_shape_source = path;  // tried once per path: a bad file is reported once
  try {
    if (path.empty()) throw InputError("an element uses the custom shape: set its OBJ file in the elements panel");
    doc.custom_shape = std::make_shared<const ShapeMesh>(load_custom_shape(path));
  } catch (const std::exception& e) {
    report_error(doc, e);
  }
  return doc.custom_shape;
}

const ShapeMesh* custom_shape(Document& doc) { return shared_custom_shape(doc).get(); }

void report_status(Document& doc, std::string text) {
  doc.messages.status = std::move(text);
  doc.messages.status_from_run = false;
}

void report_run_status(Document& doc, std::string text) {
  report_status(doc, std::move(text));
  doc.messages.status_from_run = true;
}

void report_run_error(Document& doc, std::string text, bool input) {
  report_error(doc, std::move(text), input);
  doc.messages.status_from_run = doc.messages.error_from_run = true;
}

void mark_run_started(Document& doc) {
  // The previous run's error no longer applies to the design now being solved.
  if (doc.messages.error_from_run) doc.messages.error.clear();
  doc.messages.error_from_run = false;
  if (doc.messages.status_from_run)
    report_status(doc, "solving the changed design; the last result stays on screen until the new one is done");
}

void report_error(Document& doc, std::string text, bool input) {
  doc.messages.status = "error: " + text;
  doc.messages.status_from_run = doc.messages.error_from_run = false;
  doc.messages.error = std::move(text);
  doc.messages.error_kept_design = false;
  doc.messages.error_is_input = input;
  ++doc.messages.error_count;
}

void report_error(Document& doc, const std::exception& e) {
  report_error(doc, e.what(), dynamic_cast<const InputError*>(&e) != nullptr);
}

bool is_bundled_design(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path full = std::filesystem::weakly_canonical(path, error);
  if (error) return false;
  const std::filesystem::path folder = full.parent_path();
  return folder.filename() == "designs" && folder.parent_path().filename() == "assets" &&
         std::filesystem::is_directory(folder.parent_path() / "surfaces", error);
}

std::filesystem::path save_as_start(const std::filesystem::path& current) {
  if (!is_bundled_design(current)) return current;
  std::error_code error;
  return std::filesystem::current_path(error) / (current.stem().string() + "_mine.json");
}

}  // namespace paver::studio
