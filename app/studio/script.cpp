#include "script.h"

#include "map/surface_charts.h"

#include "core/input_error.h"
#include "file_browser.h"
#include "synthetic_input.h"
#include "pattern/unit_cell.h"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <cmath>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <utility>

namespace paver::studio {
namespace {

using Kind = ScriptCommand::Kind;

constexpr std::pair<std::string_view, Kind> kCommands[] = {
    {"open", Kind::Open},       {"cut_axis", Kind::CutAxis}, {"design", Kind::Design}, {"pattern", Kind::Pattern},
    {"spacing", Kind::Spacing}, {"set", Kind::Set},       {"optimize", Kind::Optimize},
    {"undo", Kind::Undo},       {"redo", Kind::Redo},     {"export", Kind::Export}, {"cut", Kind::Cut},
    {"screenshot", Kind::Screenshot}, {"view3d", Kind::View3d}, {"view2d", Kind::View2d},
    {"panel", Kind::Panel},     {"wait", Kind::Wait},     {"quit", Kind::Quit},
    {"select", Kind::Select},   {"pin", Kind::Pin},       {"unpin", Kind::Unpin},   {"drag", Kind::Drag},
    {"delete", Kind::Delete},   {"add", Kind::Add},       {"brush", Kind::Brush},
    {"colour", Kind::Colour}, {"save", Kind::Save}, {"select_box", Kind::SelectBox}, {"browse", Kind::Browse},
    {"click", Kind::Click}, {"mouse_drag", Kind::MouseDrag}, {"key", Kind::Key}, {"mouse_drag3d", Kind::MouseDrag3d},
    {"orbit", Kind::Orbit}};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// A '#' at the start or after a blank starts a comment; one inside a word (a path) does not.
std::string_view strip_comment(std::string_view line) {
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '#' && (i == 0 || is_space(line[i - 1]))) return line.substr(0, i);
  return line;
}

// Reads all of `text` as one number of type T; false when it is not exactly that.
template <class T>
bool parse_number(std::string_view text, T& out) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec != std::errc() || ptr != text.data() + text.size()) return false;
  if constexpr (std::is_floating_point_v<T>) return std::isfinite(out);
  return true;
}

// Splits off the first word: {word, rest (trimmed)}.
std::pair<std::string_view, std::string_view> first_word(std::string_view s) {
  std::size_t end = 0;
  while (end < s.size() && !is_space(s[end])) ++end;
  return {s.substr(0, end), trim(s.substr(end))};
}

}  // namespace

std::string_view command_name(Kind kind) {
  for (const auto& [name, k] : kCommands)
    if (k == kind) return name;
  return "?";
}

bool parse_script_line(std::string_view line, int line_number, const std::string& source, ScriptCommand& out) {
  const std::string_view content = trim(strip_comment(line));
  if (content.empty()) return false;
  const std::string where = source + ":" + std::to_string(line_number) + ": ";
  const auto [word, rest] = first_word(content);
  const std::string name(word);

  const Kind* kind = nullptr;
  for (const auto& [command, k] : kCommands)
    if (command == word) kind = &k;
  if (!kind) {
    std::string known;
    for (const auto& [command, k] : kCommands) known += (known.empty() ? "" : ", ") + std::string(command);
    throw InputError(where + "unknown command '" + name + "'; commands are " + known);
  }
  out = ScriptCommand{};
  out.kind = *kind;
  out.line = line_number;

  const auto need_argument = [&](const char* what) {
    if (rest.empty()) throw InputError(where + name + " needs " + what);
  };
  // A command that takes one name from a list: kept as written, or refused naming the list.
  const auto need_choice = [&](bool known, const char* choices) {
    need_argument(choices);
    if (!known) throw InputError(where + name + " '" + std::string(rest) + "': use " + choices);
    out.text = std::string(rest);
  };
  switch (*kind) {
    case Kind::Open:
    case Kind::Design:
    case Kind::Save:
    case Kind::Export:
    case Kind::Screenshot:
      need_argument(*kind == Kind::Export ? "a folder" : "a file path");
      out.text = std::string(rest);  // the rest of the line, so paths may hold blanks
      if (*kind == Kind::Screenshot && !out.text.ends_with(".png"))
        throw InputError(where + "screenshot writes PNG: give a path ending in .png");
      break;
    case Kind::Pattern: need_choice(tessellation_from_name(rest).has_value(), "tri, grid or hex"); break;
    case Kind::CutAxis: need_choice(cut_axis_from_name(rest).has_value(), "auto, x, y or z"); break;
    case Kind::Click:
    case Kind::MouseDrag: {
      const bool drag = *kind == Kind::MouseDrag;
      need_argument(drag ? "two map points U0 V0 U1 V1 (and shift or ctrl), e.g. mouse_drag 0 0 0.5 0"
                         : "a map point U V (and shift or ctrl), e.g. click 0 0");
      std::vector<std::string_view> words;
      for (std::string_view left = rest; !left.empty();) {
        const auto [word, after] = first_word(left);
        words.push_back(word);
        left = after;
      }
      const std::size_t numbers = drag ? 4 : 2;
      const bool modifier = words.size() == numbers + 1;
      if (modifier) {
        out.shift = words.back() == "shift";
        out.ctrl = words.back() == "ctrl";
      }
      double* targets[] = {&out.u, &out.v, &out.u1, &out.v1};
      bool ok = (words.size() == numbers || (modifier && (out.shift || out.ctrl)));
      for (std::size_t i = 0; ok && i < numbers; ++i) ok = parse_number(words[i], *targets[i]);
      if (!ok)
        throw InputError(where + name + " '" + std::string(rest) + "': give " + (drag ? "four" : "two") +
                         " numbers (map points), then optionally shift or ctrl");
      break;
    }
    case Kind::MouseDrag3d: {
      need_argument("an element id and the map point to drop it at, e.g. mouse_drag3d 42 0.5 0");
      const auto [id, after_id] = first_word(rest);
      const auto [u, v] = first_word(after_id);
      if (!parse_number(id, out.id) || out.id < 0 || !parse_number(u, out.u) || !parse_number(v, out.v))
        throw InputError(where + "mouse_drag3d '" + std::string(rest) + "': give an element id and a map point U V");
      break;
    }
    case Kind::Key:
      need_choice(key_from_name(rest).has_value(), "E, P, I, V, L, C, R, N, Delete, Escape or Space");
      out.key = *key_from_name(rest);
      break;
    case Kind::Browse: need_choice(browse_purpose_from_name(rest).has_value(), "surface, design, save, export or shape"); break;
    case Kind::Colour: need_choice(rest == "ratio" || rest == "type", "ratio or type"); break;
    case Kind::Panel: {
      need_argument("a panel name: file, pattern, elements, optimize, report or help");
      if (std::find(std::begin(kPanelNames), std::end(kPanelNames), rest) == std::end(kPanelNames))
        throw InputError(where + "panel '" + std::string(rest) + "': use file, pattern, elements, optimize, report or help");
      out.text = std::string(rest);
      break;
    }
    case Kind::Spacing: {
      need_argument("the edge length D (0 = derive it from the surface)");
      const auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), out.number);
      if (ec != std::errc() || ptr != rest.data() + rest.size() || !std::isfinite(out.number) || out.number < 0)
        throw InputError(where + "spacing '" + std::string(rest) + "': must be a finite number >= 0");
      break;
    }
    case Kind::Set: {
      need_argument("a key and a value, e.g. set solver.dt 0.25");
      const auto [key, value] = first_word(rest);
      if (value.empty()) throw InputError(where + "set " + std::string(key) + " needs a value");
      out.text = std::string(key);
      out.value = std::string(value);
      break;
    }
    case Kind::Cut: {
      need_argument("the metal's thickness and a folder, e.g. cut 1 out/metal");
      const auto [thickness, folder] = first_word(rest);
      const auto [ptr, ec] = std::from_chars(thickness.data(), thickness.data() + thickness.size(), out.number);
      if (ec != std::errc() || ptr != thickness.data() + thickness.size() || !std::isfinite(out.number) ||
          !(out.number > 0))
        throw InputError(where + "cut '" + std::string(thickness) + "': the thickness must be a number above 0");
      if (folder.empty()) throw InputError(where + "cut " + std::string(thickness) + " needs a folder");
      out.text = std::string(folder);
      break;
    }
    case Kind::Orbit: {
      need_argument("degrees and a number of frames, e.g. orbit 90 60");
      const auto [degrees, frames] = first_word(rest);
      if (!parse_number(degrees, out.number) || !std::isfinite(out.number) || !parse_number(frames, out.frames) ||
          out.frames < 1)
        throw InputError(where + "orbit '" + std::string(rest) + "': give degrees and a whole number of frames >= 1");
      break;
    }
    case Kind::Wait: {
      need_argument("a number of frames");
      const auto [ptr, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), out.frames);
      if (ec != std::errc() || ptr != rest.data() + rest.size() || out.frames < 0)
        throw InputError(where + "wait '" + std::string(rest) + "': must be a whole number of frames >= 0");
      break;
    }
    case Kind::Select:
    case Kind::Pin:
    case Kind::Unpin:
    case Kind::Delete:
    case Kind::Drag: {
      const bool drag = *kind == Kind::Drag;
      need_argument(drag ? "an element id and a move in spacings, e.g. drag 42 0.4 0" : "an element id (placements.csv's id)");
      const auto [id, move] = first_word(rest);
      if (id == "selection" && move.empty() && (*kind == Kind::Pin || *kind == Kind::Unpin || *kind == Kind::Delete)) {
        out.id = ScriptCommand::kSelection;
        break;
      }
      if (!parse_number(id, out.id) || out.id < 0)
        throw InputError(where + name + " '" + std::string(id) + "': an element id is a whole number >= 0");
      if (!drag && !move.empty()) throw InputError(where + name + " takes one element id, got '" + std::string(rest) + "'");
      if (drag) {
        const auto [du, dv] = first_word(move);
        if (!parse_number(du, out.u) || !parse_number(dv, out.v))
          throw InputError(where + "drag " + std::string(id) + " needs the move as two numbers of spacings D, e.g. drag " +
                           std::string(id) + " 0.4 0");
      }
      break;
    }
    case Kind::SelectBox: {
      need_argument("two map corners U0 V0 U1 V1, e.g. select_box -1 -1 1 1");
      const auto [u0, after_u0] = first_word(rest);
      const auto [v0, after_v0] = first_word(after_u0);
      const auto [u1, v1] = first_word(after_v0);
      if (!parse_number(u0, out.u) || !parse_number(v0, out.v) || !parse_number(u1, out.u1) || !parse_number(v1, out.v1))
        throw InputError(where + "select_box '" + std::string(rest) + "': give two map corners as four numbers U0 V0 U1 V1");
      break;
    }
    case Kind::Add: {
      need_argument("a map point U V (as placements.csv's u and v), e.g. add 1.5 -2");
      const auto [u, v] = first_word(rest);
      if (!parse_number(u, out.u) || !parse_number(v, out.v))
        throw InputError(where + "add '" + std::string(rest) + "': give the map point as two numbers U V");
      break;
    }
    case Kind::Brush: {
      need_argument("a map point, a radius in spacings and a strength, e.g. brush 0 0 4 0.3");
      const auto [u, after_u] = first_word(rest);
      const auto [v, after_v] = first_word(after_u);
      const auto [radius, strength] = first_word(after_v);
      if (!parse_number(u, out.u) || !parse_number(v, out.v) || !parse_number(radius, out.radius) ||
          !parse_number(strength, out.strength) || !(out.radius > 0) || out.strength < -0.5 || out.strength > 1)
        throw InputError(where + "brush '" + std::string(rest) +
                         "': give U V RADIUS STRENGTH, the radius > 0 spacings, the strength in [-0.5, 1]");
      break;
    }
    default:
      if (!rest.empty()) throw InputError(where + name + " takes no argument, got '" + std::string(rest) + "'");
  }
  return true;
}

std::vector<ScriptCommand> parse_script(std::string_view text, const std::string& source) {
  std::vector<ScriptCommand> commands;
  int line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ScriptCommand command;
    if (parse_script_line(line, ++line_number, source, command)) commands.push_back(std::move(command));
  }
  return commands;
}

std::vector<ScriptCommand> load_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the script for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_script(text.str(), path);
}

}  // namespace paver::studio
