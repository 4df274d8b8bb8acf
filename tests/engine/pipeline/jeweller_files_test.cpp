// The pendant a jeweller paves with 1.5 mm stones and a 0.1 mm gap (issue 14's "done when"): the
// run's elements.glb and paved.3mf hold every stone of placements.csv, each where the
// placements put it, and the glTF passes the Khronos validator where it is installed.
#include "io/design_io.h"
#include "pipeline/run_pipeline.h"
#include "surface_maps.h"
#include "temp_folder.h"
#include "test_meshes.h"
#include "threemf_read_back.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <tiny_gltf.h>

namespace paver {
namespace {

using JewellerFiles = test::TempFolderTest;

TEST_F(JewellerFiles, PendantStonesAreInTheGlbAndThe3mfOnePerPlacement) {
  PipelineRequest request;
  request.surface_path = test::bundled_surface("pendant");
  request.map = test::bundled_map("pendant");
  request.design.pattern.tessellation = Tessellation::Triangle;
  request.design.elements.gap = 0.1;
  set_stone_size(request.design, 1.5);  // D = stone + gap
  request.out = dir_ / "out";
  const PipelineResult result = run_pipeline(request);
  const Elements& stones = result.pavement.elements;
  ASSERT_GT(stones.size(), 100u);

  tinygltf::TinyGLTF loader;
  tinygltf::Model glb;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&glb, &error, &warning, (dir_ / "out" / "elements.glb").string())) << error;
  const tinygltf::Node& root = glb.nodes[std::size_t(glb.scenes[0].nodes[0])];
  std::size_t stone_nodes = 0;
  for (const int child : root.children) {
    const tinygltf::Node& node = glb.nodes[std::size_t(child)];
    if (node.name == "surface") continue;
    ++stone_nodes;
    const std::size_t i = std::stoul(node.name.substr(8));
    ASSERT_LT(i, stones.size());
    EXPECT_DOUBLE_EQ(node.scale[0], 1.5);
    EXPECT_DOUBLE_EQ(node.translation[0], stones.position[i].x);
    EXPECT_DOUBLE_EQ(node.translation[2], stones.position[i].z);
  }
  EXPECT_EQ(stone_nodes, stones.size());
  EXPECT_EQ(glb.meshes.size(), 2u) << "the pendant and one shared gem";

  const test::ReadBack3mf threemf = test::read_3mf(dir_ / "out" / "paved.3mf");
  EXPECT_EQ(threemf.meshes.size(), 1u) << "one shared gem (the open pendant is no 3MF model)";
  ASSERT_EQ(threemf.components.size(), stones.size());
  ASSERT_EQ(threemf.build_items.size(), 1u);
  // lib3mf writes 6 significant digits of coordinates about the pendant's middle (it is ~30 mm).
  for (std::size_t i = 0; i < stones.size(); ++i) {
    const glm::dvec3 centre = test::apply_3mf(threemf.build_items[0], test::apply_3mf(threemf.components[i].transform, {0, 0, 0}));
    EXPECT_LT(glm::length(centre - stones.position[i]), 2e-4) << "stone " << i << " off by more than 0.2 um";
  }
}

}  // namespace
}  // namespace paver
