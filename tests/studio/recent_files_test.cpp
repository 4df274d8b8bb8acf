#include "recent_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;

TEST(RecentFiles, NewestFirstWithoutRepeatsUpToTheLimit) {
  std::vector<fs::path> recent;
  remember_recent_file(recent, "/a/dome.obj", 3);
  remember_recent_file(recent, "/a/wave.obj", 3);
  remember_recent_file(recent, "/a/dome.obj", 3);
  EXPECT_EQ(recent, (std::vector<fs::path>{"/a/dome.obj", "/a/wave.obj"}));
  remember_recent_file(recent, "/a/b/../vase.obj", 3);
  remember_recent_file(recent, "/a/design.json", 3);
  EXPECT_EQ(recent, (std::vector<fs::path>{"/a/design.json", "/a/vase.obj", "/a/dome.obj"}));
  remember_recent_file(recent, "relative.obj", 3);
  EXPECT_TRUE(recent.front().is_absolute());
}

TEST(RecentFiles, SavedAndLoadedUnderTheConfigFolder) {
  const fs::path config = fs::temp_directory_path() / ("paver_recent_" + std::to_string(getpid()));
  fs::remove_all(config);
  ::setenv("XDG_CONFIG_HOME", config.c_str(), 1);
  const fs::path file = recent_files_path();
  EXPECT_EQ(file, config / "paver/recent.txt");
  EXPECT_TRUE(load_recent_files(file).empty()) << "no list yet is an empty list";
  const std::vector<fs::path> recent = {"/x/dome.obj", "/x/with space.json"};
  save_recent_files(file, recent);  // creates the folders
  EXPECT_EQ(load_recent_files(file), recent);
  fs::remove_all(config);
}

}  // namespace
}  // namespace paver::studio
