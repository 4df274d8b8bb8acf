#pragma once
// design.json: the file form of Design. Version 3 (1 and 2 are read too: Design::kVersion). Unknown keys and out-of-range values are
// errors that name the key ("pattern.operators[2].offset: ..."); missing keys take defaults.
#include "design/design.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

// `notes` (when given) receives what a user should know about an older file: a version 1 file
// holding solver.mu_stretched 0.5, that version's default, keeps it (today's default is 0.75).
Design design_from_json(const nlohmann::json& json, const std::string& source,
                        std::vector<std::string>* notes = nullptr);
nlohmann::json design_to_json(const Design& design);

// Parses and reads a design file's text; `source` names it in errors. Syntax errors name the
// line and column.
Design design_from_text(std::string_view text, const std::string& source, std::vector<std::string>* notes = nullptr);

// The largest design file read (a million edits is about 10 MiB); a larger file, a pipe or a device
// is refused before reading.
constexpr std::uintmax_t kMaxDesignFileBytes = std::uintmax_t(64) << 20;

// Reads and validates a design file. Syntax errors name the line and column.
Design load_design(const std::filesystem::path& path, std::vector<std::string>* notes = nullptr);
void save_design(const std::filesystem::path& path, const Design& design);  // atomic

}  // namespace paver
