#include "script_runner.h"

#include "design_edits.h"
#include "design_keys.h"
#include "element_editing.h"
#include "panels/panels.h"

#include "core/input_error.h"
#include "core/printable.h"

#include <cstdio>
#include <initializer_list>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace paver::studio {
namespace {

using Kind = ScriptCommand::Kind;
// Long enough for a dense surface's map on a slow machine; a hang still ends the session.
constexpr auto kTimeout = std::chrono::minutes(10);

bool needs_final_pavement(Kind kind) {
  switch (kind) {
    case Kind::Optimize: case Kind::Export: case Kind::Cut: case Kind::Select: case Kind::Pin: case Kind::Unpin:
    case Kind::Drag: case Kind::Delete: case Kind::Add: case Kind::Brush: case Kind::SelectBox:
    case Kind::Click: case Kind::MouseDrag: case Kind::MouseDrag3d:
      return true;
    default:
      return false;
  }
}

// " 1.5 -2 ..." for the log, each number as %g.
std::string numbers_text(std::initializer_list<double> numbers) {
  std::string text;
  for (const double x : numbers) {
    char number[32];
    std::snprintf(number, sizeof number, " %g", x);
    text += number;
  }
  return text;
}

std::string describe(const ScriptCommand& c) {
  std::string text(command_name(c.kind));
  const std::string modifier = c.shift ? " shift" : c.ctrl ? " ctrl" : "";
  switch (c.kind) {
    case Kind::Spacing: return text + numbers_text({c.number});
    case Kind::Wait: return text + " " + std::to_string(c.frames);
    case Kind::Orbit: return text + numbers_text({c.number, double(c.frames)});
    case Kind::Brush: return text + numbers_text({c.u, c.v, c.radius, c.strength});
    case Kind::Add: return text + numbers_text({c.u, c.v});
    case Kind::SelectBox: return text + numbers_text({c.u, c.v, c.u1, c.v1});
    case Kind::Click: return text + numbers_text({c.u, c.v}) + modifier;
    case Kind::MouseDrag: return text + numbers_text({c.u, c.v, c.u1, c.v1}) + modifier;
    case Kind::Drag:
    case Kind::MouseDrag3d:
      text.append(1, ' ').append(std::to_string(c.id));  // (no " " + string: GCC 12 -Wrestrict)
      return text + numbers_text({c.u, c.v});
    case Kind::Cut: return text + numbers_text({c.number}) + " " + c.text;
    case Kind::Type:
      return text + " \"" + c.text + "\" \"" + c.value + "\" " +
             (c.type_end == TypeEnd::Enter ? "enter" : c.type_end == TypeEnd::Tab ? "tab" : "away");
    default: break;
  }
  if (c.id == ScriptCommand::kSelection) return text + " selection";
  if (c.id >= 0) return text + " " + std::to_string(c.id);
  if (!c.text.empty()) text += " " + c.text;
  if (!c.value.empty()) text += " " + c.value;
  return text;
}

// The element commands, on the pavement on screen (ready() waited for it to be final).
void edit_element(Studio& s, const ScriptCommand& c) {
  Document& doc = s.doc;
  const Pavement& pavement = *doc.result.pavement;
  if (c.id == ScriptCommand::kSelection) {  // pin, unpin or delete what is selected, as the keys do
    if (selection(s.ui).empty()) throw InputError(describe(c) + ": nothing is selected");
    if (c.kind == Kind::Delete)
      delete_selected(s);
    else
      pin_selected(s, c.kind == Kind::Pin);
    return;
  }
  switch (c.kind) {
    case Kind::Select: select_element(s, c.id); break;
    case Kind::SelectBox:
      select_box(s, glm::dvec2(c.u, c.v), glm::dvec2(c.u1, c.v1));
      std::printf("selected %zu\n", selection(s.ui).size());  // the session's log: what the box took
      break;
    case Kind::Pin: change_design(doc, with_pinned(doc.design, pavement, c.id, true)); select_element(s, c.id); break;
    case Kind::Unpin: change_design(doc, with_pinned(doc.design, pavement, c.id, false)); break;
    case Kind::Drag: {
      const double spacing = pavement.design.pattern.spacing;
      change_design(doc, with_dragged(doc.design, pavement, c.id, glm::dvec2(c.u, c.v) * spacing));
      select_element(s, c.id);
      break;
    }
    case Kind::Delete:
      change_design(doc, without_element(doc.design, pavement, c.id));
      if (s.ui.selected_element == c.id) clear_selection(s.ui);
      break;
    case Kind::Add: {
      int id = -1;
      change_design(doc, with_added_element(doc.design, pavement, glm::dvec2(c.u, c.v), &id));
      clear_selection(s.ui);
      s.ui.selected_element = id;
      report_status(doc, "added element " + std::to_string(id));
      break;
    }
    default: break;
  }
}

}  // namespace

ScriptRunner::ScriptRunner(std::vector<ScriptCommand> commands, std::string source)
    : commands_(std::move(commands)), source_(std::move(source)) {}

bool ScriptRunner::ready(const Studio& s, const ScriptCommand& c) const {
  if (!needs_final_pavement(c.kind)) return true;
  // The pavement for the current design, final and on screen (its latency measured).
  return result_is_final(s) && s.doc.result.latency_ms >= 0;
}

void ScriptRunner::act(Studio& s, const ScriptCommand& c) {
  Document& doc = s.doc;
  switch (c.kind) {
    case Kind::Open: open_surface(s, c.text); break;
    case Kind::CutAxis: set_cut_axis(s, *enum_from_name<CutAxis>(c.text)); break;
    case Kind::Design:
      if (open_design_file(doc, c.text)) s.ui.design_path = c.text;
      break;
    case Kind::Pattern: change_design(doc, with_tessellation(doc.design, *enum_from_name<Tessellation>(c.text))); break;
    case Kind::Spacing: {
      Design d = doc.design;
      d.pattern.spacing = c.number;
      change_design(doc, d);
      break;
    }
    case Kind::Set: change_design(doc, set_design_key(doc.design, c.text, c.value)); break;
    case Kind::Optimize: break;  // ready() waited for it
    case Kind::Undo:
      if (!undo(doc)) throw InputError("undo: there is nothing to undo");
      break;
    case Kind::Redo:
      if (!redo(doc)) throw InputError("redo: there is nothing to redo");
      break;
    case Kind::Save:  // as Save as: never onto a bundled design or an input (it fails the script)
      save_design_as(s, c.text);
      break;
    case Kind::Export: export_outputs(s, c.text); break;
    case Kind::Cut: cut_metal(s, c.text, c.number); break;
    case Kind::Screenshot: s.ui.screenshot = c.text; break;
    case Kind::View3d:
      if (!s.views.large_3d) swap_views(s);
      break;
    case Kind::View2d:
      if (s.views.large_3d) swap_views(s);
      break;
    case Kind::Panel:
      s.ui.select_panel = c.text;
      frames_left_ = 2;  // ImGui sizes a table's fitted columns on the frame after its first
      break;
    case Kind::Wait: frames_left_ = c.frames; break;
    case Kind::Orbit:
      orbit_step_ = float(c.number * std::numbers::pi / 180.0 / c.frames);
      frames_left_ = c.frames;
      s.orbiting_frames.emplace();  // the first turn is drawn this frame
      break;
    case Kind::Quit: s.quit = true; break;
    case Kind::Select:
    case Kind::Pin:
    case Kind::Unpin:
    case Kind::Drag:
    case Kind::Delete:
    case Kind::Add:
    case Kind::SelectBox: edit_element(s, c); break;
    case Kind::Brush: paint_guidance(s, glm::dvec2(c.u, c.v), c.radius, c.strength); break;
    case Kind::Browse: {
      const BrowsePurpose purpose = *browse_purpose_from_name(c.text);
      start_browsing(s.ui.browser, purpose, browse_start(s, purpose));
      break;
    }
    case Kind::Click:
    case Kind::MouseDrag: {
      const glm::vec2 from = map_to_window(s, glm::dvec2(c.u, c.v));
      const std::vector<InputFrame> frames = c.kind == Kind::Click
                                                 ? click_frames(from, c.shift, c.ctrl)
                                                 : drag_frames(from, map_to_window(s, glm::dvec2(c.u1, c.v1)), c.shift, c.ctrl);
      s.input_queue.insert(s.input_queue.end(), frames.begin(), frames.end());
      frames_left_ = 3;  // and a few frames for what it did to take effect
      break;
    }
    case Kind::MouseDrag3d: {
      const auto [from, to] = element_drag_3d(s, c.id, glm::dvec2(c.u, c.v));
      const std::vector<InputFrame> frames = drag_frames(from, to, false, false);
      s.input_queue.insert(s.input_queue.end(), frames.begin(), frames.end());
      frames_left_ = 3;
      break;
    }
    case Kind::Type: {
      const std::optional<glm::vec2> at = field_centre(c.text);
      if (!at) throw InputError("type: no field '" + c.text + "' on screen: show its panel first (e.g. panel elements)");
      // Away: the status bar's right end, where a click takes nothing.
      const ImVec2 size = ImGui::GetMainViewport()->WorkSize;
      const std::vector<InputFrame> frames = typing_frames(*at, c.value, c.type_end, glm::vec2(size.x - 8, size.y - 6));
      s.input_queue.insert(s.input_queue.end(), frames.begin(), frames.end());
      frames_left_ = 3;
      typing_since_frame_ = ImGui::GetFrameCount();
      break;
    }
    case Kind::Key: {
      const std::vector<InputFrame> frames = key_frames(c.key, map_to_window(s, glm::dvec2(0), false), c.shift);
      s.input_queue.insert(s.input_queue.end(), frames.begin(), frames.end());
      frames_left_ = 3;
      break;
    }
    case Kind::Colour:
      s.views.colour_mode = c.text == "type" ? render::ColourMode::ElementType : render::ColourMode::NeighbourRatio;
      break;
  }
}

bool ScriptRunner::settled(Studio& s, const ScriptCommand& c) {
  switch (c.kind) {
    case Kind::Open: return !s.loader.busy() && s.doc.surface.path == std::filesystem::path(c.text);
    case Kind::CutAxis: return !s.loader.busy();
    case Kind::Screenshot: return !s.ui.screenshot;  // after_present wrote it
    case Kind::Wait:
    case Kind::Panel: return frames_left_-- <= 0;
    case Kind::Orbit:
      if (frames_left_-- > 0) {
        s.views.camera.yaw += orbit_step_;  // drawn this frame
        return false;
      }
      std::printf("frames_while_orbiting %s\n", describe(frame_pace(s.orbiting_frames->frame_ms)).c_str());
      std::fflush(stdout);
      s.orbiting_frames.reset();
      return true;
    case Kind::Type:
      if (!s.input_queue.empty() || frames_left_-- > 0) return false;
      // A click beside the box (on the label) types into nothing: say so, not go on as if it took.
      if (!field_was_active_since(c.text, typing_since_frame_))
        throw std::runtime_error("type: the click on field '" + c.text + "' did not give it the keyboard");
      return true;
    case Kind::Click:
    case Kind::MouseDrag:
    case Kind::MouseDrag3d:
    case Kind::Key: return s.input_queue.empty() && frames_left_-- <= 0;
    case Kind::Cut: return !s.cutter.busy() && !s.cutter.has_outcome();  // and its outcome reported
    default: return true;
  }
}

void ScriptRunner::fail(Studio& s, const std::string& message, int code) {
  std::fprintf(stderr, "paver-studio: error: %s\n", message.c_str());
  exit_code_ = code;
  finished_ = true;
  s.quit = true;
}

void ScriptRunner::frame(Studio& s) {
  if (finished_) return;
  const Messages& messages = s.doc.messages;
  // The session's log says what each command did, every status line the designer would have seen.
  if (messages.status != status_said_) {
    status_said_ = messages.status;
    std::printf("status: %s\n", printable_cut(status_said_, kMaxMessageBytes).c_str());
    std::fflush(stdout);
  }
  const std::string where =
      next_ < commands_.size() ? source_ + ":" + std::to_string(commands_[next_].line) + ": " : source_ + ": ";
  if (messages.error_count > errors_seen_) return fail(s, where + messages.error, messages.error_is_input ? 2 : 1);
  if (next_ >= commands_.size()) {  // the end of the script is a quit
    finished_ = true;
    s.quit = true;
    return;
  }
  const ScriptCommand& c = commands_[next_];
  const auto now = std::chrono::steady_clock::now();
  if (since_ == std::chrono::steady_clock::time_point{}) since_ = now;
  if (now - since_ > kTimeout)
    return fail(s, where + std::string(command_name(c.kind)) + " did not finish in 10 minutes", 1);
  // Nothing would ever pave: it waited the whole timeout.
  if (needs_final_pavement(c.kind) && !s.doc.surface.map && !s.loader.busy())
    return fail(s, where + std::string(command_name(c.kind)) + " needs a surface: put an 'open FILE' line before it", 2);
  try {
    if (phase_ == Phase::Ready) {
      if (!ready(s, c)) return;
      std::printf("script %d: %s\n", c.line, describe(c).c_str());
      std::fflush(stdout);
      act(s, c);
      phase_ = Phase::Settling;
      if (s.doc.messages.error_count > errors_seen_) return;  // failed: reported next frame
    }
    if (!settled(s, c)) return;
  } catch (const InputError& e) {
    return fail(s, where + e.what(), 2);
  } catch (const std::exception& e) {
    return fail(s, where + e.what(), 1);
  }
  if (c.kind == Kind::Quit) finished_ = true;
  phase_ = Phase::Ready;
  since_ = {};
  ++next_;
}

}  // namespace paver::studio
