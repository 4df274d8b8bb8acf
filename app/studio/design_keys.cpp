#include "design_keys.h"
#include "design/design_keys.h"

#include "io/design_io.h"
#include "core/input_error.h"

#include <nlohmann/json.hpp>

#include <cctype>

namespace paver::studio {

std::string design_key_pointer(std::string_view key) {
  const std::string name(key);
  if (key.empty())
    throw InputError("set: the key is empty; keys look like " + key_path(Key::solver_dt) + " or " +
                     key_path(Key::edge_t, 0));
  std::string pointer = "/";
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '.') {
      if (pointer.back() == '/') throw InputError("set " + name + ": empty part in the key");
      pointer += '/';
    } else if (c == '[') {
      const std::size_t close = key.find(']', i);
      if (close == std::string_view::npos || close == i + 1) throw InputError("set " + name + ": unclosed '['");
      for (std::size_t k = i + 1; k < close; ++k)
        if (!std::isdigit(static_cast<unsigned char>(key[k])))
          throw InputError("set " + name + ": an index in [] must be a number");
      if (pointer.back() != '/') pointer += '/';
      pointer += key.substr(i + 1, close - i - 1);
      i = close;
    } else if (c == '/' || c == '~') {
      throw InputError("set " + name + ": use dots between the parts of a key (" + key_path(Key::solver_dt) + ")");
    } else {
      pointer += c;
    }
  }
  if (pointer.back() == '/') throw InputError("set " + name + ": the key ends with a dot");
  return pointer;
}

Design set_design_key(const Design& design, std::string_view key, std::string_view value) {
  const std::string name(key);
  const nlohmann::json::json_pointer pointer(design_key_pointer(key));
  nlohmann::json json = design_to_json(design);
  if (!json.contains(pointer) || pointer.empty())
    throw InputError("set " + name + ": no such design key; keys are those of design.json (docs/design_file.md), e.g. " +
                     key_path(Key::solver_dt) + ", " + key_path(Key::pattern_spacing) + ", " +
                     key_path(Key::vertex_scale) + ", " + key_path(Key::rotation_deg));
  nlohmann::json parsed = nlohmann::json::parse(value.begin(), value.end(), nullptr, false);
  if (parsed.is_discarded()) parsed = std::string(value);
  json[pointer] = std::move(parsed);
  return design_from_json(json, "set " + name);  // validates too
}

}  // namespace paver::studio
