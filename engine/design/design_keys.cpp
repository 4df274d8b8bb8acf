#include "design/design_keys.h"

#include "core/number_text.h"

#include <nlohmann/json.hpp>

#include <glm/vec2.hpp>

#include <charconv>
#include <deque>
#include <system_error>

namespace paver {
namespace {

// The part of a row written by hand; its type, choices and default come from visit_keys.
struct Row {
  Key key;
  std::string_view path;
  ValueRange range = ValueRange::any();
  std::string_view range_note = {};
  std::string_view unit = {};
  std::string_view help = {};
  std::string_view flag = {};
  std::string_view studio = {};
  bool required = false;
};

constexpr ValueRange kNonNegative = ValueRange::at_least(0);
constexpr ValueRange kUnitScale = ValueRange::open_closed(0, 1);
constexpr std::string_view kSurfaceUnits = "surface units";

// In Key's order; "#" in `studio` stands for the item's index.
constexpr Row kRows[] = {
    {Key::units, "units", {}, {}, {},
     "the unit of the surface's coordinates, so of D, the gap and every length; sizes and carats are reported in mm",
     "units", "Elements > Stones (jewellery) > units"},
    {Key::pattern_tessellation, "pattern.tessellation", {}, {}, {},
     "the tessellation: the paper's three, two pentagonal ones, or a cell drawn in pattern.cell (the long names "
     "triangle, square, hexagon are read too; docs/tessellations.md)",
     "pattern",
     "Pattern > tessellation"},
    {Key::pattern_spacing, "pattern.spacing", kNonNegative, "0 = derive from the surface", kSurfaceUnits,
     "D, the edge length; 0 derives it from the surface (about 1,000 points)", "spacing", "Pattern > D (spacing)"},
    {Key::pattern_bracing, "pattern.bracing", {}, {}, {}, "virtual edges across faces that are not triangles (eq. 7)",
     {}, "Pattern > bracing"},
    {Key::pattern_operators, "pattern.operators", {}, {}, {}, "edge operators on the unit cell, applied in order", {},
     "Pattern > edge operators > #"},
    {Key::operator_op, "pattern.operators[].op", {}, {}, {}, "flip, add or remove the edge", {},
     "Pattern > edge operators > #"},
    {Key::operator_from, "pattern.operators[].from", kNonNegative, "a unit-cell vertex index", {},
     "the edge's vertex in the cell", {}, "Pattern > edge operators > #"},
    {Key::operator_to, "pattern.operators[].to", kNonNegative, "a unit-cell vertex index", {},
     "the edge's other vertex, in the cell `offset` away", {}, "Pattern > edge operators > #"},
    {Key::operator_offset, "pattern.operators[].offset", ValueRange::closed(-kMaxOperatorOffset, kMaxOperatorOffset),
     "cells away: an edge joins nearby vertices", "lattice steps a1, a2", "the cell of `to`", {},
     "Pattern > edge operators > #"},
    {Key::operator_virtual, "pattern.operators[].virtual", {}, {}, {},
     "add only: the new edge is a spring that carries no elements", {}, "Pattern > edge operators > #"},
    {Key::cell_a1, "pattern.cell.a1", {}, {}, "x D", "tessellation \"cell\": the first lattice vector", {},
     "Pattern > drawn cell"},
    {Key::cell_a2, "pattern.cell.a2", {}, {}, "x D", "the second lattice vector, to the left of a1", {},
     "Pattern > drawn cell"},
    {Key::cell_vertices, "pattern.cell.vertices", {}, {}, {}, "the drawn cell's vertices (docs/tessellations.md)", {},
     "Pattern > drawn cell"},
    {Key::cell_vertex_at, "pattern.cell.vertices[].at", {}, {}, "x D", "where the vertex is in the cell", {},
     "Pattern > drawn cell", true},
    {Key::cell_edges, "pattern.cell.edges", {}, {}, {}, "the drawn cell's edges: they meet only at their ends", {},
     "Pattern > drawn cell"},
    {Key::cell_edge_from, "pattern.cell.edges[].from", kNonNegative, "a vertex of the drawn cell", {},
     "the edge's vertex in the cell", {}, "Pattern > drawn cell", true},
    {Key::cell_edge_to, "pattern.cell.edges[].to", kNonNegative, "a vertex of the drawn cell", {},
     "the edge's other vertex, in the cell `offset` away", {}, "Pattern > drawn cell", true},
    {Key::cell_edge_offset, "pattern.cell.edges[].offset", ValueRange::closed(-kMaxDrawnCellOffset, kMaxDrawnCellOffset),
     "cells away: an edge joins nearby vertices", "lattice steps a1, a2", "the cell of `to`", {},
     "Pattern > drawn cell"},
    {Key::cell_edge_virtual, "pattern.cell.edges[].virtual", {}, {}, {},
     "the edge is a spring that carries no elements", {}, "Pattern > drawn cell"},
    {Key::pattern_topology, "pattern.topology", {}, {}, {},
     "the paper's lattice, a pattern grown on the surface, or auto: the lattice unless it tears (docs/topology.md)",
     "topology", "Pattern > topology"},
    {Key::vertex_enabled, "elements.vertex.enabled", {}, {}, {}, "a V-element on every lattice vertex", {},
     "Elements > V-elements > enabled"},
    {Key::vertex_scale, "elements.vertex.scale", kUnitScale, "diameter = scale * D", "x D",
     "the V-element's diameter over D", {}, "Elements > V-elements > size (x D)"},
    {Key::vertex_shape, "elements.vertex.shape", {}, {}, {}, "the V-element's shape", {},
     "Elements > V-elements > shape"},
    {Key::elements_edge, "elements.edge", {}, {}, {}, "E-elements, each on the pattern's edges (below)", {},
     "Elements > E-element #"},
    {Key::edge_t, "elements.edge[].t", ValueRange::closed(0, 1), {}, {}, "where along the edge it sits", {},
     "Elements > E-element # > along the edge"},
    {Key::edge_scale, "elements.edge[].scale", kUnitScale, "diameter = scale * D", "x D",
     "the E-element's diameter over D", {}, "Elements > E-element # > size (x D)"},
    {Key::edge_shape, "elements.edge[].shape", {}, {}, {}, "the E-element's shape", {},
     "Elements > E-element # > shape"},
    {Key::edge_cell_edges, "elements.edge[].cell_edges", kNonNegative, "a unit-cell edge index", {},
     "the unit-cell edges it sits on; empty: every real edge", {}, "Elements > E-element # > cell edges"},
    {Key::face_enabled, "elements.face.enabled", {}, {}, {},
     "an F-element at the centre of every face of the pattern (docs/tessellations.md)", "face-elements",
     "Elements > F-elements > enabled"},
    {Key::face_scale, "elements.face.scale", kUnitScale, "diameter = scale * D", "x D",
     "the F-element's diameter over D", "face-scale", "Elements > F-elements > size (x D)"},
    {Key::face_shape, "elements.face.shape", {}, {}, {}, "the F-element's shape", {},
     "Elements > F-elements > shape"},
    {Key::custom_shape, "elements.custom_shape", {}, {}, {},
     "OBJ, OFF, PLY or STL for the custom shape, +Z along the normal, relative to the design file (below)", {},
     "Elements > Custom shape"},
    {Key::allow_overlap, "elements.allow_overlap", {}, {}, {},
     "elements may intersect by design (the paper's figure 15)", {}, "Elements > allow overlapping elements"},
    {Key::gap, "elements.gap", kNonNegative, kSurfaceUnits, kSurfaceUnits,
     "free space between neighbouring footprints (docs/contact.md)", "gap", "Elements > Stones (jewellery) > gap"},
    {Key::margin, "elements.margin", kNonNegative, kSurfaceUnits, kSurfaceUnits,
     "free band along the boundary that no footprint enters (docs/stones.md)", "margin",
     "Elements > Stones (jewellery) > edge margin"},
    {Key::rim_rows, "elements.rim_rows", {}, {}, {},
     "a row of stones along the rims: none, around every hole, every rim, or auto (every rim for a tri lattice of "
     "V-elements, none for other patterns; docs/holes_and_bands.md)", "rim-rows",
     "Elements > Stones (jewellery) > rim rows"},
    {Key::close_spots, "elements.close_spots", {}, {}, {},
     "after the pass, a stone pushed into every bare spot where one fits, its neighbours moving to make room "
     "(docs/contact.md)",
     "close-spots", "Elements > Stones (jewellery) > close bare spots"},
    {Key::fill_sizes, "elements.fill_sizes", ValueRange::above(0), "each a stocked size smaller than the main stone",
     kSurfaceUnits,
     "stocked stone sizes smaller than the main stone: after the pass, every place where one fits gets the largest "
     "that fits (docs/stones.md)",
     "fill-sizes", "Elements > Stones (jewellery) > fill with smaller sizes"},
    {Key::grade_by, "elements.grade.by", {}, {}, {},
     "graded stones: the main size falls off towards the smallest where the surface bends most, near the "
     "rims or towards a point (a pendant's tip), in stocked steps (docs/stones.md)",
     "grade", "Elements > Stones (jewellery) > graded by"},
    {Key::grade_smallest, "elements.grade.smallest", kNonNegative, "0 = none; with a grade, less than the main stone",
     kSurfaceUnits, "the smallest graded stone", "grade-smallest", "Elements > Stones (jewellery) > smallest graded"},
    {Key::grade_width, "elements.grade.width", kNonNegative, "0 = three main stones", kSurfaceUnits,
     "rim, point: how far from the margin, or the point, the stones grow back to the main size", "grade-width",
     "Elements > Stones (jewellery) > grade width"},
    {Key::grade_point, "elements.grade.point", {}, "[x, y, z]; with grade \"point\"", kSurfaceUnits,
     "point: where the graded stones are smallest, the surface's point nearest x, y, z (a pendant's tip)", "grade-point",
     "Elements > Stones (jewellery) > towards the point"},
    {Key::beads_enabled, "elements.beads.enabled", {}, {}, {},
     "a bead (shared prong) in the gap of every three stones in contact (docs/stones.md)", "beads",
     "Elements > Stones (jewellery) > beads between stones"},
    {Key::beads_scale, "elements.beads.scale", ValueRange::open_closed(0, 2), {}, {},
     "the bead over the largest that fits between its stones, when that is larger than its least size", {},
     "Elements > Stones (jewellery) > bead size"},
    {Key::beads_min_diameter, "elements.beads.min_diameter", ValueRange::above(0), {}, "mm",
     "the least bead, castable (a cast bead is about 0.5-0.6 mm; docs/stones.md)", "bead-min",
     "Elements > Stones (jewellery) > least bead"},
    {Key::beads_over, "elements.beads.over", kNonNegative, {}, "mm",
     "how far a bead reaches over the girdle of each stone it holds", "bead-over",
     "Elements > Stones (jewellery) > bead reach over the girdle"},
    {Key::placement_offset, "placement.offset", {}, {}, "pattern-plane units, as D", "the pattern moved over the map",
     {}, "Pattern > Placement > offset"},
    {Key::rotation_deg, "placement.rotation_deg", {}, {}, "degrees",
     "the pattern turned: clockwise as the map shows it, seen from the side the normals point to", {},
     "Pattern > Placement > rotation"},
    {Key::placement_scale, "placement.scale", ValueRange::above(0), {}, {}, "the map scaled under the pattern", {},
     "Pattern > Placement > scale"},
    {Key::band_rows, "placement.band_rows", {}, {}, {},
     "on a band, which way the rows run; auto paves both ways and keeps the better", {}, "Pattern > band rows"},
    {Key::cut_axis, "placement.cut_axis", {}, {}, {},
     "a closed surface is cut into charts across this axis through its centre (auto: its longest)", "cut",
     "File > cut across"},
    {Key::align, "placement.align", {}, {}, {}, "rows along a world axis as it lies on the surface (below)", "align",
     "Pattern > Placement > rows along axis"},
    {Key::fit_offset, "placement.fit_offset", {}, {}, {},
     "shift the lattice within one cell to where the most elements fit (below)", "fit-offset",
     "Pattern > Placement > fit offset"},
    // The solver's rows are the parameter table's (filled in by the table below).
#define PAVER_SOLVER_ROW(type, name, ...) {Key::solver_##name, "solver." #name},
    PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_ROW)
#undef PAVER_SOLVER_ROW
    {Key::edits_moved, "edits.moved", {}, {}, {}, "stones dragged or pinned (below; docs/editing.md)", {},
     "Elements > Single stones > edits (moved)"},
    {Key::moved_id, "edits.moved[].id", ValueRange::closed(0, kFirstAddedId - 1), "a pattern particle's id", {},
     "the pattern particle's id (placements.csv's id)", {}, "Elements > Single stones > edits (moved)", true},
    {Key::moved_uv, "edits.moved[].uv", {}, {}, "map units", "the map point it goes to", {},
     "Elements > Single stones > edits (moved)", true},
    {Key::moved_pinned, "edits.moved[].pinned", {}, {}, {},
     "held exactly there; false lets it relax from there", {}, "Elements > Single stones > edits (moved)"},
    {Key::edits_deleted, "edits.deleted", {}, {}, {}, "stones deleted (below)", {},
     "Elements > Single stones > edits (deleted)"},
    {Key::deleted_id, "edits.deleted[].id", kNonNegative, "an element id", {}, "the element's id", {},
     "Elements > Single stones > edits (deleted)", true},
    {Key::deleted_uv, "edits.deleted[].uv", {}, {}, "map units",
     "where it was: the element found there when the ids have changed", {},
     "Elements > Single stones > edits (deleted)", true},
    {Key::edits_added, "edits.added", {}, {}, {}, "stones added (below)", {}, "Elements > Single stones > edits (added)"},
    {Key::added_id, "edits.added[].id", ValueRange::at_least(kFirstAddedId), "the designer's own ids", {},
     "its own id, from 1,000,000,000", {}, "Elements > Single stones > edits (added)", true},
    {Key::added_uv, "edits.added[].uv", {}, {}, "map units", "the map point it is held at", {},
     "Elements > Single stones > edits (added)", true},
    {Key::guidance, "guidance", {}, {}, {}, "painted dabs that make the pattern looser or denser (docs/editing.md)", {},
     "Pattern > Guidance brush > dab #"},
    {Key::dab_uv, "guidance[].uv", {}, {}, "map units", "the dab's centre", {}, "Pattern > Guidance brush > dab #", true},
    {Key::dab_radius, "guidance[].radius", ValueRange::above(0), kSurfaceUnits, kSurfaceUnits, "the dab's radius", {},
     "Pattern > Guidance brush > dab #", true},
    {Key::dab_strength, "guidance[].strength", ValueRange::closed(-0.5, 1), "-0.5 = half the spacing, +1 = twice it",
     {}, "the spacing's change at the centre: +0.3 = 30% looser", {}, "Pattern > Guidance brush > dab #", true},
};

template <class T>
constexpr bool kIsItems = false;
template <class T>
constexpr bool kIsItems<std::vector<T>> = !std::is_same_v<T, int> && !std::is_same_v<T, double>;

template <class T>
KeyType type_of() {
  if constexpr (std::is_same_v<T, double>) return KeyType::Number;
  else if constexpr (std::is_same_v<T, int>) return KeyType::Integer;
  else if constexpr (std::is_same_v<T, bool>) return KeyType::Bool;
  else if constexpr (std::is_same_v<T, std::string>) return KeyType::Text;
  else if constexpr (NamedEnum<T>) return KeyType::Choice;
  else if constexpr (std::is_same_v<T, glm::dvec2>) return KeyType::Pair;
  else if constexpr (std::is_same_v<T, glm::ivec2>) return KeyType::IntPair;
  else if constexpr (std::is_same_v<T, std::vector<int>>) return KeyType::IntList;
  else if constexpr (std::is_same_v<T, std::vector<double>>) return KeyType::NumberList;
  else {
    static_assert(kIsItems<T>, "a key's field of a type the table does not know");
    return KeyType::Objects;
  }
}

// What a default value looks like in design.json.
template <class T>
nlohmann::json default_json(const T& value) {
  if constexpr (NamedEnum<T>) return std::string(enum_name(value));
  else if constexpr (std::is_same_v<T, glm::dvec2>) return {value.x, value.y};
  else if constexpr (std::is_same_v<T, glm::ivec2>) return {value.x, value.y};
  else if constexpr (kIsItems<T>) return nlohmann::json::array();
  else return value;
}

// A default as the docs write it: numbers as number_text gives them, arrays with spaces.
std::string default_text_of(const nlohmann::json& value) {
  if (value.is_number_float()) return number_text(value.get<double>());
  if (!value.is_array()) return value.dump();
  std::string items;
  for (const nlohmann::json& item : value) items += (items.empty() ? "" : ", ") + default_text_of(item);
  return "[" + items + "]";
}

struct KeyTable {
  std::vector<DesignKey> rows;
  std::deque<std::string> texts;  // the rows' derived strings (a deque: views into them stay valid)

  std::string_view keep(std::string text) { return *texts.insert(texts.end(), std::move(text)); }

  template <class T>
  void describe(Key key, const T& value) {
    DesignKey& row = rows[std::size_t(key)];
    row.type = type_of<T>();
    if constexpr (NamedEnum<T>) row.choices = keep(enum_choices_quoted<T>());
    row.default_text = keep(default_text_of(default_json(value)));
    if constexpr (kIsItems<T>) {
      const typename T::value_type item{};
      visit_item_keys(item, [&](Key k, const auto& field) { describe(k, field); });
    }
  }

  KeyTable() {
    for (const Row& r : kRows)
      rows.push_back({r.key, r.path, KeyType::Number, r.range, r.range_note, r.unit, r.help, r.flag, r.studio,
                      r.required, {}, {}});
    for (const SolverParameter& p : solver_parameters()) {
      DesignKey& row = rows[std::size_t(find_row(p.name))];
      row.range = p.range;
      row.unit = p.unit;
      row.help = p.label;  // the plain words; docs/parameters.md has the whole help
      row.flag = p.flag;
      row.studio = keep("Optimize > " + std::string(p.label) + " (" + std::string(p.name) + ")");
    }
    const Design defaults;
    visit_keys(defaults, [&](Key key, const auto& value) { describe(key, value); });
  }

  Key find_row(std::string_view solver_name) const {
    for (const DesignKey& row : rows)
      if (row.path.starts_with("solver.") && row.path.substr(7) == solver_name) return row.key;
    return Key::units;  // not reached: every parameter has a row
  }
};

const KeyTable& key_table() {
  static const KeyTable instance;
  return instance;
}

// "elements.edge[2].t" -> "elements.edge[].t", and the first index (2).
std::string without_indices(std::string_view path) {
  std::string shape;
  for (std::size_t i = 0; i < path.size(); ++i) {
    shape += path[i];
    if (path[i] != '[') continue;
    const std::size_t close = path.find(']', i);
    if (close == std::string_view::npos) return std::string(path);
    shape += ']';
    i = close;
  }
  return shape;
}

// What a value must be: "finite and >= 0 (surface units)"; an integer is finite anyway.
std::string refusal(const DesignKey& row, bool integer) {
  std::string allowed = row.range.describe();
  if (integer && allowed.starts_with("finite and ")) allowed = allowed.substr(11);
  return allowed + (row.range_note.empty() ? "" : " (" + std::string(row.range_note) + ")");
}

bool counts_integers(KeyType type) { return type == KeyType::Integer || type == KeyType::IntPair || type == KeyType::IntList; }
bool is_numeric(KeyType type) {
  return counts_integers(type) || type == KeyType::Number || type == KeyType::Pair || type == KeyType::NumberList;
}

// The range check of one key's value (and every number in it), naming it with its index.
class RangeCheck {
public:
  std::optional<std::string> problem;

  template <class T>
  void operator()(Key key, const T& value, std::optional<std::size_t> index = std::nullopt) {
    if (problem) return;
    const DesignKey& row = design_key(key);
    const std::string path = key_path(key, index);
    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
      check(row, path, double(value), std::is_same_v<T, int>);
    } else if constexpr (std::is_same_v<T, glm::dvec2> || std::is_same_v<T, glm::ivec2>) {
      for (int k = 0; k < 2; ++k) check(row, path + "[" + std::to_string(k) + "]", double(value[k]), std::is_same_v<T, glm::ivec2>);
    } else if constexpr (std::is_same_v<T, std::vector<int>> || std::is_same_v<T, std::vector<double>>) {
      for (std::size_t k = 0; k < value.size(); ++k)
        check(row, path + "[" + std::to_string(k) + "]", double(value[k]), std::is_same_v<T, std::vector<int>>);
    } else if constexpr (kIsItems<T>) {
      for (std::size_t i = 0; i < value.size(); ++i)
        visit_item_keys(value[i], [&](Key k, const auto& field) { (*this)(k, field, i); });
    }
  }

private:
  void check(const DesignKey& row, const std::string& path, double value, bool integer) {
    if (row.range.contains(value) || problem) return;
    problem = "'" + path + "' must be " + refusal(row, integer) + ", got " + number_text(value);
  }
};

// A flag's text as the key's value; a refusal says what the value must be.
template <class T>
std::optional<std::string> parse_flag(const DesignKey& row, std::string_view text, T& out) {
  if constexpr (std::is_same_v<T, bool>) {
    // A bool key whose default is on is turned off by "false" (the CLI's --no- twin).
    if (text == "false") {
      out = false;
      return std::nullopt;
    }
    if (!text.empty() && text != "true") return std::string("is true or false");
    out = true;
    return std::nullopt;
  } else if constexpr (NamedEnum<T>) {
    const std::optional<T> named = enum_from_name<T>(text);
    if (!named) return "use " + enum_choices_words<T>();
    out = *named;
    return std::nullopt;
  } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      return std::string(std::is_same_v<T, int> ? "must be a whole number" : "must be a number");
    if (!row.range.contains(double(value))) return "must be " + refusal(row, std::is_same_v<T, int>);
    out = value;
    return std::nullopt;
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    // Comma-separated: "1.3,1.1,0.9"; an empty text is the empty list.
    std::vector<double> values;
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      double value = 0;
      if (const std::optional<std::string> problem = parse_flag(row, text.substr(start, comma - start), value))
        return problem->starts_with("must be a number") ? "must be numbers separated by commas (1.3,1.1,0.9)" : *problem;
      values.push_back(value);
      start = comma + 1;
      if (start == text.size()) return std::string("must be numbers separated by commas (1.3,1.1,0.9)");  // "1.3,"
    }
    out = std::move(values);
    return std::nullopt;
  } else {
    return std::string("is not a flag");
  }
}

}  // namespace

std::span<const DesignKey> design_keys() { return key_table().rows; }

const DesignKey& design_key(Key key) { return key_table().rows[std::size_t(key)]; }

const DesignKey* find_design_key(std::string_view path) {
  const std::string shape = without_indices(path);
  for (const DesignKey& row : design_keys())
    if (row.path == shape) return &row;
  return nullptr;
}

std::string key_path(Key key, std::optional<std::size_t> index) {
  std::string path(design_key(key).path);
  const std::size_t brackets = path.find("[]");
  if (brackets != std::string::npos && index) path.insert(brackets + 1, std::to_string(*index));
  return path;
}

std::string key_and_flag(Key key) {
  const DesignKey& row = design_key(key);
  return std::string(row.path) + (row.flag.empty() ? "" : " (--" + std::string(row.flag) + ")");
}

std::optional<std::string> key_range_problem(const Design& design) {
  RangeCheck check;
  visit_keys(design, check);
  return check.problem;
}

std::optional<std::string> set_key_from_text(Design& design, Key key, std::string_view text) {
  std::optional<std::string> problem = std::string("is not a flag");
  const DesignKey& row = design_key(key);
  visit_keys(design, [&](Key k, auto& field) {
    if (k == key) problem = parse_flag(row, text, field);
  });
  return problem;
}

std::vector<Key> flag_keys() {
  std::vector<Key> keys;
  for (const DesignKey& row : design_keys())
    if (!row.flag.empty()) keys.push_back(row.key);
  return keys;
}

std::string design_keys_markdown() {
  const auto type_text = [](const DesignKey& row) -> std::string {
    switch (row.type) {
      case KeyType::Number: return "number";
      case KeyType::Integer: return "integer";
      case KeyType::Bool: return "bool";
      case KeyType::Text: return "text";
      case KeyType::Choice: return std::string(row.choices);
      case KeyType::Pair: return "[x, y]";
      case KeyType::IntPair: return "[i, j] integers";
      case KeyType::IntList: return "[i, ...] integers";
      case KeyType::NumberList: return "[x, ...] numbers";
      case KeyType::Objects: return "array of objects";
    }
    return "";
  };
  std::string md = "| key | type | default | range | unit | flag | meaning |\n|---|---|---|---|---|---|---|\n";
  md += "| `version` | integer | (required) | " + std::to_string(Design::kOldestVersion) + " to " +
        std::to_string(Design::kVersion) + " |  |  | the file's version (below) |\n";
  for (const DesignKey& row : design_keys()) {
    const std::string range = is_numeric(row.type) ? refusal(row, counts_integers(row.type)) : "";
    md += "| `" + std::string(row.path) + "` | " + type_text(row) + " | " +
          (row.required ? std::string("(required)") : "`" + std::string(row.default_text) + "`") + " | " + range +
          " | " + std::string(row.unit) + " | " + (row.flag.empty() ? "" : "`--" + std::string(row.flag) + "`") +
          " | " + std::string(row.help) + " |\n";
  }
  return md;
}

}  // namespace paver
