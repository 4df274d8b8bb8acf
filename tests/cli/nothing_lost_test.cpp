// The attacks of issue 41 on `paver run`, end to end: inputs that are pipes, devices or folders
// are refused at once (one hung in open(), one grew past 16 GB); a symlinked output folder stays a
// link; folders of the user's named like ours survive; two runs into one folder leave one whole
// set; an output folder that can never be made is refused before the work; NaN and contradictory
// flags are refused; messages are escaped and cut; a few late or misleading refusals say what is
// wrong. Each case ends in exit 2 with one clear line, or in a complete set. The publish's own
// kill-at-every-step test is tests/engine/io/publish_faults_test.cpp.
#include "cli_runner.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <set>
#include <sstream>
#include <vector>
#include <string>

namespace paver::cli_test {
namespace {

const std::string kDome = "assets/surfaces/dome.obj";

class NothingLost : public CliTest {
protected:
  // `paver args...` under a 60 s timeout, so that a hang fails the test (exit 124) instead of the suite.
  CliResult bounded(const std::vector<std::string>& args) const {
    std::vector<std::string> all = {"60", PAVER_CLI};
    all.insert(all.end(), args.begin(), args.end());
    return run_program("timeout", all, dir());
  }
  static std::set<std::string> names(const fs::path& folder) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(folder)) out.insert(e.path().filename().string());
    return out;
  }
  // The files the folder's manifest lists, with the manifest itself.
  static std::set<std::string> manifest_set(const fs::path& folder) {
    std::set<std::string> out = {".paver-files"};
    std::istringstream lines(read_file_text(folder / ".paver-files"));
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("file ", 0) == 0) out.insert(line.substr(5));
    return out;
  }
};

void expect_refused(const CliResult& r, const std::string& fragment) {
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr lacks \"" << fragment << "\"\n" << describe(r);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << describe(r);
}

TEST_F(NothingLost, InputsThatAreNotRegularFilesAreRefusedAtOnce) {
  const fs::path out = dir() / "out";
  const fs::path pipe = dir() / "design.json";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  expect_refused(bounded({"run", kDome, "--design", pipe.string(), "--out", out.string()}), "is not a regular file (a pipe)");
  expect_refused(bounded({"run", kDome, "--design", "/dev/zero", "--out", out.string()}), "is not a regular file (a device)");
  expect_refused(bounded({"run", kDome, "--design", dir().string(), "--out", out.string()}), "is a folder, not a design file");
  const fs::path surface_pipe = dir() / "surface.obj";
  ASSERT_EQ(::mkfifo(surface_pipe.c_str(), 0600), 0);
  expect_refused(bounded({"run", surface_pipe.string(), "--out", out.string()}), "is not a regular file (a pipe)");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(NothingLost, ASymlinkedOutputFolderStaysALink) {
  const fs::path real = dir() / "real", link = dir() / "link";
  fs::create_directories(real);
  fs::create_symlink(real, link);
  const CliResult first = paver({"run", kDome, "--out", link.string(), "--formats", "ply,stl", "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  const CliResult second = paver({"run", kDome, "--out", link.string(), "--formats", "obj", "--quiet"});
  ASSERT_EQ(second.exit_code, 0) << describe(second);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link was replaced by a folder";
  EXPECT_EQ(names(real), manifest_set(real)) << "the target holds the second set, whole and alone";
  EXPECT_TRUE(fs::exists(real / "elements.obj"));
  EXPECT_FALSE(fs::exists(real / "elements.stl"));
  EXPECT_EQ(names(dir()).count("link") + names(dir()).count("real"), 2u);
  for (const std::string& name : names(dir())) EXPECT_EQ(name.find("staging"), std::string::npos) << name;
}

TEST_F(NothingLost, TheUsersFoldersAreNeverRemovedForTheirNames) {
  const fs::path out = dir() / "out";
  const std::vector<fs::path> users = {dir() / ".out.paver-staging.999999", out / ".paver-staging.999998",
                                       out / ".paver-staging.0123456789abcdef"};
  for (const fs::path& folder : users) {
    fs::create_directories(folder);
    write_file_text(folder / "thesis.tex", "years of work");
  }
  for (int run = 0; run < 2; ++run) {
    const CliResult r = paver({"run", kDome, "--out", out.string(), "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << describe(r);
  }
  for (const fs::path& folder : users) EXPECT_EQ(read_file_text(folder / "thesis.tex"), "years of work") << folder;

  // A folder, or a pipe, where paver keeps its list of files: refused, left as it is, no hang.
  const fs::path other = dir() / "other";
  fs::create_directories(other / ".paver-files");
  write_file_text(other / ".paver-files" / "mine.txt", "mine");
  expect_refused(bounded({"run", kDome, "--out", other.string()}), ".paver-files: is not a regular file but a folder");
  EXPECT_EQ(read_file_text(other / ".paver-files" / "mine.txt"), "mine");
  fs::remove_all(other / ".paver-files");
  ASSERT_EQ(::mkfifo((other / ".paver-files").c_str(), 0600), 0);
  expect_refused(bounded({"run", kDome, "--out", other.string()}), "is not a regular file but a special file");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(other / ".paver-files")));
}

TEST_F(NothingLost, TwoRunsIntoOneFolderLeaveOneWholeSet) {
  // Before the lock: both exit 0 with 13 files of which the manifest listed 8, and every later run was refused.
  const fs::path out = dir() / "out";
  fs::create_directories(out);
  write_file_text(out / "notes.txt", "mine");
  const auto run = [&](const std::string& formats, const std::string& code) {
    return shell_quote(PAVER_CLI) + " run " + kDome + " --quiet --out " + shell_quote(out.string()) + " --formats " +
           formats + " >/dev/null 2>&1; echo $? > " + shell_quote((dir() / code).string());
  };
  for (int round = 0; round < 3; ++round) {
    const CliResult both = run_program("sh", {"-c", "(" + run("ply,stl,glb", "a.code") + ") & (" + run("obj", "b.code") + ") & wait"}, dir());
    EXPECT_EQ(read_file_text(dir() / "a.code"), "0\n");
    EXPECT_EQ(read_file_text(dir() / "b.code"), "0\n");
    std::set<std::string> expected = manifest_set(out);
    expected.insert("notes.txt");
    EXPECT_EQ(names(out), expected) << "one run's set, whole, and the user's file";
    const CliResult next = paver({"run", kDome, "--out", out.string(), "--quiet"});
    EXPECT_EQ(next.exit_code, 0) << describe(next);
  }
  EXPECT_EQ(read_file_text(out / "notes.txt"), "mine");
}

TEST_F(NothingLost, AnOutputFolderThatCannotBeMadeIsRefusedBeforeTheWork) {
  fs::create_symlink(dir() / "loop_b", dir() / "loop_a");
  fs::create_symlink(dir() / "loop_a", dir() / "loop_b");
  fs::create_symlink(dir() / "gone", dir() / "dangling");
  std::string long_path = dir().string();
  while (long_path.size() < 5000) long_path += "/" + std::string(200, 'p');
  const std::vector<std::pair<std::string, std::string>> cases = {
      {(dir() / "loop_a").string(), "symbolic links"},
      {(dir() / "loop_a" / "out").string(), "symbolic links"},
      {(dir() / "dangling").string(), "leads nowhere"},
      {long_path, "bytes a path may have"}};
  for (const auto& [out, why] : cases) {
    const CliResult r = paver({"run", kDome, "--out", out});
    expect_refused(r, why);
    EXPECT_EQ(r.err.find("paver: mapping"), std::string::npos) << "refused after the work began\n" << describe(r);
    EXPECT_EQ(r.err.find("staging"), std::string::npos) << describe(r);
    EXPECT_LT(r.err.size(), 600u) << describe(r);
  }
  EXPECT_FALSE(fs::exists(dir() / "gone"));
}

TEST_F(NothingLost, NaNAndContradictoryFlagsAreRefused) {
  const fs::path out = dir() / "out";
  const CliResult nan = paver({"run", kDome, "--max-output-gb", "nan", "--out", out.string()});
  expect_refused(nan, "--max-output-gb NaN");
  EXPECT_EQ(nan.err.find("-nan"), std::string::npos) << describe(nan);
  expect_refused(paver({"run", kDome, "--backend", "cpu", "--device", "X", "--out", out.string()}),
                 "--device X names a Vulkan device, but --backend cpu");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(NothingLost, MessagesAreEscapedAndCut) {
  const fs::path out = dir() / "out";
  const fs::path nul = dir() / "nul.json";
  write_file_text(nul, "{\"version\": 3, \"sol\\u0000ver\": {}}");
  const CliResult r = paver({"run", kDome, "--design", nul.string(), "--out", out.string()});
  expect_refused(r, "sol\\x00ver");
  const fs::path huge = dir() / "huge.json";
  write_file_text(huge, R"({"version": 3, "pattern": {"tessellation": ")" + std::string(1 << 20, 'x') + R"("}})");
  const CliResult h = paver({"run", kDome, "--design", huge.string(), "--out", out.string()});
  EXPECT_EQ(h.exit_code, 2) << h.err.substr(0, 500);
  EXPECT_LE(h.err.size(), 2100u) << "one line a terminal can show, not a megabyte";
  EXPECT_NE(h.err.find("bytes ...]"), std::string::npos) << h.err.substr(0, 500);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(NothingLost, LateOrMisleadingRefusalsSayWhatIsWrong) {
  const fs::path out = dir() / "out";
  // Deleting every element blamed the stones' size.
  const CliResult first = paver({"run", kDome, "--out", (dir() / "first").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << describe(first);
  nlohmann::json design = nlohmann::json::parse(read_file_text(dir() / "first" / "design.json"));
  std::istringstream placements(read_file_text(dir() / "first" / "placements.csv"));
  std::string line;
  std::getline(placements, line);  // the header
  design["edits"]["deleted"] = nlohmann::json::array();
  int count = 0;
  for (; std::getline(placements, line); ++count) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 11u) << line;  // id, kind, x, y, z, nx, ny, nz, diameter, u, v
    design["edits"]["deleted"].push_back({{"id", std::stoi(cells[0])}, {"uv", {std::stod(cells[9]), std::stod(cells[10])}}});
  }
  ASSERT_GT(count, 10);
  write_file_text(dir() / "none.json", design.dump());
  expect_refused(paver({"run", kDome, "--design", (dir() / "none.json").string(), "--out", out.string()}),
                 "deletes every one of the");
  // A custom shape without area made elements of no size.
  write_file_text(dir() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  write_file_text(dir() / "flat.json", R"({"version": 3, "elements": {"vertex": {"shape": "custom"}, "custom_shape": "flat.obj"}})");
  expect_refused(paver({"run", kDome, "--design", (dir() / "flat.json").string(), "--out", out.string()}),
                 "its faces have no area");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace paver::cli_test
