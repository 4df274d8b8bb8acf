#include "io/gltf_export.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "elements/element_frame.h"
#include "io/atomic_file.h"
#include "io/shape_table.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace paver {
namespace {

// Everything goes into the GLB's one binary chunk; views start on 4-byte boundaries as glTF asks.
class BinaryBuilder {
public:
  explicit BinaryBuilder(tinygltf::Model& model) : model_(model) {
    model_.buffers.emplace_back();
  }

  int vec3_accessor(const std::vector<float>& xyz, bool with_bounds) {
    tinygltf::Accessor a;
    a.bufferView = view(xyz.data(), xyz.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = xyz.size() / 3;
    if (with_bounds) bounds(xyz, 3, a);
    return add(std::move(a));
  }
  int vec4_accessor(const std::vector<float>& xyzw) {
    tinygltf::Accessor a;
    a.bufferView = view(xyzw.data(), xyzw.size() * sizeof(float), -1);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC4;
    a.count = xyzw.size() / 4;
    return add(std::move(a));
  }
  int index_accessor(const std::vector<std::uint32_t>& indices) {
    tinygltf::Accessor a;
    a.bufferView = view(indices.data(), indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = indices.size();
    return add(std::move(a));
  }

private:
  int view(const void* data, std::size_t bytes, int target) {
    auto& buffer = model_.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = bytes;
    if (target >= 0) v.target = target;
    const auto* bytes_begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), bytes_begin, bytes_begin + bytes);
    model_.bufferViews.push_back(std::move(v));
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }
  static void bounds(const std::vector<float>& values, int width, tinygltf::Accessor& a) {
    a.minValues.assign(std::size_t(width), std::numeric_limits<double>::infinity());
    a.maxValues.assign(std::size_t(width), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::size_t c = i % std::size_t(width);
      a.minValues[c] = std::min(a.minValues[c], double(values[i]));
      a.maxValues[c] = std::max(a.maxValues[c], double(values[i]));
    }
  }
  int add(tinygltf::Accessor&& a) {
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  tinygltf::Model& model_;
};

int add_material(tinygltf::Model& model, const char* name, std::array<double, 4> colour, double metallic,
                 double roughness) {
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorFactor = {colour.begin(), colour.end()};
  m.pbrMetallicRoughness.metallicFactor = metallic;
  m.pbrMetallicRoughness.roughnessFactor = roughness;
  model.materials.push_back(std::move(m));
  return static_cast<int>(model.materials.size()) - 1;
}

int add_mesh(tinygltf::Model& model, BinaryBuilder& binary, const std::string& name, const std::vector<float>& xyz,
             const std::vector<float>* normals, const std::vector<std::uint32_t>& indices, int material) {
  tinygltf::Primitive p;
  p.attributes["POSITION"] = binary.vec3_accessor(xyz, true);
  if (normals) p.attributes["NORMAL"] = binary.vec3_accessor(*normals, false);
  p.indices = binary.index_accessor(indices);
  p.material = material;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = name;
  mesh.primitives.push_back(std::move(p));
  model.meshes.push_back(std::move(mesh));
  return static_cast<int>(model.meshes.size()) - 1;
}

int add_node(tinygltf::Model& model, tinygltf::Node&& node) {
  model.nodes.push_back(std::move(node));
  return static_cast<int>(model.nodes.size()) - 1;
}

// An element's placement as glTF's translation, rotation (unit quaternion x, y, z, w) and scale.
struct ElementPose {
  glm::dvec3 translation;
  glm::dquat rotation;
  double scale;
};
ElementPose pose_of(const Elements& elements, std::size_t i) {
  const ElementFrame f = element_frame(elements.normal[i]);
  return {elements.position[i], glm::normalize(glm::quat_cast(glm::dmat3(f.t, f.b, f.n))), elements.diameter[i]};
}

const char* kind_label(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return "vertex stones";
    case ElementKind::Edge: return "edge stones";
    case ElementKind::Face: return "face stones";
    case ElementKind::Bead: return "beads";
  }
  return "elements";
}

std::string mesh_name(ShapeKind shape, ElementKind kind) {
  return std::string(enum_name(shape)) + " (" + kind_label(kind) + ")";
}

}  // namespace

double expected_glb_bytes(std::size_t elements, std::size_t surface_vertices, std::size_t surface_faces) {
  // A node per element is about 170 bytes of JSON; the surface 24 bytes per vertex, 12 per face.
  return 170.0 * double(elements) + 24.0 * double(surface_vertices) + 12.0 * double(surface_faces) + 65536.0;
}

void write_pavement_glb(const std::filesystem::path& path, const GltfSurface& surface, const Elements& elements,
                        Units units, const ElementMeshOptions& options) {
  const ShapeTable shapes(elements, options.custom, path);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Paver";
  BinaryBuilder binary(model);

  tinygltf::Node root;
  root.name = "pavement";
  const double metres = millimetres_per_unit(units) / 1000.0;
  root.scale = {metres, metres, metres};

  if (surface.mesh && surface.mesh->face_count() > 0) {
    const SurfaceMesh& m = *surface.mesh;
    std::vector<float> xyz, normals;
    xyz.reserve(m.positions.size() * 3);
    for (const glm::dvec3& p : m.positions) xyz.insert(xyz.end(), {float(p.x), float(p.y), float(p.z)});
    const bool with_normals = surface.normals && surface.normals->size() == m.positions.size();
    if (with_normals)
      for (const glm::dvec3& n : *surface.normals) {
        const glm::dvec3 u = glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0, 0, 1);
        normals.insert(normals.end(), {float(u.x), float(u.y), float(u.z)});
      }
    std::vector<std::uint32_t> indices;
    indices.reserve(m.triangles.size() * 3);
    for (const glm::ivec3& t : m.triangles)
      indices.insert(indices.end(), {std::uint32_t(t.x), std::uint32_t(t.y), std::uint32_t(t.z)});
    const int metal = add_material(model, "metal", {0.83, 0.69, 0.22, 1.0}, 1.0, 0.3);
    model.materials[std::size_t(metal)].doubleSided = true;  // an open surface is seen from both sides
    tinygltf::Node node;
    node.name = "surface";
    node.mesh = add_mesh(model, binary, "surface", xyz, with_normals ? &normals : nullptr, indices, metal);
    root.children.push_back(add_node(model, std::move(node)));
  }

  // Elements grouped by (shape, kind), each group one shared mesh; the stones get no normals, so
  // viewers shade their facets flat, as cut stones look.
  std::map<std::pair<ShapeKind, ElementKind>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < elements.size(); ++i) groups[{elements.shape[i], elements.kind[i]}].push_back(i);
  // One material per kind in its colour (elements.h): stones glossy, beads metal.
  std::map<ElementKind, int> kind_material;
  bool instancing = false;
  for (const auto& [key, members] : groups) {
    const auto [shape_kind, kind] = key;
    if (!kind_material.count(kind)) {
      const auto c = kind_colour(kind);
      const bool metal = kind == ElementKind::Bead;
      kind_material[kind] = add_material(model, kind_label(kind), {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, 1.0},
                                         metal ? 1.0 : 0.0, metal ? 0.3 : 0.05);
    }
    const int material = kind_material[kind];
    const ShapeMesh& shape = shapes[shape_kind];
    std::vector<float> xyz;
    for (const glm::vec3& p : shape.positions) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    std::vector<std::uint32_t> indices;
    for (const glm::ivec3& t : shape.triangles)
      indices.insert(indices.end(), {std::uint32_t(t.x), std::uint32_t(t.y), std::uint32_t(t.z)});
    const int mesh = add_mesh(model, binary, mesh_name(shape_kind, kind), xyz, nullptr, indices, material);

    if (members.size() <= kGltfInstancingThreshold) {
      for (const std::size_t i : members) {
        const ElementPose p = pose_of(elements, i);
        tinygltf::Node node;
        node.name = "element " + std::to_string(i);
        node.mesh = mesh;
        node.translation = {p.translation.x, p.translation.y, p.translation.z};
        node.rotation = {p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w};
        node.scale = {p.scale, p.scale, p.scale};
        root.children.push_back(add_node(model, std::move(node)));
      }
      continue;
    }
    instancing = true;
    std::vector<float> translations, rotations, scales;
    translations.reserve(members.size() * 3);
    rotations.reserve(members.size() * 4);
    scales.reserve(members.size() * 3);
    for (const std::size_t i : members) {
      const ElementPose p = pose_of(elements, i);
      translations.insert(translations.end(), {float(p.translation.x), float(p.translation.y), float(p.translation.z)});
      rotations.insert(rotations.end(), {float(p.rotation.x), float(p.rotation.y), float(p.rotation.z), float(p.rotation.w)});
      scales.insert(scales.end(), {float(p.scale), float(p.scale), float(p.scale)});
    }
    tinygltf::Value::Object attributes;
    attributes["TRANSLATION"] = tinygltf::Value(binary.vec3_accessor(translations, false));
    attributes["ROTATION"] = tinygltf::Value(binary.vec4_accessor(rotations));
    attributes["SCALE"] = tinygltf::Value(binary.vec3_accessor(scales, false));
    tinygltf::Value::Object extension;
    extension["attributes"] = tinygltf::Value(std::move(attributes));
    tinygltf::Node node;
    node.name = mesh_name(shape_kind, kind) + ", " + std::to_string(members.size()) + " instances";
    node.mesh = mesh;
    node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(std::move(extension));
    root.children.push_back(add_node(model, std::move(node)));
  }
  if (instancing) {
    // Required: a viewer without it would show one stone per kind and look plausible but wrong.
    model.extensionsUsed.push_back("EXT_mesh_gpu_instancing");
    model.extensionsRequired.push_back("EXT_mesh_gpu_instancing");
  }

  tinygltf::Scene scene;
  scene.name = "pavement";
  scene.nodes.push_back(add_node(model, std::move(root)));
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);

  if (options.stop && options.stop->load()) throw Interrupted();
  write_file_atomically(path, [&](std::ostream& out) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true))
      throw InputError("cannot write " + path.string() + ": the glTF writer failed; check the disk space");
  });
}

}  // namespace paver
