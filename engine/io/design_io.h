#pragma once
// design.json: the file form of Design. Version 1. Unknown keys and out-of-range values are
// errors that name the key ("pattern.operators[2].offset: ..."); missing keys take defaults.
#include "design/design.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace paver {

Design design_from_json(const nlohmann::json& json, const std::string& source);
nlohmann::json design_to_json(const Design& design);

// Parses and reads a design file's text; `source` names it in errors. Syntax errors name the
// line and column.
Design design_from_text(std::string_view text, const std::string& source);

// Reads and validates a design file. Syntax errors name the line and column.
Design load_design(const std::filesystem::path& path);
void save_design(const std::filesystem::path& path, const Design& design);  // atomic

}  // namespace paver
