#pragma once
// The studio's file dialog, without its drawing: which folder it shows, what it lists (folders
// first, then the files of the kind asked for), where a double click goes, and the path chosen.
// panels/file_dialog.cpp draws it with ImGui; tests drive this part directly.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver::studio {

// What the dialog is choosing, and so which files it lists and what OK does.
enum class BrowsePurpose { OpenSurface, LoadDesign, SaveDesign, ExportFolder, CustomShape };

struct BrowserEntry {
  std::string name;
  bool folder = false;
  std::uintmax_t bytes = 0;  // files only
};

struct FileBrowser {
  BrowsePurpose purpose = BrowsePurpose::OpenSurface;
  bool open = false;
  std::filesystem::path folder;     // absolute
  std::string name;                 // the file name typed or clicked (a save's new name)
  std::vector<BrowserEntry> entries;
  std::string problem;              // why the folder could not be listed, or why OK cannot go on
  bool show_hidden = false;
};

// The file extensions a purpose lists (lower case, with the dot); empty for folders.
std::vector<std::string> browse_extensions(BrowsePurpose purpose);
const char* browse_title(BrowsePurpose purpose);
// "surface", "design", "save", "export", "shape" (the script's `browse` names); none for others.
std::optional<BrowsePurpose> browse_purpose_from_name(std::string_view name);

// A folder's entries that the purpose can use: sub-folders, then files with one of `extensions`
// (any case), each group sorted by name without regard to case; dot-files only when asked.
// Throws InputError naming the folder when it cannot be read.
std::vector<BrowserEntry> list_folder(const std::filesystem::path& folder, const std::vector<std::string>& extensions,
                                      bool show_hidden);

// Opens the dialog at `current`'s folder (a file's parent, or the folder itself) or, when that
// does not exist, at the working folder; a save starts with `current`'s file name.
void start_browsing(FileBrowser& browser, BrowsePurpose purpose, const std::filesystem::path& current);
// Shows another folder (absolute, or relative to the one shown); a folder that cannot be listed
// leaves the dialog where it was and says why in `problem`.
void show_folder(FileBrowser& browser, const std::filesystem::path& folder);
void show_parent_folder(FileBrowser& browser);
// A double click: a folder is entered, a file is chosen (returned).
std::optional<std::filesystem::path> activate(FileBrowser& browser, const BrowserEntry& entry);
// OK: the path chosen, or nothing (with `problem` set) when the name is empty or names a folder.
// A save gets ".json" when its name has no extension; an export folder is the folder shown (or
// the sub-folder named, created later by the export).
std::optional<std::filesystem::path> chosen_path(FileBrowser& browser);

}  // namespace paver::studio
