#pragma once
// Writes a mesh as an OBJ file, byte for byte the same on every run.
#include "mesh_building.h"

#include <filesystem>
#include <string_view>

namespace paver::assetgen {

// Writes OUTDIR/name.obj through a temporary file and an atomic rename, so a reader (or a
// parallel build) never sees half a file.
// Throws std::runtime_error ("name: what went wrong") on failure.
void write_obj(const std::filesystem::path& dir, std::string_view name, const Mesh& m);

}  // namespace paver::assetgen
