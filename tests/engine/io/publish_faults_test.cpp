// A publish killed at every step it takes (io/output_set.h): the process ends at the k-th change
// on disk, for every k, in both ways of publishing. Afterwards the folder holds one complete set,
// the old or the new (swapped in at once; moved in one at a time, once the next run has finished
// what the killed one began), every entry of the user's is there again with its content, no
// staging folder is left once the next run has recovered, and that run publishes normally.
#include "io/output_set.h"
#include "io/set_manifest.h"

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

int steps_taken = 0;
int kill_at = -1;

void count_or_die(const std::string&) {
  if (steps_taken++ == kill_at) ::_exit(3);
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class PublishFaultsTest : public ::testing::TestWithParam<bool> {
protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("paver_publish_faults_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    out_ = base_ / "out";
  }
  void TearDown() override {
    OutputSet::set_test_hooks({});
    fs::remove_all(base_);
  }

  // The old set and the user's entries: a file, a folder with a file in it, a link.
  void make_old_folder() {
    fs::remove_all(base_);
    fs::create_directories(base_);
    publish("old", {"a.csv", "b.ply", "report.json"});
    write(out_ / "notes.txt", "mine");
    fs::create_directories(out_ / "thesis");
    write(out_ / "thesis" / "one.tex", "draft");
    fs::create_symlink("notes.txt", out_ / "link.txt");
  }
  void publish(const std::string& tag, const std::vector<std::string>& files) {
    OutputSet set(out_, kKnown);
    for (const auto& f : files) write(set.staging() / f, tag);
    set.publish();
  }
  void hooks(OutputSet::StepHook step) { OutputSet::set_test_hooks({.step = step, .one_at_a_time = GetParam()}); }

  // The set the folder holds: its files (the user's aside) must be those the manifest lists, all of
  // one run. Returns that run's tag, or "mixed".
  std::string whole_set() const {
    const SetManifest manifest = read_set_manifest(out_);
    std::set<std::string> listed(manifest.files.begin(), manifest.files.end()), found;
    for (const auto& entry : fs::directory_iterator(out_)) {
      const std::string name = entry.path().filename().string();
      if (name != ".paver-files" && !users_.contains(name)) found.insert(name);
    }
    if (found != listed) return "mixed";
    std::set<std::string> tags;
    for (const std::string& name : listed) tags.insert(read(out_ / name));
    return tags.size() == 1 ? *tags.begin() : "mixed";
  }
  void expect_users_entries_whole() const {
    EXPECT_EQ(read(out_ / "notes.txt"), "mine");
    EXPECT_EQ(read(out_ / "thesis" / "one.tex"), "draft");
    EXPECT_TRUE(fs::is_symlink(out_ / "link.txt"));
    EXPECT_EQ(fs::hard_link_count(out_ / "notes.txt"), 1u);
  }
  std::set<std::string> beside() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(base_)) names.insert(entry.path().filename().string());
    return names;
  }

  fs::path base_, out_;
  const std::set<std::string> users_ = {"notes.txt", "thesis", "link.txt"};
};

TEST_P(PublishFaultsTest, AKillAtAnyStepLeavesOneWholeSetAndTheNextRunWorks) {
  make_old_folder();
  hooks(count_or_die);
  steps_taken = 0;
  kill_at = -1;
  publish("new", {"a.csv", "preview.png", "report.json"});
  const int steps = steps_taken;
  EXPECT_EQ(whole_set(), "new");
  ASSERT_GE(steps, 6) << "the dry run must take the publish's steps";
  for (int k = 0; k < steps; ++k) {
    SCOPED_TRACE("killed at step " + std::to_string(k) + " of " + std::to_string(steps));
    OutputSet::set_test_hooks({});
    make_old_folder();
    const pid_t child = ::fork();
    if (child == 0) {
      hooks(count_or_die);
      steps_taken = 0;
      kill_at = k;
      publish("new", {"a.csv", "preview.png", "report.json"});
      ::_exit(0);
    }
    ASSERT_GT(child, 0);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << "the hook must have ended the run";
    OutputSet::set_test_hooks({.one_at_a_time = GetParam()});
    // Swapped: one whole set at every instant. One at a time: every file proven ours until the next run ends it.
    if (!GetParam()) {
      EXPECT_NE(whole_set(), "mixed");
    }
    EXPECT_NO_THROW(OutputSet::refuse_replacing_users_files(out_, {out_ / "a.csv", out_ / "preview.png"}, kKnown));
    OutputSet::recover_interrupted(out_, kKnown);
    const std::string after = whole_set();
    EXPECT_TRUE(after == "old" || after == "new") << after;
    expect_users_entries_whole();
    EXPECT_EQ(beside(), (std::set<std::string>{"out"})) << "no staging folder left after recovery";
    publish("newer", {"a.csv", "report.json"});
    EXPECT_EQ(whole_set(), "newer");
    expect_users_entries_whole();
    EXPECT_EQ(beside(), (std::set<std::string>{"out"}));
  }
}

INSTANTIATE_TEST_SUITE_P(BothWays, PublishFaultsTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "OneAtATime" : "Swapped"; });

}  // namespace
}  // namespace paver
