#include "file_browser.h"

#include "core/input_error.h"
#include "mesh/read_mesh_file.h"

#include <algorithm>
#include <cctype>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

bool wants_file(BrowsePurpose purpose) { return purpose != BrowsePurpose::ExportFolder; }

}  // namespace

std::vector<std::string> browse_extensions(BrowsePurpose purpose) {
  switch (purpose) {
    case BrowsePurpose::OpenSurface:
    case BrowsePurpose::CustomShape: {
      const auto formats = mesh_file_extensions();  // what read_mesh_file reads
      return {formats.begin(), formats.end()};
    }
    case BrowsePurpose::LoadDesign:
    case BrowsePurpose::SaveDesign: return {".json"};
    case BrowsePurpose::ExportFolder: return {};
  }
  return {};
}

const char* browse_title(BrowsePurpose purpose) {
  switch (purpose) {
    case BrowsePurpose::OpenSurface: return "Open a surface";
    case BrowsePurpose::LoadDesign: return "Load a design";
    case BrowsePurpose::SaveDesign: return "Save the design as";
    case BrowsePurpose::ExportFolder: return "Export into a folder";
    case BrowsePurpose::CustomShape: return "The custom element shape";
  }
  return "Choose a file";
}

std::optional<BrowsePurpose> browse_purpose_from_name(std::string_view name) {
  if (name == "surface") return BrowsePurpose::OpenSurface;
  if (name == "design") return BrowsePurpose::LoadDesign;
  if (name == "save") return BrowsePurpose::SaveDesign;
  if (name == "export") return BrowsePurpose::ExportFolder;
  if (name == "shape") return BrowsePurpose::CustomShape;
  return std::nullopt;
}

std::vector<BrowserEntry> list_folder(const fs::path& folder, const std::vector<std::string>& extensions,
                                      bool show_hidden) {
  std::error_code error;
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, error);
  if (error) throw InputError(folder.string() + ": cannot list this folder (" + error.message() + ")");
  std::vector<BrowserEntry> folders, files;
  for (; it != fs::directory_iterator(); it.increment(error)) {
    if (error) throw InputError(folder.string() + ": cannot list this folder (" + error.message() + ")");
    const std::string name = it->path().filename().string();
    if (!show_hidden && name.starts_with('.')) continue;
    std::error_code kind_error;  // a dangling link or a file gone meanwhile is left out, not fatal
    if (it->is_directory(kind_error)) {
      folders.push_back({name, true, 0});
    } else if (it->is_regular_file(kind_error) &&
               std::ranges::find(extensions, lowercase(it->path().extension().string())) != extensions.end()) {
      const std::uintmax_t bytes = it->file_size(kind_error);
      files.push_back({name, false, kind_error ? 0 : bytes});
    }
  }
  const auto by_name = [](const BrowserEntry& a, const BrowserEntry& b) {
    const std::string la = lowercase(a.name), lb = lowercase(b.name);
    return la != lb ? la < lb : a.name < b.name;
  };
  std::ranges::sort(folders, by_name);
  std::ranges::sort(files, by_name);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

void show_folder(FileBrowser& browser, const fs::path& folder) {
  std::error_code error;
  const fs::path target = fs::weakly_canonical(browser.folder / folder, error);
  if (error) {
    browser.problem = (browser.folder / folder).string() + ": " + error.message();
    return;
  }
  try {
    browser.entries = list_folder(target, browse_extensions(browser.purpose), browser.show_hidden);
    browser.folder = target;
    browser.problem.clear();
  } catch (const std::exception& e) {
    browser.problem = e.what();
  }
}

void show_parent_folder(FileBrowser& browser) {
  if (browser.folder.has_parent_path() && browser.folder.parent_path() != browser.folder)
    show_folder(browser, browser.folder.parent_path());
}

void start_browsing(FileBrowser& browser, BrowsePurpose purpose, const fs::path& current) {
  browser.purpose = purpose;
  browser.open = true;
  browser.name.clear();
  browser.problem.clear();
  std::error_code error;
  fs::path start = fs::current_path(error);
  if (!current.empty()) {
    const fs::path absolute = fs::absolute(current, error);
    if (fs::is_directory(absolute, error)) {
      start = absolute;
    } else if (fs::is_directory(absolute.parent_path(), error)) {
      start = absolute.parent_path();
      if (wants_file(purpose)) browser.name = absolute.filename().string();
    }
  }
  browser.folder = start;
  show_folder(browser, ".");
}

std::optional<fs::path> activate(FileBrowser& browser, const BrowserEntry& entry) {
  if (entry.folder) {
    show_folder(browser, entry.name);
    return std::nullopt;
  }
  browser.name = entry.name;
  return chosen_path(browser);
}

std::optional<fs::path> chosen_path(FileBrowser& browser) {
  if (!wants_file(browser.purpose)) return browser.name.empty() ? browser.folder : browser.folder / browser.name;
  if (browser.name.empty()) {
    browser.problem = "type a file name or click a file";
    return std::nullopt;
  }
  fs::path path = browser.folder / browser.name;
  std::error_code error;
  if (fs::is_directory(path, error)) {
    browser.problem = path.string() + " is a folder: double-click it to look inside";
    return std::nullopt;
  }
  if (browser.purpose == BrowsePurpose::SaveDesign) {
    if (!path.has_extension()) path += ".json";
    // A design is JSON: a name ending otherwise would write JSON over a mesh or an image.
    if (path.extension() != ".json") {
      browser.problem = path.filename().string() + ": a design file's name ends in .json";
      return std::nullopt;
    }
  }
  if (browser.purpose != BrowsePurpose::SaveDesign && !fs::exists(path, error)) {
    browser.problem = path.string() + " does not exist";
    return std::nullopt;
  }
  browser.problem.clear();
  return path.lexically_normal();
}

}  // namespace paver::studio
