#pragma once
// A triangulation of points that lie on the surface, given by their map (uv) positions and their
// lifted 3D positions: Delaunay in the map, then edge flips until every interior edge is Delaunay
// by the surface's own angles (the two opposite angles, measured in 3D, sum to at most pi), so
// the connectivity follows the surface where the map shears it. The adaptive pattern connects its
// particles with it.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace paver {

// For each triangle, the triangle across the edge opposite each of its corners (-1 where none):
// triangles that share an edge in opposite directions. Corner indices are >= 0.
std::vector<glm::ivec3> triangle_neighbours(const std::vector<glm::ivec3>& triangles);

// Delaunay triangulation of 2D points (Bowyer-Watson): counter-clockwise triangles covering their
// convex hull. Duplicate points are left out of every triangle.
std::vector<glm::ivec3> delaunay_triangulation(std::span<const glm::dvec2> points);

// Flips interior edges of `triangles` (counter-clockwise in `uv`) until the opposite angles in 3D
// (`position`) sum to at most pi + 1e-9 wherever the flip keeps the uv triangles positive.
// Returns how many edges were flipped.
int flip_to_surface_delaunay(std::vector<glm::ivec3>& triangles, std::span<const glm::dvec2> uv,
                             std::span<const glm::dvec3> position);

// Delaunay in uv, flipped to the surface's angles; triangles with a 3D edge longer than
// `longest_edge` (across a concave stretch of the boundary) are left out.
std::vector<glm::ivec3> triangulate_surface_points(std::span<const glm::dvec2> uv,
                                                   std::span<const glm::dvec3> position, double longest_edge);

}  // namespace paver
