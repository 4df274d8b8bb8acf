#pragma once
// elements.glb: the whole pavement for renderers and viewers, as glTF 2.0 binary (written with
// tinygltf). The surface is one mesh in a metal material; each element shape and kind (V or E)
// is one mesh in a stone material, shared by every element of that kind: a node per element
// places it (translation, rotation, uniform scale), or, above kGltfInstancingThreshold elements
// of a kind, one node with EXT_mesh_gpu_instancing carries all their transforms, so that a
// million stones do not become a million nodes. glTF lengths are metres: a root node scales the
// surface's units to them (Design::units).
#include "design/design.h"
#include "elements/elements.h"
#include "io/element_export.h"
#include "mesh/surface_mesh.h"

#include <cstddef>
#include <filesystem>
#include <vector>

namespace paver {

// Blender 3.4 cannot open a file that requires EXT_mesh_gpu_instancing, and imports a node per stone
// at about 0.7 ms each: up to 100,000 stones of a kind, nodes (a file Blender opens in about a
// minute); above, where no importer would finish anyway, the extension keeps the file small.
inline constexpr std::size_t kGltfInstancingThreshold = 100000;

struct GltfSurface {
  const SurfaceMesh* mesh = nullptr;             // null: elements only
  const std::vector<glm::dvec3>* normals = nullptr;  // #V unit vertex normals (smooth shading), optional
};

// About how many bytes elements.glb will take (checked before writing with the other meshes).
double expected_glb_bytes(std::size_t elements, std::size_t surface_vertices, std::size_t surface_faces);

// Throws InputError naming `path` when it cannot be written; options.stop as in element_export.h
// (checked before the file is serialised). options.colours is not used: stones get their kind's
// material.
void write_pavement_glb(const std::filesystem::path& path, const GltfSurface& surface, const Elements& elements,
                        Units units, const ElementMeshOptions& options = {});

}  // namespace paver
