#include "file_browser.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;

// A folder of a few files and sub-folders, removed afterwards.
class FileBrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("paver_browser_" + std::to_string(getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "rings");
    fs::create_directories(root_ / "Archive");
    fs::create_directories(root_ / ".cache");
    for (const char* name : {"pendant.OBJ", "bead.stl", "notes.txt", "b.json", "A.json", ".hidden.obj"})
      std::ofstream(root_ / name) << "x";
    std::ofstream(root_ / "rings" / "band.ply") << "ply";
  }
  void TearDown() override { fs::remove_all(root_); }

  static std::vector<std::string> names(const FileBrowser& b) {
    std::vector<std::string> out;
    for (const BrowserEntry& e : b.entries) out.push_back(e.name);
    return out;
  }

  fs::path root_;
};

TEST_F(FileBrowserTest, ListsFoldersFirstThenTheFilesOfTheKindAsked) {
  FileBrowser b;
  start_browsing(b, BrowsePurpose::OpenSurface, root_);
  EXPECT_EQ(b.folder, fs::canonical(root_));
  EXPECT_EQ(names(b), (std::vector<std::string>{"Archive", "rings", "bead.stl", "pendant.OBJ"}))
      << "folders first, case-blind order, only mesh files, no dot-files";
  EXPECT_TRUE(b.entries[0].folder);
  EXPECT_EQ(b.entries[2].bytes, 1u);
  b.show_hidden = true;
  show_folder(b, ".");
  EXPECT_EQ(names(b), (std::vector<std::string>{".cache", "Archive", "rings", ".hidden.obj", "bead.stl", "pendant.OBJ"}));

  b.show_hidden = false;  // a preference: the next dialog keeps it
  start_browsing(b, BrowsePurpose::LoadDesign, root_);
  EXPECT_EQ(names(b), (std::vector<std::string>{"Archive", "rings", "A.json", "b.json"}));
}

TEST_F(FileBrowserTest, DoubleClickEntersAFolderAndChoosesAFile) {
  FileBrowser b;
  start_browsing(b, BrowsePurpose::OpenSurface, root_ / "pendant.OBJ");
  EXPECT_EQ(b.folder, fs::canonical(root_)) << "a file's own folder";
  EXPECT_FALSE(activate(b, {"rings", true, 0}));
  EXPECT_EQ(b.folder, fs::canonical(root_ / "rings"));
  EXPECT_EQ(names(b), (std::vector<std::string>{"band.ply"}));
  EXPECT_EQ(activate(b, b.entries[0]), fs::canonical(root_ / "rings" / "band.ply"));
  show_parent_folder(b);
  EXPECT_EQ(b.folder, fs::canonical(root_));
}

TEST_F(FileBrowserTest, AFolderThatCannotBeListedLeavesTheDialogWhereItWasAndSaysWhy) {
  FileBrowser b;
  start_browsing(b, BrowsePurpose::OpenSurface, root_);
  show_folder(b, "no_such_folder");
  EXPECT_EQ(b.folder, fs::canonical(root_));
  EXPECT_NE(b.problem.find("no_such_folder"), std::string::npos) << b.problem;
  EXPECT_EQ(names(b).size(), 4u);
}

TEST_F(FileBrowserTest, OkNeedsAFileThatExistsToOpenAndAddsJsonToASave) {
  FileBrowser b;
  start_browsing(b, BrowsePurpose::LoadDesign, root_);
  EXPECT_FALSE(chosen_path(b)) << "no name yet";
  EXPECT_FALSE(b.problem.empty());
  b.name = "missing.json";
  EXPECT_FALSE(chosen_path(b));
  EXPECT_NE(b.problem.find("does not exist"), std::string::npos) << b.problem;
  b.name = "rings";
  EXPECT_FALSE(chosen_path(b)) << "a folder is not a design";
  b.name = "A.json";
  EXPECT_EQ(chosen_path(b), fs::canonical(root_ / "A.json"));

  start_browsing(b, BrowsePurpose::SaveDesign, root_ / "pendant_v2.json");
  EXPECT_EQ(b.name, "pendant_v2.json") << "a save starts from the current name";
  b.name = "pendant_v3";
  EXPECT_EQ(chosen_path(b), fs::canonical(root_) / "pendant_v3.json") << "a new file, .json added";
  b.name = "pendant.OBJ";
  EXPECT_FALSE(chosen_path(b)) << "a design never goes over a mesh";
  EXPECT_NE(b.problem.find("ends in .json"), std::string::npos) << b.problem;

  start_browsing(b, BrowsePurpose::ExportFolder, root_ / "rings");
  EXPECT_EQ(b.folder, fs::canonical(root_ / "rings"));
  EXPECT_EQ(chosen_path(b), fs::canonical(root_ / "rings")) << "the folder shown";
  b.name = "out";
  EXPECT_EQ(chosen_path(b), fs::canonical(root_ / "rings") / "out") << "or a new one inside it";
}

}  // namespace
}  // namespace paver::studio
