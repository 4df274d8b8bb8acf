// End-to-end tests of paver-assetgen (app/assetgen): the real binary writes into a temporary
// folder; what it writes must load cleanly and, for the small set, equal the committed copies
// byte for byte, so assets/surfaces cannot drift from its generator.
#include "cli_runner.h"

#include "mesh/mesh_loader.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace paver::cli_test {
namespace {

const fs::path kCommitted = fs::path(PAVER_SOURCE_DIR) / "assets" / "surfaces";

CliResult assetgen(const std::vector<std::string>& args, const fs::path& scratch) {
  return run_program(PAVER_ASSETGEN, args, scratch);
}

// Names of the files in `folder` (all of them, so stray temporaries show up too).
std::set<std::string> file_names(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// Loads through the engine's reader, the way a user's file is loaded; no repair allowed.
void expect_loads_cleanly(const fs::path& path, int min_faces) {
  SCOPED_TRACE(path.string());
  LoadedSurface loaded;
  ASSERT_NO_THROW(loaded = load_surface(path));
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  EXPECT_GE(loaded.mesh.face_count(), min_faces);
}

using Assetgen = CliTest;

TEST_F(Assetgen, SmallSetEqualsTheCommittedSurfaces) {
  const fs::path out = dir() / "surfaces";  // missing: the generator creates it
  const CliResult r = assetgen({out.string()}, dir());
  ASSERT_EQ(r.exit_code, 0) << describe(r);

  std::set<std::string> committed;
  for (const auto& entry : fs::directory_iterator(kCommitted))
    if (entry.path().extension() == ".obj") committed.insert(entry.path().filename().string());
  ASSERT_FALSE(committed.empty());
  EXPECT_EQ(file_names(out), committed) << describe(r);
  for (const std::string& name : file_names(out)) {
    expect_loads_cleanly(out / name, 400);
    if (committed.count(name) != 0) {
      EXPECT_TRUE(read_file_text(out / name) == read_file_text(kCommitted / name))
          << name << " differs from assets/surfaces/" << name << ": regenerate the committed set";
    }
  }
}

TEST_F(Assetgen, DenseSetLoadsCleanly) {
  const fs::path out = dir() / "dense";
  const CliResult r = assetgen({out.string(), "--dense"}, dir());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::set<std::string> expected = {"dome_dense.obj", "wave_dense.obj", "facade_dense.obj"};
  EXPECT_EQ(file_names(out), expected) << describe(r);
  for (const std::string& name : expected) expect_loads_cleanly(out / name, 50000);
}

TEST_F(Assetgen, HelpExitsZero) {
  const CliResult r = assetgen({"--help"}, dir());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("OUTDIR"), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("--dense"), std::string::npos) << describe(r);
}

// A usage error: exit 2, one line on stderr naming the program, nothing written.
TEST_F(Assetgen, BadArgumentsExitTwoWithOneLine) {
  const std::string out = (dir() / "out").string();
  const std::vector<std::vector<std::string>> cases = {
      {}, {"--dense"}, {out, "--bogus"}, {out, "extra"}, {out, "--dense", "--dense"}, {""}};
  for (const auto& args : cases) {
    const CliResult r = assetgen(args, dir());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_EQ(r.err.rfind("paver-assetgen: ", 0), 0u) << describe(r);
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "expected exactly one line\n" << describe(r);
    EXPECT_TRUE(r.out.empty()) << describe(r);
    EXPECT_FALSE(fs::exists(out)) << describe(r);
  }
}

}  // namespace
}  // namespace paver::cli_test
