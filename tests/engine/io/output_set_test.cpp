// Tests for engine/io/output_set.cpp: a run's files appear in the output folder all at once, an
// unpublished set leaves no trace, a previous run's files never mix with a new run's, the user's
// own entries are left alone (even under an output's name: the manifest tells them apart; folders,
// links and pipes of theirs too), a symlinked folder stays a link, only staging folders that bear
// our marker are ever removed, and runs publishing into one folder take turns.
// The kill-at-every-step test is publish_faults_test.cpp.
#include "io/output_set.h"
#include "io/set_manifest.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <csignal>
#include <set>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

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
  SetManifest manifest = read_set_manifest(out);
  EXPECT_EQ(manifest.files, (std::vector<std::string>{"a.csv", "report.json"}));
  EXPECT_EQ(manifest.token.size(), 16u);
  write(out / "notes.txt", "mine");
  publish_run(out, "new", {"b.ply", "report.json"});
  manifest = read_set_manifest(out);
  EXPECT_EQ(manifest.files, (std::vector<std::string>{"b.ply", "report.json"}));
  EXPECT_TRUE(manifest.old.empty());
  EXPECT_EQ(names(out), (std::set<std::string>{"b.ply", "notes.txt", "report.json"}));
}

TEST_F(OutputSetTest, AManifestFromBeforeTokensStillProvesItsFiles) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  for (const char* name : {"a.csv", "b.ply"}) write(out / name, "old");
  write(out / kManifest, "a.csv\nb.ply\n");
  write(out / "notes.txt", "mine");
  EXPECT_NO_THROW(OutputSet::refuse_replacing_users_files(out, {out / "b.ply"}, kKnown));
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "notes.txt", "report.json"}));
}

TEST_F(OutputSetTest, AUsersNameWithANewlineCannotForgeAManifestLine) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  write(out / "x\nfile b.ply", "mine");
  const std::string sub = "d\nfile preview.png";
  fs::create_directories(out / sub);  // a folder: moved, so recorded as borrowed
  publish_run(out, "new", {"a.csv", "report.json"});
  write(out / "b.ply", "my scan");
  write(out / "preview.png", "my photo");
  EXPECT_THROW(OutputSet::refuse_replacing_users_files(out, {out / "b.ply"}, kKnown), InputError);
  EXPECT_THROW(OutputSet::refuse_replacing_users_files(out, {out / "preview.png"}, kKnown), InputError);
  publish_run(out, "newer", {"a.csv", "report.json"});
  EXPECT_EQ(read(out / "b.ply"), "my scan");
  EXPECT_EQ(read(out / "preview.png"), "my photo");
  EXPECT_TRUE(fs::is_directory(out / sub));
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

TEST_F(OutputSetTest, EveryKindOfUserEntryStaysWithItsInode) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "b.ply", "report.json"});
  write(out / "notes.txt", "mine");
  fs::create_directories(out / "thesis" / "chapters");
  write(out / "thesis" / "chapters" / "one.tex", "draft");
  fs::create_symlink("notes.txt", out / "link.txt");
  fs::create_symlink("nowhere", out / "dangling");
  ASSERT_EQ(::mkfifo((out / "pipe").c_str(), 0600), 0);
  struct stat before {};
  ASSERT_EQ(::stat((out / "notes.txt").c_str(), &before), 0);
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "dangling", "link.txt", "notes.txt", "pipe", "report.json",
                                               "thesis"}));
  EXPECT_EQ(read(out / "thesis" / "chapters" / "one.tex"), "draft");
  EXPECT_TRUE(fs::is_symlink(out / "link.txt"));
  EXPECT_EQ(fs::read_symlink(out / "dangling"), "nowhere");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(out / "pipe")));
  struct stat after {};
  ASSERT_EQ(::stat((out / "notes.txt").c_str(), &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino) << "the user's file must be the same file, not a copy";
  EXPECT_EQ(after.st_nlink, 1u) << "no second link left behind";
  EXPECT_EQ(read(out / "a.csv"), "new");
  EXPECT_EQ(names(base_), (std::set<std::string>{"out"})) << "no staging folder left";
}

TEST_F(OutputSetTest, ASymlinkedFolderStaysALink) {
  const fs::path real = base_ / "real";
  const fs::path link = base_ / "link";
  fs::create_directories(real);
  fs::create_symlink(real, link);
  publish_run(link, "old", {"a.csv", "b.ply", "report.json"});
  publish_run(link, "new", {"a.csv", "report.json"});
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link must not become a folder";
  EXPECT_EQ(fs::read_symlink(link), real);
  EXPECT_EQ(names(real), (std::set<std::string>{"a.csv", "report.json"}));
  EXPECT_EQ(read(real / "a.csv"), "new");
  EXPECT_EQ(names(base_), (std::set<std::string>{"link", "real"}));
  fs::create_symlink(base_ / "gone", base_ / "dangling");
  EXPECT_THROW(OutputSet(base_ / "dangling", kKnown), InputError) << "a link that leads nowhere is refused";
  EXPECT_FALSE(fs::exists(base_ / "gone"));
}

TEST_F(OutputSetTest, AManifestThatIsNotARegularFileIsRefusedNotFollowed) {
  const fs::path out = base_ / "out";
  fs::create_directories(out);
  write(base_ / "elsewhere.txt", "a.csv\nnotes.txt\n");
  const auto make_folder = [&] { fs::create_directories(out / kManifest / "inside"); };
  const auto make_pipe = [&] { ASSERT_EQ(::mkfifo((out / kManifest).c_str(), 0600), 0); };
  const auto make_link = [&] { fs::create_symlink(base_ / "elsewhere.txt", out / kManifest); };
  for (const auto& make : std::vector<std::function<void()>>{make_folder, make_pipe, make_link}) {
    fs::remove_all(out / kManifest);
    make();
    write(out / "a.csv", "mine");
    // A pipe read would block: the check must not open it.
    EXPECT_THROW(OutputSet::refuse_replacing_users_files(out, {out / "report.json"}, kKnown), InputError);
    EXPECT_THROW(publish_run(out, "new", {"report.json"}), InputError);
    EXPECT_EQ(read(out / "a.csv"), "mine");
    EXPECT_TRUE(fs::exists(fs::symlink_status(out / kManifest)));
    if (fs::is_directory(fs::symlink_status(out / kManifest))) {
      EXPECT_TRUE(fs::exists(out / kManifest / "inside"));
    }
  }
  EXPECT_EQ(read(base_ / "elsewhere.txt"), "a.csv\nnotes.txt\n");
  EXPECT_EQ(names(base_), (std::set<std::string>{"elsewhere.txt", "out"})) << "no staging folder left";
}

TEST_F(OutputSetTest, FoldersNamedLikeStagingAreTheUsersUnlessMarked) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  const std::vector<fs::path> users = {base_ / ".out.paver-staging.999999", base_ / ".out.paver-staging.0123456789abcdef",
                                       out / ".paver-staging.999998", out / ".paver-staging.fedcba9876543210"};
  for (const fs::path& folder : users) {
    fs::create_directories(folder);
    write(folder / "thesis.tex", "years of work");
    write(folder / "a.csv", "mine too");
  }
  // One with a marker whose token is not its name's is not ours either.
  write(users[1] / kManifest, "# paver output set; token=1111111111111111 pid=999999\n");
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(OutputSet::recover_interrupted(out, kKnown), 0);
  for (const fs::path& folder : users) {
    EXPECT_EQ(read(folder / "thesis.tex"), "years of work") << folder;
    EXPECT_EQ(read(folder / "a.csv"), "mine too") << folder;
  }
}

TEST_F(OutputSetTest, AKilledRunsStagingIsRemovedButNotALiveOnes) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  // A run killed while writing: its staging folder bears its marker and its pid is gone.
  const pid_t killed = ::fork();
  if (killed == 0) {
    OutputSet set(out, kKnown);
    write(set.staging() / "a.csv", "half");
    ::_exit(0);
  }
  ASSERT_GT(killed, 0);
  ::waitpid(killed, nullptr, 0);
  // A run still writing: same, but alive.
  const pid_t live = ::fork();
  if (live == 0) {
    OutputSet set(out, kKnown);
    write(set.staging() / "a.csv", "busy");
    ASSERT_EQ(::write(ready[1], "x", 1), 1);
    ::pause();
    ::_exit(0);
  }
  char byte;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  EXPECT_EQ(names(base_).size(), 3u) << "out and two staging folders";
  publish_run(out, "new", {"a.csv", "report.json"});
  EXPECT_EQ(names(base_).size(), 2u) << "the killed run's staging goes, the live one's stays";
  ::kill(live, SIGTERM);
  ::waitpid(live, nullptr, 0);
  EXPECT_EQ(OutputSet::recover_interrupted(out, kKnown), 1);
  EXPECT_EQ(names(base_), (std::set<std::string>{"out"}));
  EXPECT_EQ(read(out / "a.csv"), "new");
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST_F(OutputSetTest, TwoRunsWithDifferentSetsLeaveOneWholeSet) {
  // Before the lock, both ended with exit 0 and 13 files of which the manifest listed 8.
  const fs::path out = base_ / "out";
  write(base_ / "keep.txt", "mine");
  std::vector<pid_t> runs;
  for (int run = 0; run < 2; ++run) {
    const pid_t child = ::fork();
    if (child == 0) {
      for (int round = 0; round < 20; ++round) {
        const std::vector<std::string> files =
            run == 0 ? std::vector<std::string>{"a.csv", "b.ply", "report.json"}
                     : std::vector<std::string>{"a.csv", "preview.png", "report.json"};
        OutputSet set(out, kKnown);
        for (const auto& f : files) write(set.staging() / f, "run" + std::to_string(run));
        set.publish();
      }
      ::_exit(0);
    }
    runs.push_back(child);
  }
  for (const pid_t child : runs) {
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  const SetManifest manifest = read_set_manifest(out);
  const std::set<std::string> listed(manifest.files.begin(), manifest.files.end());
  EXPECT_EQ(names(out), listed) << "every file in the folder is the last set's, and only those";
  const std::string tag = read(out / "report.json");
  for (const std::string& name : listed) EXPECT_EQ(read(out / name), tag) << name;
  EXPECT_EQ(names(base_), (std::set<std::string>{"keep.txt", "out"}));
}

TEST_F(OutputSetTest, APublishWaitsForTheRunHoldingTheFolder) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  const int held = ::open(out.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX), 0);
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(read(out / "a.csv"), "old") << "nothing may be published while another run holds the folder";
    ::close(held);
  });
  publish_run(out, "new", {"a.csv", "report.json"});
  release.join();
  EXPECT_EQ(read(out / "a.csv"), "new");
}

TEST_F(OutputSetTest, OneAtATimePublishesTheSameSet) {
  OutputSet::set_test_hooks({.one_at_a_time = true});
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "b.ply", "report.json"});
  write(out / "notes.txt", "mine");
  publish_run(out, "new", {"a.csv", "report.json"});
  OutputSet::set_test_hooks({});
  EXPECT_EQ(names(out), (std::set<std::string>{"a.csv", "notes.txt", "report.json"}));
  EXPECT_EQ(read(out / "a.csv"), "new");
  EXPECT_TRUE(read_set_manifest(out).old.empty());
  EXPECT_EQ(names(base_), (std::set<std::string>{"out"}));
}

// An old file that cannot be removed (immutable, as `chattr +i` makes it) does not hold the new
// set back: it is published whole, and the swapped-out folder that keeps the old file is named in
// a warning that says why it is there. Needs the immutable flag (root on ext4, xfs, btrfs).
TEST_F(OutputSetTest, AnOldFileThatCannotBeRemovedLeavesTheNewSetWholeAndSaysSo) {
  const fs::path out = base_ / "out";
  publish_run(out, "old", {"a.csv", "report.json"});
  const int fd = ::open((out / "a.csv").c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  int flags = 0;
  const bool immutable = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0 &&
                         (flags |= FS_IMMUTABLE_FL, ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0);
  ::close(fd);
  if (!immutable) GTEST_SKIP() << "SKIPPED: this file system or user cannot make a file immutable";
  OutputSet set(out, kKnown);
  write(set.staging() / "a.csv", "new");
  write(set.staging() / "report.json", "new");
  set.publish();
  fs::path kept;
  for (const auto& e : fs::directory_iterator(base_))
    if (e.path().filename() != "out") kept = e.path();
  if (const int old_fd = ::open((kept / "a.csv").c_str(), O_RDONLY); old_fd >= 0) {
    flags &= ~FS_IMMUTABLE_FL;  // first, so that TearDown can remove it whatever fails below
    EXPECT_EQ(::ioctl(old_fd, FS_IOC_SETFLAGS, &flags), 0);
    ::close(old_fd);
  }
  EXPECT_EQ(read(out / "a.csv"), "new");
  EXPECT_EQ(read(out / "report.json"), "new");
  std::string said;
  for (const auto& w : set.warnings()) said += w + "\n";
  EXPECT_NE(said.find("could not remove the previous set's"), std::string::npos) << said;
  EXPECT_NE(said.find("still holds what the warnings above name"), std::string::npos) << said;
  ASSERT_FALSE(kept.empty()) << "the folder keeping the old file must be beside the output folder";
  EXPECT_NE(said.find(kept.string()), std::string::npos) << said;
  EXPECT_EQ(read(kept / "a.csv"), "old");
}

}  // namespace
}  // namespace paver
