#include "scene_data.h"

#include "renderer.h"

#include "map/lifting.h"
#include "mesh/surface_mesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace paver::render {

std::uint32_t pack_colour(std::array<std::uint8_t, 3> c, std::uint8_t a) {
  return std::uint32_t(c[0]) | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]) << 16 | std::uint32_t(a) << 24;
}

PreparedElements prepare_elements(const Elements& elements, const std::vector<std::array<std::uint8_t, 3>>& colours,
                                  const ShapeMesh* custom) {
  PreparedElements out;
  const ShapeDetail detail = shape_detail_for(elements.size());
  for (ShapeKind kind : kDrawnShapes) {
    ShapeMesh mesh;
    if (kind == ShapeKind::Custom) {
      if (!custom) continue;
      mesh = *custom;
    } else {
      mesh = make_builtin_shape(kind, detail);
    }
    const std::uint32_t first = std::uint32_t(out.shape_vertices.size());
    for (const auto& t : mesh.triangles)
      for (int c : {t.x, t.y, t.z}) out.shape_vertices.push_back(mesh.positions[c]);
    out.shape_range[kind] = {first, std::uint32_t(out.shape_vertices.size()) - first};
  }
  out.instances.reserve(elements.size());
  out.disks.reserve(elements.size());
  for (ShapeKind kind : kDrawnShapes) {
    if (!out.shape_range.count(kind)) continue;
    const std::uint32_t first = std::uint32_t(out.instances.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if (elements.shape[i] != kind) continue;
      const std::uint32_t colour =
          pack_colour(i < colours.size() ? colours[i] : std::array<std::uint8_t, 3>{200, 200, 200});
      out.instances.push_back(make_element_instance(elements, i, colour));
      out.disks.push_back({glm::vec2(elements.uv[i]), float(0.5 * elements.diameter[i]), colour});
    }
    out.instance_range[kind] = {first, std::uint32_t(out.instances.size()) - first};
  }
  return out;
}

PreparedPattern prepare_pattern(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points) {
  // Each 3D edge is lifted at a few points and raised a hair along the normal, so that the surface
  // does not hide it: 0.2% of the surface's bounding box diagonal.
  constexpr int kSamples = 4;
  PreparedPattern out;
  std::vector<glm::dvec2> samples;
  const std::uint32_t real = pack_colour({30, 90, 200}), virtual_colour = pack_colour({140, 170, 220});
  for (int e = 0; e < pattern.edge_count(); ++e) {
    const glm::dvec2 a = points[pattern.edge_a[e]];
    const glm::dvec2 b = nearest_image(map, points[pattern.edge_b[e]], a);  // across a band's seam
    const std::uint32_t c = pattern.edge_virtual[e] ? virtual_colour : real;
    out.lines2d.push_back({glm::vec3(glm::vec2(a), 0), c});
    out.lines2d.push_back({glm::vec3(glm::vec2(b), 0), c});
    if (pattern.edge_virtual[e]) continue;
    for (int s = 0; s <= kSamples; ++s) samples.push_back(a + (double(s) / kSamples) * (b - a));
  }
  LiftedPoints lifted;
  lifted.resize(samples.size());
  lift_points(map, samples, lifted);
  const double raise = 0.002 * bounding_box_diagonal(map.mesh);
  const std::uint32_t lifted_colour = pack_colour({20, 40, 90});
  for (std::size_t i = 0; i < samples.size(); i += kSamples + 1)
    for (int s = 0; s < kSamples; ++s) {
      const std::size_t p = i + s, q = i + s + 1;
      if (lifted.triangle[p] < 0 || lifted.triangle[q] < 0) continue;
      out.lines3d.push_back({glm::vec3(lifted.position[p] + raise * lifted.normal[p]), lifted_colour});
      out.lines3d.push_back({glm::vec3(lifted.position[q] + raise * lifted.normal[q]), lifted_colour});
    }
  return out;
}

}  // namespace paver::render
