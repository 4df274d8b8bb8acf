#include "mesh/read_mesh_file.h"

#include "mesh/mesh_messages.h"
#include "mesh/obj_reader.h"
#include "mesh/off_reader.h"
#include "mesh/ply_reader.h"
#include "mesh/reader_support.h"
#include "mesh/stl_reader.h"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace paver {
namespace {

using namespace mesh_detail;

std::string read_bytes(const std::filesystem::path& path, const std::string& source) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) fail(source, "file not found; check the path");
  if (std::filesystem::is_directory(status)) fail(source, "is a directory, not a mesh file");
  // A device or a pipe has no length to check a file's counts against before reading it.
  if (!std::filesystem::is_regular_file(status))
    fail(source, "is not a regular file (a device, pipe or socket); save the mesh to a file and give its path");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) fail(source, "cannot be read (" + error.message() + ")");
  if (size > kMaxMeshFileBytes)
    fail(source, "the file is too large (" + std::to_string(size) + " bytes); Paver reads mesh files of up to " +
                     std::to_string(kMaxMeshFileBytes >> 20) + " MiB: simplify the mesh first");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(source, "cannot be opened for reading; check its permissions");
  std::string bytes(size, '\0');
  in.read(bytes.data(), std::streamsize(size));
  // A file that changed size while being read is read again by the user, not guessed at.
  if (in.bad() || std::uintmax_t(in.gcount()) != size || in.peek() != std::ifstream::traits_type::eof())
    fail(source, "could not be read (I/O error, or the file changed while being read)");
  if (bytes.empty()) fail(source, "the file is empty (0 bytes), so it contains no faces; export the surface again");
  return bytes;
}

}  // namespace

std::span<const std::string_view> mesh_file_extensions() {
  static constexpr std::string_view kExtensions[] = {".obj", ".off", ".ply", ".stl"};
  return kExtensions;
}

PolygonSoup read_mesh_file(const std::filesystem::path& path, const std::string& source) {
  const std::string extension = lowercase(path.extension().string());
  if (std::ranges::find(mesh_file_extensions(), extension) == mesh_file_extensions().end())
    fail(source, (extension.empty() ? std::string("has no file extension")
                                    : "unsupported file type '" + path.extension().string() + "'") +
                     "; Paver reads surfaces in OBJ, OFF, PLY (ASCII or binary) and STL (ASCII or binary) format "
                     "(.obj, .off, .ply, .stl)");
  const std::string bytes = read_bytes(path, source);
  if (extension == ".obj") return read_obj(bytes, source);
  if (extension == ".off") return read_off(bytes, source);
  if (extension == ".ply") return read_ply(bytes, source);
  return read_stl(bytes, source);
}

}  // namespace paver
