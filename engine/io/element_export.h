#pragma once
// Export of the elements for fabrication and for other tools.
#include "design/design.h"
#include "elements/elements.h"
#include "pattern/pattern.h"
#include "mesh/surface_mesh.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace paver {

// placements.csv: header exactly `id,kind,x,y,z,nx,ny,nz,diameter,u,v`, one row per element,
// kind V or E (beads, written after the stones, B), full double precision (17 significant digits).
// `stop`: as ElementMeshOptions::stop below.
void write_placements_csv(const std::filesystem::path& path, const Elements& elements,
                          const std::atomic<bool>* stop = nullptr);

// Every element as real geometry: its shape scaled to its diameter, +Z turned onto its normal,
// moved to its centre. `custom` is the user's shape when any element uses ShapeKind::Custom.
// `colours` (one RGB per element, optional) colour the element's vertices in the PLY; without
// them V-elements are blue and E-elements orange, like the paper's figure 4.
struct ElementMeshOptions {
  const ShapeMesh* custom = nullptr;
  const std::vector<std::array<std::uint8_t, 3>>* colours = nullptr;
  // When it becomes true the writer stops within a MiB and throws Interrupted (core/interrupted.h),
  // leaving no file behind (io/atomic_file.h).
  const std::atomic<bool>* stop = nullptr;
};
// Vertices and triangles of every element's mesh together (the size of the PLY/OBJ/STL): the
// output bound (io/mesh_formats.h) is checked on it before writing.
struct ElementMeshSize {
  std::size_t elements = 0, vertices = 0, faces = 0;
};
ElementMeshSize element_mesh_size(const Elements& elements, const ElementMeshOptions& options = {});
// `count` elements of one shape (`custom` for ShapeKind::Custom).
ElementMeshSize shape_mesh_size(ShapeKind kind, std::size_t count, const ShapeMesh* custom = nullptr);
// The same for a pattern whose elements are not placed yet: one V-element per point (when
// enabled) and one E-element per designed edge element on each real edge, so that a run can be
// refused before the solve. Boundary filling and refill add a few more later.
ElementMeshSize expected_element_mesh_size(const Pattern& pattern, const ElementsDesign& design,
                                           const ElementMeshOptions& options = {});

void write_elements_ply(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options = {});
void write_elements_obj(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options = {});
// Binary STL (for printers and CAM): an 80-byte header, the triangle count, then per triangle its
// unit normal and three vertices as little-endian float32 and a zero attribute word, so the file
// is 84 + 50 * triangles bytes. STL has no colours: options.colours is ignored.
void write_elements_stl(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options = {});

// Any closed or open triangle mesh (the cut solid) as binary STL, the same way; `title` goes into
// the header after "Paver ".
void write_mesh_stl(const std::filesystem::path& path, const SurfaceMesh& mesh, const std::string& title,
                    const std::atomic<bool>* stop = nullptr);

}  // namespace paver
