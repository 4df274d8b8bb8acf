#include "io/design_io.h"

#include "io/atomic_file.h"
#include "core/closest_name.h"
#include "core/input_error.h"
#include "pattern/unit_cell.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <variant>
#include <vector>

namespace paver {
namespace {

using nlohmann::json;

constexpr Tessellation kTessellations[] = {Tessellation::Triangle, Tessellation::Grid, Tessellation::Hexagon};
constexpr Topology kTopologies[] = {Topology::Lattice, Topology::Adaptive, Topology::Auto};
constexpr Units kUnits[] = {Units::Millimetre, Units::Centimetre, Units::Metre, Units::Inch};
constexpr BandRows kBandRows[] = {BandRows::Along, BandRows::Across, BandRows::Auto};
constexpr AlignAxis kAlignAxes[] = {AlignAxis::None, AlignAxis::X, AlignAxis::Y, AlignAxis::Z};
constexpr CutAxis kCutAxes[] = {CutAxis::Auto, CutAxis::X, CutAxis::Y, CutAxis::Z};
constexpr RimRows kRimRows[] = {RimRows::None, RimRows::Holes, RimRows::All};
constexpr FilterBase kFilterBases[] = {FilterBase::Current, FilterBase::Initial};
constexpr ShapeKind kShapes[] = {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::HexPrism, ShapeKind::Disc,
                                 ShapeKind::Custom};
constexpr EdgeOperator::Kind kOperatorKinds[] = {EdgeOperator::Kind::Flip, EdgeOperator::Kind::Add,
                                                 EdgeOperator::Kind::Remove};

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string indexed(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }


// Reads design.json values into Design fields. Every error names the source and the full key
// path ("pattern.operators[2].offset") so the user can find the line to fix.
class Reader {
public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& message) const { throw InputError(source_ + ": " + message); }

  [[noreturn]] void wrong_type(const json& value, const std::string& path, std::string_view expected) const {
    fail("'" + path + "' must be " + std::string(expected) + ", got " + value.type_name());
  }

  // Requires `value` to be an object whose keys are all in `known`.
  void check_object(const json& value, const std::string& path, std::initializer_list<std::string_view> known) const {
    check_keys(value, path, known);
  }
  template <class Known>
  void check_keys(const json& value, const std::string& path, const Known& known) const {
    if (!value.is_object()) wrong_type(value, path, "an object");
    for (const auto& item : value.items()) {
      const std::string& key = item.key();
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      fail("unknown key '" + join(path, key) + "'" + suggestion(key, path, known));
    }
  }

  // Reads object[key] into `out`; an edit without its element's id or position means nothing.
  template <class T>
  void required(const json& object, const std::string& path, const char* key, T& out) const {
    if (!object.contains(key)) fail("missing key '" + join(path, key) + "'");
    field(object, path, key, out);
  }

  // Reads object[key] into `out` when present; an absent key keeps the default already in `out`.
  template <class T>
  void field(const json& object, const std::string& path, const char* key, T& out) const {
    const auto it = object.find(key);
    if (it != object.end()) read(*it, join(path, key), out);
  }

  void read(const json& value, const std::string& path, double& out) const {
    if (!value.is_number()) wrong_type(value, path, "a number");
    out = value.get<double>();
  }

  void read(const json& value, const std::string& path, int& out) const {
    if (value.is_number_unsigned()) {
      // Values above INT64_MAX are stored unsigned; compare without converting to int64.
      const auto number = value.get<std::uint64_t>();
      if (number > std::uint64_t(INT_MAX)) out_of_int_range(value, path);
      out = int(number);
    } else if (value.is_number_integer()) {
      const auto number = value.get<std::int64_t>();
      if (number < INT_MIN || number > INT_MAX) out_of_int_range(value, path);
      out = int(number);
    } else if (value.is_number_float()) {
      // Tools that only know doubles write 2 as 2.0; that is still the integer 2.
      const double number = value.get<double>();
      if (number != std::trunc(number)) fail("'" + path + "' must be an integer, got " + value.dump());
      if (number < double(INT_MIN) || number > double(INT_MAX)) out_of_int_range(value, path);
      out = int(number);
    } else {
      wrong_type(value, path, "an integer");
    }
  }

  void read(const json& value, const std::string& path, bool& out) const {
    if (!value.is_boolean()) wrong_type(value, path, "true or false");
    out = value.get<bool>();
  }

  void read(const json& value, const std::string& path, std::string& out) const {
    if (!value.is_string()) wrong_type(value, path, "a string");
    out = value.get<std::string>();
  }

  void read(const json& value, const std::string& path, glm::dvec2& out) const {
    check_pair(value, path, "an array of 2 numbers");
    read(value[0], indexed(path, 0), out.x);
    read(value[1], indexed(path, 1), out.y);
  }

  void read(const json& value, const std::string& path, glm::ivec2& out) const {
    check_pair(value, path, "an array of 2 integers");
    read(value[0], indexed(path, 0), out.x);
    read(value[1], indexed(path, 1), out.y);
  }

  void read(const json& value, const std::string& path, Tessellation& out) const {
    // The command line's long names ("triangle", "square", "hexagon") are read here too.
    if (value.is_string())
      if (const std::optional<Tessellation> t = tessellation_from_name(value.get<std::string>())) {
        out = *t;
        return;
      }
    read_name(value, path, out, kTessellations, tessellation_name);
  }
  void read(const json& value, const std::string& path, Topology& out) const {
    read_name(value, path, out, kTopologies, topology_name);
  }
  void read(const json& value, const std::string& path, BandRows& out) const {
    read_name(value, path, out, kBandRows, band_rows_name);
  }
  void read(const json& value, const std::string& path, AlignAxis& out) const {
    read_name(value, path, out, kAlignAxes, align_axis_name);
  }
  void read(const json& value, const std::string& path, CutAxis& out) const {
    read_name(value, path, out, kCutAxes, cut_axis_name);
  }
  void read(const json& value, const std::string& path, RimRows& out) const {
    read_name(value, path, out, kRimRows, rim_rows_name);
  }
  void read(const json& value, const std::string& path, Units& out) const {
    read_name(value, path, out, kUnits, units_name);
  }
  void read(const json& value, const std::string& path, FilterBase& out) const {
    read_name(value, path, out, kFilterBases, filter_base_name);
  }
  void read(const json& value, const std::string& path, ShapeKind& out) const {
    read_name(value, path, out, kShapes, shape_name);
  }
  void read(const json& value, const std::string& path, EdgeOperator::Kind& out) const {
    read_name(value, path, out, kOperatorKinds, operator_name);
  }

  template <class T>
  void read(const json& value, const std::string& path, std::vector<T>& out) const {
    if (!value.is_array()) wrong_type(value, path, "an array");
    out.assign(value.size(), T{});
    for (size_t i = 0; i < value.size(); ++i) read(value[i], indexed(path, i), out[i]);
  }

  void read(const json& value, const std::string& path, EdgeOperator& out) const {
    check_object(value, path, {"op", "from", "to", "offset", "virtual"});
    field(value, path, "op", out.kind);
    field(value, path, "from", out.from);
    field(value, path, "to", out.to);
    field(value, path, "offset", out.offset);
    field(value, path, "virtual", out.is_virtual);
  }

  void read(const json& value, const std::string& path, PatternDesign& out) const {
    check_object(value, path, {"tessellation", "spacing", "bracing", "operators", "topology"});
    field(value, path, "tessellation", out.tessellation);
    field(value, path, "spacing", out.spacing);
    field(value, path, "bracing", out.bracing);
    field(value, path, "operators", out.operators);
    field(value, path, "topology", out.topology);
  }

  void read(const json& value, const std::string& path, VertexElementDesign& out) const {
    check_object(value, path, {"enabled", "scale", "shape"});
    field(value, path, "enabled", out.enabled);
    field(value, path, "scale", out.scale);
    field(value, path, "shape", out.shape);
  }

  void read(const json& value, const std::string& path, EdgeElementDesign& out) const {
    check_object(value, path, {"t", "scale", "shape", "cell_edges"});
    field(value, path, "t", out.t);
    field(value, path, "scale", out.scale);
    field(value, path, "shape", out.shape);
    field(value, path, "cell_edges", out.cell_edges);
  }

  void read(const json& value, const std::string& path, ElementsDesign& out) const {
    check_object(value, path, {"vertex", "edge", "custom_shape", "allow_overlap", "gap", "margin", "rim_rows", "beads"});
    field(value, path, "vertex", out.vertex);
    field(value, path, "edge", out.edge);
    field(value, path, "custom_shape", out.custom_shape);
    field(value, path, "allow_overlap", out.allow_overlap);
    field(value, path, "gap", out.gap);
    field(value, path, "margin", out.margin);
    field(value, path, "rim_rows", out.rim_rows);
    field(value, path, "beads", out.beads);
  }

  void read(const json& value, const std::string& path, BeadDesign& out) const {
    check_object(value, path, {"enabled", "scale"});
    field(value, path, "enabled", out.enabled);
    field(value, path, "scale", out.scale);
  }

  void read(const json& value, const std::string& path, MovedParticle& out) const {
    check_object(value, path, {"id", "uv", "pinned"});
    required(value, path, "id", out.id);
    required(value, path, "uv", out.uv);
    field(value, path, "pinned", out.pinned);
  }

  // An element named by id and map point: a deletion or an addition.
  template <class IdAndPoint>
    requires std::is_same_v<IdAndPoint, DeletedElement> || std::is_same_v<IdAndPoint, AddedElement>
  void read(const json& value, const std::string& path, IdAndPoint& out) const {
    check_object(value, path, {"id", "uv"});
    required(value, path, "id", out.id);
    required(value, path, "uv", out.uv);
  }

  void read(const json& value, const std::string& path, GuidanceDab& out) const {
    check_object(value, path, {"uv", "radius", "strength"});
    required(value, path, "uv", out.uv);
    required(value, path, "radius", out.radius);
    required(value, path, "strength", out.strength);
  }

  void read(const json& value, const std::string& path, ElementEdits& out) const {
    check_object(value, path, {"moved", "deleted", "added"});
    field(value, path, "moved", out.moved);
    field(value, path, "deleted", out.deleted);
    field(value, path, "added", out.added);
  }

  void read(const json& value, const std::string& path, Placement& out) const {
    check_object(value, path, {"offset", "rotation_deg", "scale", "band_rows", "cut_axis", "align", "fit_offset"});
    field(value, path, "offset", out.offset);
    field(value, path, "rotation_deg", out.rotation_deg);
    field(value, path, "scale", out.scale);
    field(value, path, "band_rows", out.band_rows);
    field(value, path, "cut_axis", out.cut_axis);
    field(value, path, "align", out.align);
    field(value, path, "fit_offset", out.fit_offset);
  }

  void read(const json& value, const std::string& path, SolverParams& out) const {
    std::vector<std::string_view> known;
    for (const SolverParameter& p : solver_parameters()) known.push_back(p.name);
    check_keys(value, path, known);
    for (const SolverParameter& p : solver_parameters())
      std::visit([&](auto member) { field(value, path, std::string(p.name).c_str(), out.*member); }, p.member);
  }

private:
  [[noreturn]] void out_of_int_range(const json& value, const std::string& path) const {
    fail("'" + path + "' must be an integer in [" + std::to_string(INT_MIN) + ", " + std::to_string(INT_MAX) +
         "], got " + value.dump());
  }

  void check_pair(const json& value, const std::string& path, std::string_view expected) const {
    if (!value.is_array()) wrong_type(value, path, expected);
    if (value.size() != 2)
      fail("'" + path + "' must be " + std::string(expected) + ", got an array of " + std::to_string(value.size()));
  }

  template <class Enum, size_t N>
  void read_name(const json& value, const std::string& path, Enum& out, const Enum (&all)[N],
                 std::string_view (*name)(Enum)) const {
    if (!value.is_string()) wrong_type(value, path, "a string");
    const std::string text = value.get<std::string>();
    for (Enum candidate : all) {
      if (name(candidate) == text) {
        out = candidate;
        return;
      }
    }
    std::string choices;
    for (Enum candidate : all) choices += (choices.empty() ? "\"" : ", \"") + std::string(name(candidate)) + "\"";
    fail("'" + path + "' must be one of " + choices + ", got " + value.dump());
  }

  // " (did you mean 'pattern.spacing'?)" when a known key is a likely misspelling of `key`.
  template <class Known>
  static std::string suggestion(const std::string& key, const std::string& path, const Known& known) {
    if (const std::optional<std::string> best = closest_name(key, known))
      return " (did you mean '" + join(path, *best) + "'?)";
    std::string list;
    for (std::string_view candidate : known) list += (list.empty() ? "" : ", ") + std::string(candidate);
    return "; known keys here: " + list;
  }

  const std::string& source_;
};

// Builds the complete design, every key written. Templated on the JSON type so that files are
// written with nlohmann::ordered_json, keeping the keys in the order a reader expects.
template <class Json>
Json to_json(const Design& design) {
  Json operators = Json::array();
  for (const EdgeOperator& op : design.pattern.operators) {
    Json item = Json::object();
    item["op"] = std::string(operator_name(op.kind));
    item["from"] = op.from;
    item["to"] = op.to;
    item["offset"] = Json::array({op.offset.x, op.offset.y});
    item["virtual"] = op.is_virtual;
    operators.push_back(std::move(item));
  }
  Json pattern = Json::object();
  pattern["tessellation"] = std::string(tessellation_name(design.pattern.tessellation));
  pattern["spacing"] = design.pattern.spacing;
  pattern["bracing"] = design.pattern.bracing;
  pattern["operators"] = std::move(operators);
  pattern["topology"] = std::string(topology_name(design.pattern.topology));

  const ElementsDesign& elements = design.elements;
  Json vertex = Json::object();
  vertex["enabled"] = elements.vertex.enabled;
  vertex["scale"] = elements.vertex.scale;
  vertex["shape"] = std::string(shape_name(elements.vertex.shape));
  Json edges = Json::array();
  for (const EdgeElementDesign& edge : elements.edge) {
    Json item = Json::object();
    item["t"] = edge.t;
    item["scale"] = edge.scale;
    item["shape"] = std::string(shape_name(edge.shape));
    item["cell_edges"] = edge.cell_edges;
    edges.push_back(std::move(item));
  }
  Json elements_json = Json::object();
  elements_json["vertex"] = std::move(vertex);
  elements_json["edge"] = std::move(edges);
  elements_json["custom_shape"] = elements.custom_shape;
  elements_json["allow_overlap"] = elements.allow_overlap;
  elements_json["gap"] = elements.gap;
  elements_json["margin"] = elements.margin;
  elements_json["rim_rows"] = std::string(rim_rows_name(elements.rim_rows));
  elements_json["beads"] = Json{{"enabled", elements.beads.enabled}, {"scale", elements.beads.scale}};

  Json placement = Json::object();
  placement["offset"] = Json::array({design.placement.offset.x, design.placement.offset.y});
  placement["rotation_deg"] = design.placement.rotation_deg;
  placement["scale"] = design.placement.scale;
  placement["band_rows"] = std::string(band_rows_name(design.placement.band_rows));
  placement["cut_axis"] = std::string(cut_axis_name(design.placement.cut_axis));
  placement["align"] = std::string(align_axis_name(design.placement.align));
  placement["fit_offset"] = design.placement.fit_offset;

  Json solver = Json::object();
  for (const SolverParameter& p : solver_parameters()) {
    std::visit(
        [&](auto member) {
          const auto value = design.solver.*member;
          if constexpr (std::is_same_v<decltype(value), const FilterBase>)
            solver[std::string(p.name)] = std::string(filter_base_name(value));
          else
            solver[std::string(p.name)] = value;
        },
        p.member);
  }

  Json moved = Json::array(), deleted = Json::array(), added = Json::array();
  for (const MovedParticle& m : design.edits.moved)
    moved.push_back(Json{{"id", m.id}, {"uv", Json::array({m.uv.x, m.uv.y})}, {"pinned", m.pinned}});
  for (const DeletedElement& d : design.edits.deleted)
    deleted.push_back(Json{{"id", d.id}, {"uv", Json::array({d.uv.x, d.uv.y})}});
  for (const AddedElement& a : design.edits.added)
    added.push_back(Json{{"id", a.id}, {"uv", Json::array({a.uv.x, a.uv.y})}});
  Json edits = Json::object();
  edits["moved"] = std::move(moved);
  edits["deleted"] = std::move(deleted);
  edits["added"] = std::move(added);

  Json root = Json::object();
  root["version"] = Design::kVersion;
  root["units"] = std::string(units_name(design.units));
  root["pattern"] = std::move(pattern);
  root["elements"] = std::move(elements_json);
  root["placement"] = std::move(placement);
  root["solver"] = std::move(solver);
  root["edits"] = std::move(edits);
  Json guidance = Json::array();
  for (const GuidanceDab& d : design.guidance)
    guidance.push_back(Json{{"uv", Json::array({d.uv.x, d.uv.y})}, {"radius", d.radius}, {"strength", d.strength}});
  root["guidance"] = std::move(guidance);
  return root;
}

// parse_error::byte counts the bytes read, the offending one included (1-based).
std::string line_and_column(std::string_view text, size_t byte) {
  const size_t position = std::min(byte == 0 ? 0 : byte - 1, text.size());
  size_t line = 1, line_start = 0;
  for (size_t i = 0; i < position; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return std::to_string(line) + ":" + std::to_string(position - line_start + 1);
}

// nlohmann's message is "[json.exception.parse_error.101] parse error at line 4, column 20: syntax
// error while parsing object key - unexpected ','; expected string literal"; keep what went wrong.
std::string short_reason(const std::string& what) {
  std::string reason = what;
  const size_t colon = reason.find(": ", reason.find("parse error"));
  if (colon != std::string::npos) reason = reason.substr(colon + 2);
  const size_t dash = reason.find(" - ");
  if (dash != std::string::npos) reason = reason.substr(dash + 3);
  return reason;
}

std::string read_design_text(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found)
    throw InputError(source + ": no such design file");
  if (status.type() == std::filesystem::file_type::directory)
    throw InputError(source + ": is a folder, not a design file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const std::string why = error ? " (" + error.message() + ")" : "";
    throw InputError(source + ": cannot open the design file for reading" + why);
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(source + ": could not read the design file");
  return std::move(text).str();
}

}  // namespace

Design design_from_json(const nlohmann::json& json, const std::string& source, std::vector<std::string>* notes) {
  const Reader reader(source);
  if (!json.is_object()) reader.fail(std::string("the design must be a JSON object, got ") + json.type_name());
  // The version comes first: a newer file's new keys should not be reported as unknown.
  const auto version = json.find("version");
  if (version == json.end())
    reader.fail("missing key 'version'; this build reads design files of version " +
                std::to_string(Design::kVersion));
  int number = 0;
  reader.read(*version, "version", number);
  if (number < Design::kOldestVersion || number > Design::kVersion)
    reader.fail("'version' is " + std::to_string(number) + ", but this build reads versions " +
                std::to_string(Design::kOldestVersion) + " to " + std::to_string(Design::kVersion));

  reader.check_object(json, "", {"version", "units", "pattern", "elements", "placement", "solver", "edits", "guidance"});
  Design design;
  reader.field(json, "", "units", design.units);
  reader.field(json, "", "pattern", design.pattern);
  reader.field(json, "", "elements", design.elements);
  reader.field(json, "", "placement", design.placement);
  reader.field(json, "", "solver", design.solver);
  reader.field(json, "", "edits", design.edits);
  reader.field(json, "", "guidance", design.guidance);
  validate_design(design, source);
  // Version 1 files were saved with every parameter, so a 0.5 there is most likely that version's
  // default rather than a choice: kept as saved (a design reproduces its pavement), and said.
  if (notes && number == 1 && design.solver.mu_stretched == 0.5 && json.contains("solver") &&
      json.at("solver").is_object() && json.at("solver").contains("mu_stretched"))
    notes->push_back(source + ": saved by an earlier Paver (design version 1), whose default solver.mu_stretched "
                              "was 0.5; the design keeps it. Today's default, 0.75, leaves large lattices fuller "
                              "(docs/parameters.md): set it, or remove the key, to use it");
  return design;
}

nlohmann::json design_to_json(const Design& design) { return to_json<nlohmann::json>(design); }

Design design_from_text(std::string_view text, const std::string& source, std::vector<std::string>* notes) {
  nlohmann::json json;
  // A key given twice in one object: JSON keeps the last without a word, so a designer's earlier
  // value was silently lost. Refused, naming the key by its path.
  struct OpenObject {
    std::set<std::string> keys;
    std::string last;
  };
  std::vector<OpenObject> open;
  std::string duplicate;
  const nlohmann::json::parser_callback_t find_duplicates = [&](int, nlohmann::json::parse_event_t event,
                                                                 nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open.emplace_back();
    if (event == Event::object_end && !open.empty()) open.pop_back();
    if (event == Event::key && !open.empty() && parsed.is_string()) {
      const std::string key = parsed.get<std::string>();
      if (!open.back().keys.insert(key).second && duplicate.empty())
        for (const OpenObject& o : open) duplicate += (duplicate.empty() ? "" : ".") + (&o == &open.back() ? key : o.last);
      open.back().last = key;
    }
    return true;
  };
  try {
    json = nlohmann::json::parse(text, find_duplicates);
    if (!duplicate.empty())
      throw InputError(source + ": '" + duplicate + "' is given twice; JSON keeps only the last, so remove one of them");
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(source + ":" + line_and_column(text, error.byte) + ": JSON syntax error: " +
                     short_reason(error.what()));
  } catch (const nlohmann::json::out_of_range& error) {
    // A number beyond double's range (1e999): nlohmann reports no position, only the number.
    std::string reason = error.what();  // "[json.exception.out_of_range.406] number overflow parsing '1e999'"
    const size_t bracket = reason.find("] ");
    if (bracket != std::string::npos) reason = reason.substr(bracket + 2);
    throw InputError(source + ": " + reason + "; numbers must be finite (at most about 1.8e308)");
  }
  return design_from_json(json, source, notes);
}

Design load_design(const std::filesystem::path& path, std::vector<std::string>* notes) {
  Design design = design_from_text(read_design_text(path), path.string(), notes);

  // A relative custom shape path means "beside the design file", wherever the program runs from.
  const std::filesystem::path shape = design.elements.custom_shape;
  if (!shape.empty() && shape.is_relative()) {
    std::error_code error;
    std::filesystem::path folder = std::filesystem::absolute(path, error).parent_path();
    if (error) folder = path.parent_path();
    design.elements.custom_shape = (folder / shape).lexically_normal().string();
  }
  return design;
}

namespace {
// The custom shape as the saved file should name it: relative to the file's folder when the shape
// is near it (in it, below it, or up to two folders above: one project that travels as a whole,
// and load_design reads a relative path so), otherwise absolute as it is.
std::string custom_shape_as_saved(const std::filesystem::path& design_path, const std::string& shape) {
  namespace fs = std::filesystem;
  if (shape.empty() || !fs::path(shape).is_absolute()) return shape;
  std::error_code error;
  const fs::path folder = fs::absolute(design_path, error).parent_path().lexically_normal();
  if (error) return shape;
  const fs::path relative = fs::path(shape).lexically_normal().lexically_relative(folder);
  if (relative.empty()) return shape;
  int ups = 0;
  for (const fs::path& part : relative) ups += part == "..";
  return ups <= 2 ? relative.generic_string() : shape;
}
}  // namespace

void save_design(const std::filesystem::path& path, const Design& design) {
  Design saved = design;
  saved.elements.custom_shape = custom_shape_as_saved(path, design.elements.custom_shape);
  write_text_atomically(path, to_json<nlohmann::ordered_json>(saved).dump(2) + "\n");
}

}  // namespace paver
