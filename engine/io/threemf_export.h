#pragma once
// paved.3mf: the pavement for printers and CAD (3MF core, written with lib3mf 1.8). One mesh
// object per element shape (unit diameter), shared by every element of it: the object "stones"
// holds one component per element, in placements.csv's order, whose transform places it (uniform
// scale, rotation, translation), so that a large pavement does not hold a copy of the mesh per
// stone. Coordinates are written about the piece's middle, which the two build items (surface,
// stones) add back, because lib3mf writes 6 significant digits. A closed surface (a bead, the cut
// metal) is one "model" object; an open one is left out, since 3MF takes only closed meshes as
// printable models and slicers read nothing else (PrusaSlicer refused the file over it). The
// model's unit is the design's.
#include "design/design.h"
#include "elements/elements.h"
#include "io/element_export.h"
#include "mesh/surface_mesh.h"

#include <cstddef>
#include <filesystem>

namespace paver {

// About how many bytes paved.3mf will take before compression (the writer holds its XML).
double expected_3mf_bytes(std::size_t elements, std::size_t surface_vertices, std::size_t surface_faces);

// `surface` may be null (elements only), and is written only when closed; `surface_name` names its
// object ("metal" for the cut solid). Throws InputError naming `path` when it cannot be written; options.stop is checked
// before the file is written.
void write_pavement_3mf(const std::filesystem::path& path, const SurfaceMesh* surface, const Elements& elements,
                        Units units, const ElementMeshOptions& options = {}, const char* surface_name = "surface");

}  // namespace paver
