// Tests for app/render/element_instance.cpp: the 3D view places every element's shape where the
// exported mesh has it (the preview shows what is exported), for normals in every direction.
#include "element_instance.h"

#include "elements/element_shape.h"
#include "io/element_export.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace paver::render {
namespace {

namespace fs = std::filesystem;

std::vector<glm::dvec3> obj_vertices(const fs::path& path) {
  std::ifstream in(path);
  std::vector<glm::dvec3> out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream fields(line.substr(2));
    glm::dvec3 v;
    fields >> v.x >> v.y >> v.z;
    out.push_back(v);
  }
  return out;
}

TEST(ElementInstance, PreviewPlacesShapesWhereTheExportDoes) {
  Elements elements;
  const std::vector<glm::dvec3> normals = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},     {0, -1, 0},
                                           {1, 2, 3},  {-2, 1, -5}, {0.3, -0.1, -0.02}, {0, 0, 0}};
  const ShapeKind shapes[] = {ShapeKind::Gem, ShapeKind::HexPrism, ShapeKind::Sphere, ShapeKind::Disc};
  for (size_t i = 0; i < normals.size(); ++i) {
    const glm::dvec3 n = glm::length(normals[i]) > 0 ? glm::normalize(normals[i]) : normals[i];
    elements.push_back(ElementKind::Vertex, int(i), 0, {0, 0}, {10.0 * i, -3.0, 2.5}, n, 1.5 + 0.25 * i,
                       shapes[i % 4]);
  }
  const fs::path obj = fs::temp_directory_path() / ("paver_instance_" + std::to_string(::getpid()) + ".obj");
  write_elements_obj(obj, elements);
  const std::vector<glm::dvec3> exported = obj_vertices(obj);
  fs::remove(obj);

  size_t k = 0;
  for (size_t i = 0; i < elements.size(); ++i) {
    SCOPED_TRACE("element " + std::to_string(i));
    const ElementInstance instance = make_element_instance(elements, i, 0u);
    // A right-handed frame, so triangles keep facing outwards.
    EXPECT_NEAR(glm::dot(glm::cross(instance.tangent, instance.bitangent), instance.normal), 1.0f, 1e-5f);
    const ShapeMesh shape = make_builtin_shape(elements.shape[i]);
    for (const glm::vec3& v : shape.positions) {
      ASSERT_LT(k, exported.size());
      const glm::vec3 shown = instance_vertex(instance, v);
      EXPECT_NEAR(glm::distance(glm::dvec3(shown), exported[k]), 0.0, 1e-4) << "shape vertex " << k;
      ++k;
    }
  }
  EXPECT_EQ(k, exported.size());
}

}  // namespace
}  // namespace paver::render
