#include "script.h"
#include "design/design_keys.h"

#include "map/surface_charts.h"

#include "core/input_error.h"
#include "core/regular_file.h"
#include "file_browser.h"
#include "synthetic_input.h"
#include "pattern/unit_cell.h"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <cmath>
#include <cstdint>
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
    {"orbit", Kind::Orbit}, {"type", Kind::Type}};

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

namespace {

// One line's command being read: its words, where it stands (for messages) and what it gives.
struct LineParser {
  std::string where;      // "s.txt:4: "
  std::string name;       // the command's word
  std::string_view rest;  // after it, trimmed
  ScriptCommand& out;

  [[noreturn]] void refuse(const std::string& what) const { throw InputError(where + what); }
  void need_argument(std::string_view what) const {
    if (rest.empty()) refuse(name + " needs " + std::string(what));
  }
  // A command that takes one name from a list: kept as written, or refused naming the list.
  void need_choice(bool known, std::string_view choices) const {
    need_argument(choices);
    if (!known) refuse(name + " '" + std::string(rest) + "': use " + std::string(choices));
    out.text = std::string(rest);
  }
  std::vector<std::string_view> words() const {
    std::vector<std::string_view> all;
    for (std::string_view left = rest; !left.empty();) {
      const auto [word, after] = first_word(left);
      all.push_back(word);
      left = after;
    }
    return all;
  }
};

// open, design, save, export, screenshot: the rest of the line, so paths may hold blanks.
void parse_path(const LineParser& p) {
  p.need_argument(p.out.kind == Kind::Export ? "a folder" : "a file path");
  p.out.text = std::string(p.rest);
  if (p.out.kind == Kind::Screenshot && !p.out.text.ends_with(".png"))
    p.refuse("screenshot writes PNG: give a path ending in .png");
}

// click U V [shift|ctrl], mouse_drag U0 V0 U1 V1 [shift|ctrl], mouse_drag3d ID U V.
void parse_pointer(const LineParser& p) {
  ScriptCommand& out = p.out;
  if (out.kind == Kind::MouseDrag3d) {
    p.need_argument("an element id and the map point to drop it at, e.g. mouse_drag3d 42 0.5 0");
    const auto [id, after_id] = first_word(p.rest);
    const auto [u, v] = first_word(after_id);
    if (!parse_number(id, out.id) || out.id < 0 || !parse_number(u, out.u) || !parse_number(v, out.v))
      p.refuse("mouse_drag3d '" + std::string(p.rest) + "': give an element id and a map point U V");
    return;
  }
  const bool drag = out.kind == Kind::MouseDrag;
  p.need_argument(drag ? "two map points U0 V0 U1 V1 (and shift or ctrl), e.g. mouse_drag 0 0 0.5 0"
                       : "a map point U V (and shift or ctrl), e.g. click 0 0");
  const std::vector<std::string_view> words = p.words();
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
    p.refuse(p.name + " '" + std::string(p.rest) + "': give " + (drag ? "four" : "two") +
             " numbers (map points), then optionally shift or ctrl");
}

// The commands that take one name from a list.
void parse_choice(const LineParser& p) {
  switch (p.out.kind) {
    case Kind::Pattern:
      p.need_choice(enum_from_name<Tessellation>(p.rest).has_value(), enum_choices_words<Tessellation>());
      break;
    case Kind::CutAxis: p.need_choice(enum_from_name<CutAxis>(p.rest).has_value(), enum_choices_words<CutAxis>()); break;
    case Kind::Key: {
      // "Shift+P": the key with Shift held, as a hand presses it.
      const bool shift = p.rest.rfind("Shift+", 0) == 0;
      const std::string_view name = std::string_view(p.rest).substr(shift ? 6 : 0);
      p.need_choice(key_from_name(name).has_value(), "E, P, B, I, M, V, L, C, R, N, Delete, Escape or Space, each also as Shift+P");
      p.out.key = *key_from_name(name);
      p.out.shift = shift;
      break;
    }
    case Kind::Browse:
      p.need_choice(browse_purpose_from_name(p.rest).has_value(), "surface, design, save, export or shape");
      break;
    case Kind::Colour: p.need_choice(p.rest == "ratio" || p.rest == "type", "ratio or type"); break;
    default: {  // Kind::Panel
      constexpr std::string_view kPanels = "file, pattern, elements, optimize, report or help";
      p.need_argument("a panel name: " + std::string(kPanels));
      if (std::find(std::begin(kPanelNames), std::end(kPanelNames), p.rest) == std::end(kPanelNames))
        p.refuse("panel '" + std::string(p.rest) + "': use " + std::string(kPanels));
      p.out.text = std::string(p.rest);
    }
  }
}

// spacing D, set KEY VALUE, cut T FOLDER, orbit DEGREES FRAMES, wait N.
void parse_values(const LineParser& p) {
  ScriptCommand& out = p.out;
  switch (out.kind) {
    case Kind::Spacing:
      p.need_argument("the edge length D (0 = derive it from the surface)");
      if (!parse_number(p.rest, out.number) || out.number < 0)
        p.refuse("spacing '" + std::string(p.rest) + "': must be a finite number >= 0");
      break;
    case Kind::Set: {
      p.need_argument("a key and a value, e.g. set " + key_path(Key::solver_dt) + " 0.25");
      const auto [key, value] = first_word(p.rest);
      if (value.empty()) p.refuse("set " + std::string(key) + " needs a value");
      out.text = std::string(key);
      out.value = std::string(value);
      break;
    }
    case Kind::Cut: {
      p.need_argument("the metal's thickness and a folder, e.g. cut 1 out/metal");
      const auto [thickness, folder] = first_word(p.rest);
      if (!parse_number(thickness, out.number) || !(out.number > 0))
        p.refuse("cut '" + std::string(thickness) + "': the thickness must be a number above 0");
      if (folder.empty()) p.refuse("cut " + std::string(thickness) + " needs a folder");
      out.text = std::string(folder);
      break;
    }
    case Kind::Orbit: {
      p.need_argument("degrees and a number of frames, e.g. orbit 90 60");
      const auto [degrees, frames] = first_word(p.rest);
      if (!parse_number(degrees, out.number) || !std::isfinite(out.number) || !parse_number(frames, out.frames) ||
          out.frames < 1)
        p.refuse("orbit '" + std::string(p.rest) + "': give degrees and a whole number of frames >= 1");
      break;
    }
    default:  // Kind::Wait
      p.need_argument("a number of frames");
      if (!parse_number(p.rest, out.frames) || out.frames < 0)
        p.refuse("wait '" + std::string(p.rest) + "': must be a whole number of frames >= 0");
  }
}

// select, pin, unpin, delete ID|selection; drag ID DU DV.
void parse_element(const LineParser& p) {
  ScriptCommand& out = p.out;
  const bool drag = out.kind == Kind::Drag;
  p.need_argument(drag ? "an element id and a move in spacings, e.g. drag 42 0.4 0" : "an element id (placements.csv's id)");
  const auto [id, move] = first_word(p.rest);
  if (id == "selection" && move.empty() && (out.kind == Kind::Pin || out.kind == Kind::Unpin || out.kind == Kind::Delete)) {
    out.id = ScriptCommand::kSelection;
    return;
  }
  if (!parse_number(id, out.id) || out.id < 0)
    p.refuse(p.name + " '" + std::string(id) + "': an element id is a whole number >= 0");
  if (!drag && !move.empty()) p.refuse(p.name + " takes one element id, got '" + std::string(p.rest) + "'");
  if (!drag) return;
  const auto [du, dv] = first_word(move);
  if (!parse_number(du, out.u) || !parse_number(dv, out.v))
    p.refuse("drag " + std::string(id) + " needs the move as two numbers of spacings D, e.g. drag " + std::string(id) +
             " 0.4 0");
}

// select_box U0 V0 U1 V1, add U V, brush U V RADIUS STRENGTH.
void parse_map_points(const LineParser& p) {
  ScriptCommand& out = p.out;
  const std::vector<std::string_view> words = p.words();
  const auto numbers = [&](std::initializer_list<double*> targets) {
    if (words.size() != targets.size()) return false;
    std::size_t i = 0;
    for (double* target : targets)
      if (!parse_number(words[i++], *target)) return false;
    return true;
  };
  if (out.kind == Kind::SelectBox) {
    p.need_argument("two map corners U0 V0 U1 V1, e.g. select_box -1 -1 1 1");
    if (!numbers({&out.u, &out.v, &out.u1, &out.v1}))
      p.refuse("select_box '" + std::string(p.rest) + "': give two map corners as four numbers U0 V0 U1 V1");
  } else if (out.kind == Kind::Add) {
    p.need_argument("a map point U V (as placements.csv's u and v), e.g. add 1.5 -2");
    if (!numbers({&out.u, &out.v})) p.refuse("add '" + std::string(p.rest) + "': give the map point as two numbers U V");
  } else {  // Kind::Brush
    p.need_argument("a map point, a radius in spacings and a strength, e.g. brush 0 0 4 0.3");
    if (!numbers({&out.u, &out.v, &out.radius, &out.strength}) || !(out.radius > 0) || out.strength < -0.5 ||
        out.strength > 1)
      p.refuse("brush '" + std::string(p.rest) +
               "': give U V RADIUS STRENGTH, the radius > 0 spacings, the strength in [-0.5, 1]");
  }
}

// type FIELD TEXT [enter|tab|away]: FIELD and TEXT each a word or "quoted" (blanks, an empty text).
void parse_typing(const LineParser& p) {
  p.need_argument("a field and the text to type, e.g. type \"stone diameter\" 1.5");
  std::string_view left = p.rest;
  const auto take = [&](const char* what) {
    if (left.empty()) p.refuse("type '" + std::string(p.rest) + "': give " + what);
    if (left.front() != '"') {
      const auto [word, after] = first_word(left);
      left = after;
      return std::string(word);
    }
    const std::size_t close = left.find('"', 1);
    if (close == std::string_view::npos) p.refuse("type '" + std::string(p.rest) + "': a quote is not closed");
    const std::string quoted(left.substr(1, close - 1));
    left = trim(left.substr(close + 1));
    return quoted;
  };
  p.out.text = take("the field's label (quoted when it has blanks)");
  p.out.value = take("the text to type after the field");
  if (left.empty() || left == "enter") p.out.type_end = TypeEnd::Enter;
  else if (left == "tab") p.out.type_end = TypeEnd::Tab;
  else if (left == "away") p.out.type_end = TypeEnd::Away;
  else p.refuse("type '" + std::string(p.rest) + "': end with enter, tab or away, got '" + std::string(left) + "'");
  if (p.out.text.empty()) p.refuse("type needs a field's label");
}

}  // namespace

bool parse_script_line(std::string_view line, int line_number, const std::string& source, ScriptCommand& out) {
  const std::string_view content = trim(strip_comment(line));
  if (content.empty()) return false;
  const std::string where = source + ":" + std::to_string(line_number) + ": ";
  const auto [word, rest] = first_word(content);
  const Kind* kind = nullptr;
  for (const auto& [command, k] : kCommands)
    if (command == word) kind = &k;
  if (!kind) {
    std::string known;
    for (const auto& [command, k] : kCommands) known += (known.empty() ? "" : ", ") + std::string(command);
    throw InputError(where + "unknown command '" + std::string(word) + "'; commands are " + known);
  }
  out = ScriptCommand{};
  out.kind = *kind;
  out.line = line_number;
  const LineParser parser{where, std::string(word), rest, out};
  switch (*kind) {
    case Kind::Open: case Kind::Design: case Kind::Save: case Kind::Export: case Kind::Screenshot:
      parse_path(parser);
      break;
    case Kind::Click: case Kind::MouseDrag: case Kind::MouseDrag3d: parse_pointer(parser); break;
    case Kind::Pattern: case Kind::CutAxis: case Kind::Key: case Kind::Browse: case Kind::Colour: case Kind::Panel:
      parse_choice(parser);
      break;
    case Kind::Spacing: case Kind::Set: case Kind::Cut: case Kind::Orbit: case Kind::Wait: parse_values(parser); break;
    case Kind::Select: case Kind::Pin: case Kind::Unpin: case Kind::Delete: case Kind::Drag: parse_element(parser); break;
    case Kind::SelectBox: case Kind::Add: case Kind::Brush: parse_map_points(parser); break;
    case Kind::Type: parse_typing(parser); break;
    default:
      if (!rest.empty()) parser.refuse(std::string(word) + " takes no argument, got '" + std::string(rest) + "'");
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
  // A script is a few hundred lines; a pipe, a device or a huge file is refused before reading.
  return parse_script(read_regular_file(path, std::uintmax_t(16) << 20, path, "script file"), path);
}

}  // namespace paver::studio
