#include "io/design_io.h"

#include "core/closest_name.h"
#include "core/input_error.h"
#include "core/regular_file.h"
#include "design/design_keys.h"
#include "io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

namespace paver {
namespace {

using nlohmann::json;

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string indexed(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

// The last part of a key's path: "elements.edge[].t" -> "t".
std::string_view leaf(Key key) {
  const std::string_view path = design_key(key).path;
  return path.substr(path.find_last_of('.') + 1);
}

// The names an object at `parent` (a table path: "", "elements", "pattern.operators[]") may hold,
// in the table's order.
std::vector<std::string_view> known_children(std::string_view parent) {
  std::vector<std::string_view> known;
  if (parent.empty()) known.push_back("version");
  const std::string prefix = parent.empty() ? "" : std::string(parent) + ".";
  for (const DesignKey& row : design_keys()) {
    if (!row.path.starts_with(prefix)) continue;
    std::string_view rest = row.path.substr(prefix.size());
    rest = rest.substr(0, rest.find_first_of(".["));
    if (std::find(known.begin(), known.end(), rest) == known.end()) known.push_back(rest);
  }
  return known;
}

// An object that holds keys of its own without being one ("elements", "elements.vertex").
bool is_group(std::string_view path) {
  return find_design_key(path) == nullptr && !known_children(path).empty();
}

// Reads design.json values into Design fields, by the design key table. Every error names the
// source and the full key path ("pattern.operators[2].offset") so the user can find the line.
class Reader {
public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& message) const { throw InputError(source_ + ": " + message); }

  [[noreturn]] void wrong_type(const json& value, const std::string& path, std::string_view expected) const {
    fail("'" + path + "' must be " + std::string(expected) + ", got " + value.type_name());
  }

  // Every key of `value` (at table path `shape`, written `path`) known, and every group in it an
  // object whose keys are known too.
  void check_keys(const json& value, const std::string& shape, const std::string& path) const {
    if (!value.is_object()) wrong_type(value, path, "an object");
    const std::vector<std::string_view> known = known_children(shape);
    for (const auto& item : value.items()) {
      const std::string& key = item.key();
      if (std::find(known.begin(), known.end(), key) == known.end())
        fail("unknown key '" + join(path, key) + "'" + suggestion(key, path, known));
      if (is_group(join(shape, key))) check_keys(item.value(), join(shape, key), join(path, key));
    }
  }

  // Every key of the design that the file gives, read into `design`.
  void read_design(const json& root, Design& design) const {
    visit_keys(design, [&](Key key, auto& field) {
      const json* value = &root;
      const std::string_view path = design_key(key).path;
      for (std::size_t start = 0; value;) {  // down the groups, which check_keys found objects
        const std::size_t dot = path.find('.', start);
        const auto it = value->find(std::string(path.substr(start, dot - start)));
        value = it == value->end() ? nullptr : &*it;
        if (dot == std::string_view::npos) break;
        start = dot + 1;
      }
      if (value) read(*value, std::string(path), field);
    });
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

  template <NamedEnum E>
  void read(const json& value, const std::string& path, E& out) const {
    if (!value.is_string()) wrong_type(value, path, "a string");
    if (const std::optional<E> named = enum_from_name<E>(value.get<std::string>())) {
      out = *named;
      return;
    }
    fail("'" + path + "' must be one of " + enum_choices_quoted<E>() + ", got " + value.dump());
  }

  template <class Number>
    requires std::is_same_v<Number, int> || std::is_same_v<Number, double>
  void read(const json& value, const std::string& path, std::vector<Number>& out) const {
    if (!value.is_array()) wrong_type(value, path, "an array");
    out.assign(value.size(), 0);
    for (size_t i = 0; i < value.size(); ++i) read(value[i], indexed(path, i), out[i]);
  }

  // An array of objects whose fields are keys of their own (operators, edits, dabs).
  template <class Item>
  void read(const json& value, const std::string& path, std::vector<Item>& out) const {
    if (!value.is_array()) wrong_type(value, path, "an array");
    out.assign(value.size(), Item{});
    for (size_t i = 0; i < value.size(); ++i) {
      const std::string at = indexed(path, i);
      check_keys(value[i], path + "[]", at);
      visit_item_keys(out[i], [&](Key key, auto& field) {
        const auto it = value[i].find(std::string(leaf(key)));
        if (it != value[i].end())
          read(*it, join(at, leaf(key)), field);
        else if (design_key(key).required)
          fail("missing key '" + join(at, leaf(key)) + "'");
      });
    }
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

  // " (did you mean 'pattern.spacing'?)" when a known key is a likely misspelling of `key`.
  static std::string suggestion(const std::string& key, const std::string& path,
                                const std::vector<std::string_view>& known) {
    if (const std::optional<std::string> best = closest_name(key, known))
      return " (did you mean '" + join(path, *best) + "'?)";
    std::string list;
    for (std::string_view candidate : known) list += (list.empty() ? "" : ", ") + std::string(candidate);
    return "; known keys here: " + list;
  }

  const std::string& source_;
};

// A key's value as design.json writes it.
template <class Json, class T>
Json value_json(const T& value) {
  if constexpr (NamedEnum<T>) {
    return std::string(enum_name(value));
  } else if constexpr (std::is_same_v<T, glm::dvec2> || std::is_same_v<T, glm::ivec2>) {
    return Json::array({value.x, value.y});
  } else if constexpr (std::is_same_v<T, std::vector<int>> || std::is_same_v<T, std::vector<double>> ||
                       std::is_arithmetic_v<T> ||
                       std::is_same_v<T, std::string>) {
    return value;
  } else {  // an array of objects
    Json items = Json::array();
    for (const auto& item : value) {
      Json object = Json::object();
      visit_item_keys(item, [&](Key key, const auto& field) { object[std::string(leaf(key))] = value_json<Json>(field); });
      items.push_back(std::move(object));
    }
    return items;
  }
}

// Builds the complete design, every key written, in the table's order. Templated on the JSON
// type so that files are written with nlohmann::ordered_json, keeping that order.
template <class Json>
Json to_json(const Design& design) {
  Json root = Json::object();
  root["version"] = Design::kVersion;
  visit_keys(design, [&](Key key, const auto& value) {
    Json* at = &root;
    const std::string_view path = design_key(key).path;
    for (std::size_t start = 0;;) {
      const std::size_t dot = path.find('.', start);
      at = &(*at)[std::string(path.substr(start, dot - start))];
      if (dot == std::string_view::npos) break;
      start = dot + 1;
    }
    *at = value_json<Json>(value);
  });
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
  return read_regular_file(path, kMaxDesignFileBytes, path.string(), "design file",
                           "a design is a few kilobytes; give the design's .json file");
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

  reader.check_keys(json, "", "");
  Design design;
  reader.read_design(json, design);
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

namespace {

// A key given twice in one object: JSON keeps the last without a word, so a designer's earlier
// value was silently lost. Found in a SAX pass of its own, linear in the file: nlohmann's
// callback parser, which did this before, scans an array's elements again at the end of each
// object in it (300,000 deletions took 24 s).
struct DuplicateKeyFinder {
  struct OpenObject {
    std::set<std::string> keys;
    std::string last;
  };
  std::vector<OpenObject> open;
  std::string duplicate;  // the first key given twice, by its path

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(nlohmann::json::number_integer_t) { return true; }
  bool number_unsigned(nlohmann::json::number_unsigned_t) { return true; }
  bool number_float(nlohmann::json::number_float_t, const std::string&) { return true; }
  bool string(std::string&) { return true; }
  bool binary(nlohmann::json::binary_t&) { return true; }
  bool start_object(std::size_t) {
    open.emplace_back();
    return true;
  }
  bool key(std::string& key) {
    if (!open.back().keys.insert(key).second) {
      for (const OpenObject& o : open) duplicate += (duplicate.empty() ? "" : ".") + (&o == &open.back() ? key : o.last);
      return false;  // one is enough
    }
    open.back().last = key;
    return true;
  }
  bool end_object() {
    open.pop_back();
    return true;
  }
  bool start_array(std::size_t) { return true; }
  bool end_array() { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }
};

}  // namespace

Design design_from_text(std::string_view text, const std::string& source, std::vector<std::string>* notes) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
    DuplicateKeyFinder finder;
    nlohmann::json::sax_parse(text, &finder);
    if (!finder.duplicate.empty())
      throw InputError(source + ": '" + finder.duplicate + "' is given twice; JSON keeps only the last, so remove one of them");
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
