// Tests for engine/io/output_set.cpp: a run's files appear in the output folder all at once, an
// unpublished set leaves no trace, a previous run's files never mix with a new run's, the user's
// own files are left alone (even under an output's name: the manifest tells them apart), and
// staging folders of killed runs are cleaned up.
#include "io/output_set.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace paver {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kKnown = {"a.csv", "b.ply", "report.json", "preview.png"};
constexpr const char* kManifest = ".paver-files";

class OutputSetTest : public ::testing::Test {
protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("paver_output_set_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    fs::create_directories(base_);
  }
  void TearDown() override { fs::remove_all(base_); }

  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  static std::string read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // The folder's files but the manifest (checked on its own).
  static std::set<std::string> names(const fs::path& folder) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().filename() != kManifest) out.insert(e.path().filename().string());
    return out;
  }
  void publish_run(const fs::path& out, const std::string& tag, std::vector<std::string> files) {
    OutputSet set(out, kKnown);
    for (const auto& f : files) write(set.staging() / f, tag);
    set.publish();
  }

  fs::path base_;
};

TEST_F(OutputSetTest, ANewFolderAppearsComplete) {
  const fs::path out = base_ / "nested" / "out";
  {
    OutputSet set(out, kKnown);
    write(set.staging() / "a.csv", "1");
    write(set.staging() / "report.json", "1");
    EXPECT_FALSE(fs::exists(out)) << "nothing may be visible before publishing";
    set.publish();
  }
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "report.json"}));
  EXPECT_EQ(names(base_ / "nested"), (std::set<std::string>{"out"})) << "no staging folder left";
}

TEST_F(OutputSetTest, AnUnpublishedSetLeavesNoTrace) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  {
    OutputSet set(out, kKnown);
    write(set.staging() / "a.csv", "new");
  }  // interrupted: destroyed without publish
  EXPECT_EQ(read(out / "a.csv"), "old");
  EXPECT_EQ(names(base_), (std::set<std::string>{"out"}));
}

TEST_F(OutputSetTest, APreviousRunsSetIsReplacedWhole) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "b.ply", "preview.png", "report.json"});
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "report.json"})) << "the old preview.png must go";
  EXPECT_EQ(read(out / "a.csv"), "new");
  EXPECT_EQ(names(base_), (std::set<std::string>{"out"}));
}

TEST_F(OutputSetTest, TheUsersOwnFilesStay) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "b.ply", "preview.png", "report.json"});
  write(out / "notes.txt", "mine");
  publish_run(out, "new", {"a.csv", "b.ply", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "b.ply", "notes.txt", "report.json"}));
  EXPECT_EQ(read(out / "notes.txt"), "mine");
  EXPECT_EQ(read(out / "b.ply"), "new");
  EXPECT_EQ(read(out / "report.json"), "new");
}

TEST_F(OutputSetTest, TheManifestListsThePublishedSet) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  EXPECT_EQ(read(out / kManifest), "a.csv\nreport.json\n");
  write(out / "notes.txt", "mine");  // the one-by-one path
  publish_run(out, "new", {"b.ply", "report.json"});
  EXPECT_EQ(read(out / kManifest), "b.ply\nreport.json\n");
  EXPECT_EQ(names(out), (std::set<std::string>{"b.ply", "notes.txt", "report.json"}));
}

TEST_F(OutputSetTest, TheUsersFilesUnderAnOutputsNameStay) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  write(out / "preview.png", "my photo");
  write(out / "b.ply", "my scan");
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "b.ply", "preview.png", "report.json"}));
  EXPECT_EQ(read(out / "preview.png"), "my photo");
  publish_run(out, "newer", {"a.csv", "report.json"});
  EXPECT_EQ(read(out / "b.ply"), "my scan") << "a second run must not take them for the first run's";
}

TEST_F(OutputSetTest, ReplacingAUsersFileIsRefusedBeforeAnyWork) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  write(out / "preview.png", "my photo");
  EXPECT_NO_THROW(OutputSet::refuse_replacing_users_files(out, {out / "a.csv", out / "report.json"}, kKnown));
  try {
    OutputSet::refuse_replacing_users_files(out, {out / "a.csv", out / "preview.png"}, kKnown);
    ADD_FAILURE() << "a run that would replace the user's preview.png must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("preview.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(out / "preview.png"), "my photo");
  // A file that an earlier run wrote is that run's to replace.
  fs::remove(out / "preview.png");
  publish_run(out, "old", {"preview.png", "report.json"});
  EXPECT_NO_THROW(OutputSet::refuse_replacing_users_files(out, {out / "preview.png"}, kKnown));
}

TEST_F(OutputSetTest, AFolderFromBeforeManifestsIsTheProgramsWhenItHasAReport) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  for (const char* name : {"a.csv", "b.ply"}) write(out / name, "old");
  write(out / "report.json", R"({"design": {"tessellation": "tri"}, "quality_after": {"fill": 0.97}})");
  write(out / "notes.txt", "mine");
  EXPECT_NO_THROW(OutputSet::refuse_replacing_users_files(out, {out / "b.ply"}, kKnown));
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "notes.txt", "report.json"})) << "the old b.ply goes";
}

TEST_F(OutputSetTest, AUsersOwnReportJsonDoesNotMakeTheFolderTheProgramsOwn) {
  // A report.json that Paver did not write made every file with an output's name an old run's.
  for (const std::string mine : {"mine\n", R"({"design": "my notes"})", R"([1, 2])"}) {
    const fs::path out = base_ / "out";
    fs::remove_all(out);
    fs::create_directories(out);
    write(out / "report.json", mine);
    write(out / "a.csv", "my table");
    EXPECT_THROW(OutputSet::refuse_replacing_users_files(out, {out / "a.csv"}, kKnown), InputError) << mine;
    EXPECT_THROW(OutputSet::refuse_replacing_users_files(out, {out / "report.json"}, kKnown), InputError) << mine;
    EXPECT_EQ(read(out / "a.csv"), "my table");
  }
}

TEST_F(OutputSetTest, StagingOfKilledRunsIsRemovedButNotOfLiveOnes) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  // A process that has exited: its pid names a killed run's staging folder.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const fs::path dead_beside = base_ / (".out.paver-staging." + std::to_string(child));
  const fs::path dead_inside = out / (".paver-staging." + std::to_string(child));
  const fs::path live = base_ / (".out.paver-staging." + std::to_string(::getpid()));
  for (const auto& p : {dead_beside, dead_inside, live}) fs::create_directories(p);
  EXPECT_EQ(OutputSet::remove_stale_staging(out), 2);
  EXPECT_FALSE(fs::exists(dead_beside));
  EXPECT_FALSE(fs::exists(dead_inside));
  EXPECT_TRUE(fs::exists(live));
}

}  // namespace
}  // namespace paver
