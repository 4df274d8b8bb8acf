#include "io/gltf_export.h"

#include "core/input_error.h"
#include "elements/element_frame.h"
#include "export_samples.h"
#include "io/shape_table.h"
#include "temp_folder.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

namespace paver {
namespace {

class GltfExport : public test::TempFolderTest {};

tinygltf::Model read_glb(const std::filesystem::path& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = loader.LoadBinaryFromFile(&model, &error, &warning, path.string());
  EXPECT_TRUE(ok) << error;
  EXPECT_TRUE(error.empty()) << error;
  return model;
}

// Where a node's translation, rotation and scale put the shape vertex v.
glm::dvec3 node_places(const tinygltf::Node& node, glm::dvec3 v) {
  const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
  return glm::dvec3(node.translation[0], node.translation[1], node.translation[2]) + q * (node.scale[0] * v);
}

// The float32 positions behind an accessor.
std::vector<float> floats_of(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& a = model.accessors[std::size_t(accessor_index)];
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
  const int width = tinygltf::GetNumComponentsInType(a.type);
  std::vector<float> values(a.count * std::size_t(width));
  std::memcpy(values.data(), model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + a.byteOffset,
              values.size() * sizeof(float));
  return values;
}

TEST_F(GltfExport, EveryElementIsANodeOnItsKindsSharedMeshPlacedAsTheExportPlacesIt) {
  const Elements elements = test::every_shape_elements();
  const SurfaceMesh surface = test::unit_square_surface();
  const std::filesystem::path path = dir_ / "elements.glb";
  write_pavement_glb(path, {.mesh = &surface}, elements, Units::Millimetre);
  const tinygltf::Model model = read_glb(path);

  ASSERT_EQ(model.scenes.size(), 1u);
  ASSERT_EQ(model.scenes[0].nodes.size(), 1u);
  const tinygltf::Node& root = model.nodes[std::size_t(model.scenes[0].nodes[0])];
  ASSERT_EQ(root.scale.size(), 3u);
  EXPECT_DOUBLE_EQ(root.scale[0], 0.001) << "glTF is in metres, the surface in millimetres";
  // The surface and one node per element; one mesh per (shape, kind) used: sphere V, gem E, gem V,
  // hex prism V, disc E, plus the surface's.
  ASSERT_EQ(root.children.size(), 1 + elements.size());
  EXPECT_EQ(model.meshes.size(), 6u);
  EXPECT_TRUE(model.extensionsRequired.empty());

  const ShapeTable shapes(elements, nullptr, path);
  std::map<int, int> mesh_users;
  std::size_t element_nodes = 0;
  for (const int child : root.children) {
    const tinygltf::Node& node = model.nodes[std::size_t(child)];
    if (node.name == "surface") {
      const tinygltf::Primitive& p = model.meshes[std::size_t(node.mesh)].primitives[0];
      EXPECT_EQ(model.accessors[std::size_t(p.attributes.at("POSITION"))].count, surface.positions.size());
      EXPECT_EQ(model.accessors[std::size_t(p.indices)].count, 3 * surface.triangles.size());
      continue;
    }
    ++element_nodes;
    ASSERT_EQ(node.name.rfind("element ", 0), 0u) << node.name;
    const std::size_t i = std::stoul(node.name.substr(8));
    ASSERT_LT(i, elements.size());
    ++mesh_users[node.mesh];
    // Every vertex of the shared mesh lands where the PLY/OBJ writers put it.
    const ElementFrame frame = element_frame(elements.normal[i]);
    const std::vector<float> xyz =
        floats_of(model, model.meshes[std::size_t(node.mesh)].primitives[0].attributes.at("POSITION"));
    const ShapeMesh& shape = shapes[elements.shape[i]];
    ASSERT_EQ(xyz.size(), 3 * shape.positions.size());
    for (std::size_t k = 0; k < shape.positions.size(); ++k) {
      const glm::dvec3 v(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
      const glm::dvec3 expected = place_shape_vertex(frame, elements.position[i], elements.diameter[i], v);
      EXPECT_LT(glm::length(node_places(node, v) - expected), 1e-12 * (1 + glm::length(expected))) << i << " " << k;
    }
  }
  EXPECT_EQ(element_nodes, elements.size());
  // The two gems of different kinds use two meshes (two materials); nothing else repeats.
  EXPECT_EQ(mesh_users.size(), 5u);
}

TEST_F(GltfExport, UnitsScaleTheRootToMetres) {
  const Elements elements = test::every_shape_elements();
  for (const auto& [units, metres] : {std::pair{Units::Inch, 0.0254}, std::pair{Units::Metre, 1.0},
                                      std::pair{Units::Centimetre, 0.01}}) {
    const std::filesystem::path path = dir_ / "units.glb";
    write_pavement_glb(path, {}, elements, units);
    const tinygltf::Model model = read_glb(path);
    EXPECT_DOUBLE_EQ(model.nodes[std::size_t(model.scenes[0].nodes[0])].scale[1], metres);
  }
}

TEST_F(GltfExport, ManyElementsOfAKindBecomeOneInstancedNode) {
  Elements elements;
  const std::size_t n = kGltfInstancingThreshold + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = double(i % 200), y = double(i / 200);
    elements.push_back(ElementKind::Vertex, int(i), 0, {x, y}, {x, y, 0.01 * x}, glm::normalize(glm::dvec3(0.01 * x, 0, 1)),
                       0.9, ShapeKind::Gem);
  }
  elements.push_back(ElementKind::Edge, 0, 0, {0, 0}, {0.5, 0, 0}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  const std::filesystem::path path = dir_ / "many.glb";
  write_pavement_glb(path, {}, elements, Units::Millimetre);
  const tinygltf::Model model = read_glb(path);
  ASSERT_EQ(model.extensionsRequired, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  const tinygltf::Node& root = model.nodes[std::size_t(model.scenes[0].nodes[0])];
  ASSERT_EQ(root.children.size(), 2u) << "one instanced node for the gems, a plain node for the one sphere";
  const tinygltf::Node* instanced = nullptr;
  for (const int child : root.children)
    if (model.nodes[std::size_t(child)].extensions.count("EXT_mesh_gpu_instancing"))
      instanced = &model.nodes[std::size_t(child)];
  ASSERT_NE(instanced, nullptr);
  const tinygltf::Value& attributes = instanced->extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
  const std::vector<float> t = floats_of(model, attributes.Get("TRANSLATION").GetNumberAsInt());
  const std::vector<float> r = floats_of(model, attributes.Get("ROTATION").GetNumberAsInt());
  const std::vector<float> s = floats_of(model, attributes.Get("SCALE").GetNumberAsInt());
  ASSERT_EQ(t.size(), 3 * n);
  ASSERT_EQ(r.size(), 4 * n);
  ASSERT_EQ(s.size(), 3 * n);
  for (const std::size_t i : {std::size_t{0}, std::size_t{4321}, n - 1}) {
    EXPECT_FLOAT_EQ(t[3 * i], float(elements.position[i].x));
    EXPECT_FLOAT_EQ(t[3 * i + 1], float(elements.position[i].y));
    EXPECT_FLOAT_EQ(s[3 * i + 2], 0.9f);
    // The rotation turns +Z onto the element's normal.
    const glm::dquat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);
    EXPECT_LT(glm::length(q * glm::dvec3(0, 0, 1) - elements.normal[i]), 1e-6);
  }
}

TEST_F(GltfExport, AnUnwritableFolderIsAnInputErrorAndLeavesNoFile) {
  const Elements elements = test::every_shape_elements();
  EXPECT_THROW(write_pavement_glb(dir_ / "missing" / "elements.glb", {}, elements, Units::Millimetre), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

// The Khronos glTF validator, when this machine has it: node with the gltf-validator package
// (npm install gltf-validator; PAVER_GLTF_VALIDATOR_MODULES names the node_modules folder if it
// is not on node's own path). Debian does not package it, so CI machines without it skip loudly.
TEST_F(GltfExport, KhronosValidatorFindsNoErrors) {
  const char* modules = std::getenv("PAVER_GLTF_VALIDATOR_MODULES");
  const std::string node_path = modules ? std::string("NODE_PATH='") + modules + "' " : std::string();
  if (std::system((node_path + "node -e \"require('gltf-validator')\" > /dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "*** the Khronos glTF validator is not installed (node + npm gltf-validator): elements.glb was "
                    "read back by tinygltf above but NOT validated here ***";
  const Elements elements = test::every_shape_elements();
  const SurfaceMesh surface = test::unit_square_surface();
  const std::vector<glm::dvec3> normals(surface.positions.size(), glm::dvec3(0, 0, 1));
  const std::filesystem::path plain = dir_ / "plain.glb";
  write_pavement_glb(plain, {.mesh = &surface, .normals = &normals}, elements, Units::Millimetre);
  const std::string script = std::string(PAVER_SOURCE_DIR) + "/tests/support/gltf_validate.js";
  const std::string command = node_path + "node '" + script + "' '" + plain.string() + "' 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  ASSERT_TRUE(pipe);
  std::string output;
  char chunk[4096];
  while (std::fgets(chunk, sizeof chunk, pipe.get())) output += chunk;
  EXPECT_NE(output.find("errors 0 warnings 0"), std::string::npos) << output;
}

}  // namespace
}  // namespace paver
