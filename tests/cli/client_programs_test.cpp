// The programs jewellers open Paver's files with, run on a small pavement's files as they are:
// PrusaSlicer loads paved.3mf and slices cut.3mf, admesh finds cut.stl one closed part needing no
// repair, Blender 3.4 imports elements.glb with every stone where placements.csv has it.
// app/setup.sh test installs them (Debian's prusa-slicer, admesh, blender and python3-numpy); a
// machine without them skips, loudly, saying what to install.
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace paver::cli_test {
namespace {

using ClientPrograms = CliTest;

bool installed(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

#ifdef PAVER_WITH_CGAL
// The number after `label :` in admesh's report, or -1 (only the cut's test reads admesh).
double admesh_figure(const std::string& report, const std::string& label) {
  std::smatch match;
  if (!std::regex_search(report, match, std::regex(label + R"(\s*:\s*([0-9.]+))"))) return -1;
  return std::stod(match[1].str());
}

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

// Blender 3.4 refused every elements.glb over 20,000 stones ("Extension EXT_mesh_gpu_instancing is
// not available"): a node per stone now up to kGltfInstancingThreshold. Here a small pendant, every
// stone imported, at its place in metres (glTF's unit; Blender turns glTF's y-up into its z-up, so
// the extents are compared as a set).
TEST_F(ClientPrograms, BlenderImportsEveryStoneAtItsPlace) {
  if (!installed("blender"))
    GTEST_SKIP() << "*** Blender is not installed (apt-get install blender python3-numpy, as app/setup.sh test "
                    "does): elements.glb was NOT imported into Blender";
  const fs::path out = dir() / "out";
  const CliResult run = paver({"run", "assets/surfaces/pendant.obj", "--stone", "3", "--gap", "0.2", "--formats", "glb",
                               "--quiet", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  const CliResult blender = run_program(
      "blender", {"-b", "--python", std::string(PAVER_SOURCE_DIR) + "/tests/support/blender_import.py", "--",
                  (out / "elements.glb").string()},
      dir());
  EXPECT_EQ(blender.exit_code, 0) << describe(blender);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(blender.out, match, std::regex(R"(imported (\d+) (\d+) (\S+) (\S+) (\S+))")))
      << describe(blender);
  // placements.csv: id,kind,x,y,z,... in millimetres.
  std::ifstream csv(out / "placements.csv");
  std::string line;
  std::getline(csv, line);
  std::size_t stones = 0;
  std::array<double, 3> extent{};
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string field;
    std::vector<std::string> row;
    while (std::getline(fields, field, ',')) row.push_back(field);
    ASSERT_GE(row.size(), 5u) << line;
    ++stones;
    for (int axis = 0; axis < 3; ++axis) extent[axis] = std::max(extent[axis], std::abs(std::stod(row[2 + axis])) * 1e-3);
  }
  EXPECT_EQ(std::stoul(match[1].str()), stones) << "every stone imported";
  std::array<double, 3> imported = {std::stod(match[3].str()), std::stod(match[4].str()), std::stod(match[5].str())};
  std::sort(extent.begin(), extent.end());
  std::sort(imported.begin(), imported.end());
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(imported[axis], extent[axis], 1e-6) << "the stones where placements.csv has them, in metres";
}

}  // namespace
}  // namespace paver::cli_test
