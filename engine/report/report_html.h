#pragma once
// report.html: the run's report for people, printable on one or two pages: the verdict, the
// bill of stones, the beads, the metal and its weight (with --subtract), the quality figures and
// the preview picture (embedded, so the file stands alone), all taken from report.json's content
// so that the two never disagree.
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>

namespace paver {

// `report`: report.json's content; `preview_png`: the PNG's bytes, or empty for none (then the
// page says how to get one).
std::string report_html(const nlohmann::json& report, const std::string& preview_png);

// Writes `folder`/report.html from `report`, embedding `folder`/preview.png when it exists.
void write_report_html(const std::filesystem::path& folder, const nlohmann::json& report);

// RFC 4648 base64, for the embedded picture.
std::string base64(const std::string& bytes);

}  // namespace paver
