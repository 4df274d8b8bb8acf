#pragma once
// Which mesh files a run writes beside its records (placements.csv, stones.csv, design.json and
// report.json, which are always written): the one list that `paver run --formats`, the studio's
// export, the output-size bound and the output guard read.
#include "io/element_export.h"
#include "mesh/surface_mesh.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

struct MeshFormats {
  bool ply = true;      // elements.ply: every element's mesh, coloured by contact
  bool obj = true;      // elements.obj
  bool stl = false;     // elements.stl: binary STL, for printers and CAM
  bool glb = true;      // elements.glb: surface and shared stone meshes, glTF 2.0 (io/gltf_export.h)
  bool threemf = true;  // paved.3mf: surface and shared stone objects, 3MF (io/threemf_export.h)
};

// "ply,obj,glb,3mf" style; an empty list or an unknown name throws InputError saying which
// names exist.
MeshFormats parse_mesh_formats(std::string_view list);
std::string mesh_formats_text(const MeshFormats& formats);

// The files these formats make, by name, in the order they are written.
std::vector<std::string> mesh_file_names(const MeshFormats& formats);
// Every mesh file name any format can make (the output set's known names).
std::vector<std::string> all_mesh_file_names();

// The files a cut of the metal writes (cut/cut_outputs.h), for the shop: the metal with its seats
// and beads (cut.stl, cut.3mf) and the stones alone (stones.3mf), to be set into it.
inline std::vector<std::string> cut_file_names() { return {"cut.stl", "cut.3mf", "stones.3mf"}; }

// About how many bytes the mesh files take: checked before writing (and, from the pattern,
// before the solve) against the user's limit.
double expected_mesh_bytes(const ElementMeshSize& size, const MeshFormats& formats, const SurfaceMesh& surface);

}  // namespace paver
