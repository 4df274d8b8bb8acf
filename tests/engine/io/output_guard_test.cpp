// Tests for engine/io/output_guard.cpp: refuse_overwriting_inputs refuses an output that is an
// input, however the path is spelled (the same path, "dir/../dir/file", a symbolic link either
// way, a hard link), naming both; it accepts distinct files and outputs that do not exist yet.
// make_output_folder creates nested folders and fails with an InputError naming the folder when a
// file is in the way.
#include "io/output_guard.h"

#include "io/atomic_file.h"

#include "core/input_error.h"

#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace paver {
namespace {

namespace fs = std::filesystem;
using test::Contains;
using test::error_of;

class OutputGuard : public ::testing::Test {
protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("paver_output_guard_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    surface_ = folder_ / "surface.obj";
    design_ = folder_ / "design.json";
    write(surface_, "v 0 0 0\n");
    write(design_, "{}\n");
  }
  void TearDown() override { fs::remove_all(folder_); }

  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

  fs::path folder_, surface_, design_;
};

TEST_F(OutputGuard, RefusesAnOutputThatIsAnInputNamingBoth) {
  const std::string message = error_of([&] { refuse_overwriting_inputs({surface_, design_}, {design_}); });
  EXPECT_TRUE(Contains(message, "refusing to write " + design_.string()));
  EXPECT_TRUE(Contains(message, "it is the input " + design_.string()));
  EXPECT_TRUE(Contains(message, "write the output elsewhere"));
}

TEST_F(OutputGuard, RefusesTheSameFileSpelledDifferently) {
  // dir/../dir/file
  const fs::path roundabout = folder_ / ".." / folder_.filename() / "surface.obj";
  ASSERT_NE(roundabout, surface_);
  EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({surface_}, {roundabout}); }),
                       "refusing to write " + roundabout.string()));
  // dir/./file and a sub-folder's ..
  fs::create_directories(folder_ / "sub");
  for (const fs::path& spelling : {folder_ / "." / "surface.obj", folder_ / "sub" / ".." / "surface.obj"})
    EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({surface_}, {spelling}); }), spelling.string()));
}

TEST_F(OutputGuard, RefusesLinksToAnInputEitherWay) {
  const fs::path symlink = folder_ / "link.obj", hardlink = folder_ / "hard.obj";
  fs::create_symlink(surface_, symlink);
  fs::create_hard_link(surface_, hardlink);
  // The output is a link to the input.
  EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({surface_}, {symlink}); }), symlink.string()));
  EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({surface_}, {hardlink}); }), hardlink.string()));
  // The input was given through the link.
  EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({symlink}, {surface_}); }),
                       "it is the input " + symlink.string()));
  // A link to the folder.
  const fs::path folder_link = folder_ / "folder_link";
  fs::create_directory_symlink(folder_, folder_link);
  EXPECT_TRUE(Contains(error_of([&] { refuse_overwriting_inputs({design_}, {folder_link / "design.json"}); }),
                       (folder_link / "design.json").string()));
}

TEST_F(OutputGuard, AcceptsDistinctFilesAndOutputsThatDoNotExist) {
  const fs::path report = folder_ / "report.json";
  write(report, "{}\n");
  // A file with the same contents is still another file.
  const fs::path copy = folder_ / "copy.obj";
  fs::copy_file(surface_, copy);
  EXPECT_NO_THROW(refuse_overwriting_inputs({surface_, design_}, {report, copy}));
  EXPECT_NO_THROW(refuse_overwriting_inputs({surface_, design_}, {folder_ / "out" / "elements.ply", folder_ / "new.json"}));
  // An input that is not a file (no design given) or does not exist is no obstacle.
  EXPECT_NO_THROW(refuse_overwriting_inputs({surface_, fs::path()}, {report}));
  EXPECT_NO_THROW(refuse_overwriting_inputs({folder_ / "missing.obj"}, {report}));
  EXPECT_NO_THROW(refuse_overwriting_inputs({}, {surface_}));
  // A dangling link as output is not an input.
  fs::create_symlink(folder_ / "nowhere.obj", folder_ / "dangling.obj");
  EXPECT_NO_THROW(refuse_overwriting_inputs({surface_}, {folder_ / "dangling.obj"}));
}

TEST_F(OutputGuard, MakesNestedOutputFolders) {
  const fs::path nested = folder_ / "a" / "b" / "c";
  ASSERT_FALSE(fs::exists(folder_ / "a"));
  make_output_folder(nested);
  EXPECT_TRUE(fs::is_directory(nested));
  // Again, now that it exists: nothing to do, no error.
  EXPECT_NO_THROW(make_output_folder(nested));
  EXPECT_NO_THROW(make_output_folder(folder_));
}

TEST_F(OutputGuard, AFileInTheWayIsAnInputErrorNamingTheFolder) {
  const fs::path file = folder_ / "taken";
  write(file, "not a folder\n");
  const std::string message = error_of([&] { make_output_folder(file); });
  EXPECT_TRUE(Contains(message, "cannot create the output folder " + file.string()));
  // A file where a parent folder should be.
  const fs::path below = file / "run" / "out";
  EXPECT_TRUE(Contains(error_of([&] { make_output_folder(below); }), "cannot create the output folder " + below.string()));
  EXPECT_TRUE(fs::is_regular_file(file)) << "the file in the way is left alone";
}

TEST_F(OutputGuard, AnOutputFileMustBeARegularFileOrNothing) {
  EXPECT_NO_THROW(check_output_file(folder_ / "uv.obj"));
  EXPECT_NO_THROW(check_output_file(surface_)) << "a regular file may be replaced";
  // A pipe, a link and a device are refused, not replaced: renaming over /dev/null made it a file.
  const fs::path pipe = folder_ / "pipe.obj", link = folder_ / "link.obj";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  fs::create_symlink(surface_, link);
  EXPECT_TRUE(Contains(error_of([&] { check_output_file(pipe); }), "not a regular file"));
  EXPECT_TRUE(Contains(error_of([&] { check_output_file(link); }), "is a symbolic link"));
  EXPECT_TRUE(Contains(error_of([&] { check_output_file("/dev/null"); }), "cannot write /dev/null: it is not a regular file"));
  EXPECT_TRUE(Contains(error_of([&] { check_output_file(folder_); }), "it is a folder"));
  EXPECT_TRUE(Contains(error_of([&] { check_output_file(folder_ / "no" / "uv.obj"); }), "does not exist; create it first"));
  // The atomic writer checks the same before it writes anything.
  EXPECT_TRUE(Contains(error_of([&] { write_text_atomically(pipe, "x"); }), "not a regular file"));
  EXPECT_TRUE(fs::is_fifo(pipe));
  EXPECT_TRUE(fs::is_symlink(link));
  for (const auto& entry : fs::directory_iterator(folder_))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

TEST(OutputFolderCheck, AcceptsAFolderToBeMadeWithoutMakingIt) {
  const std::filesystem::path base = std::filesystem::temp_directory_path() /
                                     ("paver_check_output_" + std::to_string(::getpid()));
  std::filesystem::remove_all(base);
  std::filesystem::create_directories(base);
  EXPECT_NO_THROW(check_output_folder(base));
  EXPECT_NO_THROW(check_output_folder(base / "new" / "nested"));
  EXPECT_FALSE(std::filesystem::exists(base / "new")) << "the check must write nothing";

  std::ofstream(base / "file") << "x";
  for (const auto& folder : {base / "file", base / "file" / "below"}) {
    try {
      check_output_folder(folder);
      ADD_FAILURE() << folder << " accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("output folder " + folder.string()), std::string::npos) << message;
      EXPECT_NE(message.find("is a file, not a folder"), std::string::npos) << message;
    }
  }
  std::filesystem::remove_all(base);
}

// These were refused only after the whole pipeline had run, naming the staging folder.
TEST(OutputFolderCheck, AFolderThatCanNeverBeMadeIsRefusedUpFront) {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / ("paver_check_unmakeable_" + std::to_string(::getpid()));
  fs::remove_all(base);
  fs::create_directories(base);
  fs::create_symlink(base / "loop_b", base / "loop_a");
  fs::create_symlink(base / "loop_a", base / "loop_b");
  fs::create_symlink(base / "gone", base / "dangling");
  const std::string long_name(300, 'n');
  fs::path long_path = base;
  for (int i = 0; i < 25; ++i) long_path /= std::string(200, 'p');
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {base / "loop_a", "symbolic links"},          {base / "loop_a" / "below", "symbolic links"},
      {base / "dangling", "leads nowhere"},         {base / long_name, "300 bytes long"},
      {long_path, "bytes a path may have"}};
  for (const auto& one : cases) {
    const std::string message = error_of([&] { check_output_folder(one.first); });
    EXPECT_TRUE(Contains(message, one.second)) << message;
    EXPECT_LT(message.size(), 400u) << "the message names the problem, not 5,000 characters of path";
  }
  EXPECT_FALSE(fs::exists(base / "gone"));
  fs::remove_all(base);
}

}  // namespace
}  // namespace paver
