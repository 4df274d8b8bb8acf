#pragma once
// Small pavements for the exporters' tests: elements of every built-in shape and kind, with
// awkward numbers and normals, on a two-triangle surface.
#include "elements/elements.h"
#include "mesh/surface_mesh.h"

#include <glm/geometric.hpp>

namespace paver::test {

inline Elements every_shape_elements() {
  Elements e;
  e.push_back(ElementKind::Vertex, 0, 0, {0.1, 0.2}, {0, 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Sphere);
  e.push_back(ElementKind::Edge, 3, 1, {1.0 / 3, -2e-7}, {1.25, -2.5, 3.0 / 7}, glm::normalize(glm::dvec3(1, 2, -3)),
              0.5, ShapeKind::Gem);
  e.push_back(ElementKind::Vertex, 7, 0, {2.5, 1e-3}, {-3, 0.5, 2}, {0, 0, -1}, 2.0, ShapeKind::HexPrism);
  e.push_back(ElementKind::Edge, 9, 2, {-0.5, 0.75}, {3, 4, 5}, glm::normalize(glm::dvec3(0.3, -0.1, 0.2)), 0.125,
              ShapeKind::Disc);
  e.push_back(ElementKind::Vertex, 11, 0, {0.5, 0.5}, {1, 1, 0.25}, glm::normalize(glm::dvec3(0.1, 0.2, 1)), 0.75,
              ShapeKind::Gem);
  return e;
}

inline SurfaceMesh unit_square_surface() {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.boundary_loops = {{0, 1, 2, 3}};
  return m;
}

// A closed unit cube, its faces outward: a surface 3MF takes as a printable model.
inline SurfaceMesh unit_cube_surface() {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                 {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return m;
}

}  // namespace paver::test
