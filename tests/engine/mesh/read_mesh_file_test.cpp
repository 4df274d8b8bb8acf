// Tests for engine/mesh/read_mesh_file.cpp: the reader is chosen by extension, whatever its case,
// and a file over the size limit is refused before it is read.
#include "mesh/read_mesh_file.h"

#include "input_error_assertions.h"

#include "temp_folder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

namespace paver {
namespace {

using test::Contains;
using test::error_of;

namespace fs = std::filesystem;

class ReadMeshFileTest : public test::TempFolderTest {};

TEST_F(ReadMeshFileTest, ExtensionChoosesTheReaderWhateverItsCase) {
  const PolygonSoup off = read_mesh_file(write("tri.OFF", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "tri.OFF");
  EXPECT_EQ(off.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
  const std::string as_obj = error_of([&] { read_mesh_file(write("tri.obj", "OFF\n3 1 0\n"), "tri.obj"); });
  EXPECT_TRUE(Contains(as_obj, "tri.obj: is not an OBJ file: it starts like an OFF file; give it that extension"));
  // A program renamed .obj: said so, not "contains no faces (0 vertices)".
  const std::string binary = error_of([&] { read_mesh_file(write("prog.obj", std::string("\x7f" "ELF\2\1\1\0", 8)), "prog.obj"); });
  EXPECT_TRUE(Contains(binary, "prog.obj: is not a text OBJ file (it starts with binary data)")) << binary;
}

TEST_F(ReadMeshFileTest, TooLargeFileIsRefusedBeforeReading) {
  const fs::path path = write("huge.stl", "");
  std::error_code error;
  fs::resize_file(path, kMaxMeshFileBytes + 1, error);  // sparse: takes no space
  if (error) GTEST_SKIP() << "cannot make a sparse file here: " << error.message();
  const std::string message = error_of([&] { read_mesh_file(path, "huge.stl"); });
  EXPECT_TRUE(Contains(message, "huge.stl: the file is too large (1073741825 bytes)"));
}

TEST_F(ReadMeshFileTest, DirectoryIsRefused) {
  fs::create_directories(dir_ / "mesh.obj");
  EXPECT_TRUE(Contains(error_of([&] { read_mesh_file(dir_ / "mesh.obj", "mesh.obj"); }), "is a folder"));
}

// A pipe or a device has no length to check counts against (and /dev/zero never ends): refused by kind.
TEST_F(ReadMeshFileTest, PipesAndDevicesAreRefused) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe.obj").c_str(), 0600), 0);
  EXPECT_TRUE(Contains(error_of([&] { read_mesh_file(dir_ / "pipe.obj", "pipe.obj"); }), "pipe.obj: is not a regular file"));
  fs::create_symlink("/dev/zero", dir_ / "zero.obj");
  EXPECT_TRUE(Contains(error_of([&] { read_mesh_file(dir_ / "zero.obj", "zero.obj"); }), "zero.obj: is not a regular file"));
}

}  // namespace
}  // namespace paver
