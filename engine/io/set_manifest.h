#pragma once
// The manifest of an output set, `.paver-files`: which files of a folder a Paver run made, and so
// which files a later run may replace or remove. Nothing else in a folder is ever removed.
//
//   # paver output set; token=<16 hex digits> pid=<process id>
//   file <name>        one line per file of the set
//   old <name>         the previous set's files this publish swaps out (a record for recovery)
//   borrowed <name>    an entry of the user's moved into the staging folder to be swapped back in
//
// The token is also the end of the staging folder's name: it is the marker that proves a staging
// folder ours (a folder of that name without a manifest bearing the token is the user's). Manifests
// from before tokens are one file name a line, read as `file` lines.
#include <filesystem>
#include <string>
#include <vector>

namespace paver {

inline constexpr const char* kSetManifestName = ".paver-files";

struct SetManifest {
  bool found = false;  // a manifest exists (a legacy one counts)
  std::string token;   // empty in a legacy manifest
  long pid = 0;
  std::vector<std::string> files, old, borrowed;
};

// The manifest in `folder`, or one with found == false when there is none. Throws InputError
// naming it when `.paver-files` is there but is not a regular file (a folder, a pipe, a link: never
// followed nor opened), or is larger than a manifest can be.
SetManifest read_set_manifest(const std::filesystem::path& folder);

std::string set_manifest_text(const SetManifest& manifest);

// 16 random hex digits.
std::string random_token();

// Whether `name` is listed in `names`.
bool has_name(const std::vector<std::string>& names, const std::string& name);

}  // namespace paver
