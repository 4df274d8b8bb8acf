#pragma once
// The bundled designs and the surface each is for, read from the table in
// assets/designs/README.md (one place says which surface a design belongs to). Used by the tests
// and the benchmarks.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

namespace paver::test {

// design file name (e.g. "dome_hex_d6.json") -> surface file name (e.g. "dome.obj").
inline std::map<std::string, std::string> bundled_design_surfaces(const std::filesystem::path& source_dir) {
  std::ifstream readme(source_dir / "assets/designs/README.md");
  std::map<std::string, std::string> out;
  const std::regex row(R"(^\|\s*([a-z0-9_]+\.json)\s*\|\s*([a-z0-9_]+\.obj)\s*\|)");
  std::string line;
  std::smatch match;
  while (std::getline(readme, line))
    if (std::regex_search(line, match, row)) out[match[1]] = match[2];
  return out;
}

}  // namespace paver::test
