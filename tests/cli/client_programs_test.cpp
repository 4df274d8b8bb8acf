// The programs jewellers open Paver's files with, run on a small pavement's files as they are:
// PrusaSlicer loads paved.3mf and slices cut.3mf, admesh finds cut.stl one closed part needing no
// repair. app/setup.sh test installs them (Debian's prusa-slicer and admesh); a machine without
// them skips, loudly, saying what to install.
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>

namespace paver::cli_test {
namespace {

using ClientPrograms = CliTest;

bool installed(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// The number after `label :` in admesh's report, or -1.
double admesh_figure(const std::string& report, const std::string& label) {
  std::smatch match;
  if (!std::regex_search(report, match, std::regex(label + R"(\s*:\s*([0-9.]+))"))) return -1;
  return std::stod(match[1].str());
}

#ifdef PAVER_WITH_CGAL
TEST_F(ClientPrograms, PrusaSlicerAndAdmeshTakeTheFilesAsTheyAre) {
  if (!installed("prusa-slicer") || !installed("admesh"))
    GTEST_SKIP() << "*** PrusaSlicer or admesh is not installed (apt-get install prusa-slicer admesh, as "
                    "app/setup.sh test does): paved.3mf and cut.3mf were NOT checked in the slicer";
  const fs::path out = dir() / "out";
  const CliResult run = paver({"run", "assets/surfaces/pendant.obj", "--stone", "3", "--gap", "0.2", "--beads",
                               "--subtract", "--thickness", "1.5", "--quiet", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << describe(run);

  // --info prints one section per object it loaded; a file it refuses prints "Loading of a model
  // file failed" and no section.
  const CliResult info = run_program("prusa-slicer", {"--info", (out / "paved.3mf").string()}, dir());
  EXPECT_EQ(info.exit_code, 0) << describe(info);
  EXPECT_EQ(info.err.find("Loading of a model file failed"), std::string::npos) << describe(info);
  EXPECT_NE(info.out.find("[paved.3mf]"), std::string::npos) << describe(info);
  EXPECT_NE(info.out.find("manifold = yes"), std::string::npos) << describe(info);

  const fs::path gcode = dir() / "cut.gcode";
  const CliResult slice =
      run_program("prusa-slicer", {"--export-gcode", (out / "cut.3mf").string(), "--output", gcode.string()}, dir());
  EXPECT_EQ(slice.exit_code, 0) << describe(slice);
  ASSERT_TRUE(fs::is_regular_file(gcode)) << describe(slice);
  EXPECT_GT(fs::file_size(gcode), 10000u) << "the metal sliced into layers";

  const CliResult admesh = run_program("admesh", {(out / "cut.stl").string()}, dir());
  EXPECT_EQ(admesh.exit_code, 0) << describe(admesh);
  EXPECT_EQ(admesh_figure(admesh.out, "Number of parts"), 1) << admesh.out;
  EXPECT_EQ(admesh_figure(admesh.out, "Edges fixed"), 0) << admesh.out;
  EXPECT_EQ(admesh_figure(admesh.out, "Facets reversed"), 0) << admesh.out;
  EXPECT_EQ(admesh_figure(admesh.out, "Degenerate facets"), 0) << admesh.out;
}
#endif

}  // namespace
}  // namespace paver::cli_test
