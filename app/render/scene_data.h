#pragma once
// What the views draw, prepared on the CPU before it is copied into the renderer's buffers: the
// vertex and instance layouts the shaders read, and the elements and pattern lines built in them.
// Preparing touches no Vulkan object, so any thread may do it: the studio prepares each live
// snapshot of a run off its UI thread, and the upload on it is a copy.
#include "element_instance.h"

#include "elements/element_shape.h"
#include "elements/elements.h"
#include "map/surface_map.h"
#include "pattern/pattern.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace paver::render {

struct FlatVertex {
  glm::vec3 position;
  std::uint32_t colour;  // RGBA8
};
struct DiskInstance {
  glm::vec2 centre;
  float radius;
  std::uint32_t colour;
};

std::uint32_t pack_colour(std::array<std::uint8_t, 3> rgb, std::uint8_t alpha = 255);

// The shapes drawn in the order the renderer draws them.
inline constexpr ShapeKind kDrawnShapes[] = {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::HexPrism, ShapeKind::Disc,
                                             ShapeKind::Custom};

using DrawRange = std::pair<std::uint32_t, std::uint32_t>;  // first, count

struct PreparedElements {
  // All shapes' triangles, expanded (the fragment shader makes flat normals), by shape.
  std::vector<glm::vec3> shape_vertices;
  std::map<ShapeKind, DrawRange> shape_range;     // vertices
  std::vector<ElementInstance> instances;         // 3D, grouped by shape
  std::map<ShapeKind, DrawRange> instance_range;  // instances
  std::vector<DiskInstance> disks;                // 2D, in the instances' order
};
// `colours` per element (grey where missing); shapes in the detail their count calls for.
PreparedElements prepare_elements(const Elements& elements, const std::vector<std::array<std::uint8_t, 3>>& colours,
                                  const ShapeMesh* custom);

struct PreparedPattern {
  std::vector<FlatVertex> lines2d, lines3d;  // line lists
};
// 2D: straight edges. 3D: each edge lifted at a few points so it follows the surface.
PreparedPattern prepare_pattern(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points);

}  // namespace paver::render
