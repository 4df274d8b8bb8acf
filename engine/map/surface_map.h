#pragma once
// The bijection g between the surface M and its 2D map M^ (section 4.2) with everything lifting
// needs: vertex positions and uv, normals, mean curvature, and the point-location grid.
#include "map/arap_parameterization.h"
#include "mesh/surface_mesh.h"
#include "map/uv_grid.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

inline constexpr double kCurvatureLowPercentile = 0.05;
inline constexpr double kCurvatureHighPercentile = 0.95;

struct SurfaceMap;

// Eq. 5's normalised curvature: |H| = kappa placed between the map's curvature_min and
// curvature_max, clamped to [0, 1]; 0 on a surface whose curvature does not vary.
double normalised_curvature(const SurfaceMap& map, double kappa);

struct SurfaceMap {
  SurfaceMesh mesh;                    // M: positions, triangles, boundary loop
  std::vector<glm::dvec2> uv;          // #V: M^, 2D area equals 3D area
  std::vector<glm::dvec3> normals;     // #V unit vertex normals
  std::vector<double> curvature;       // #V mean curvature |H|
  double curvature_min = 0, curvature_max = 0;  // |H| at the percentiles below: eq. 5's normalisation
  UvGrid grid;
  glm::dvec2 uv_min{0}, uv_max{0};     // bounding box of M^ (its centre is O(M^), eq. 12)
  Parameterization parameterization;   // how the map was made and how good it is
};

// Parameterizes the mesh (ARAP, bijective) and builds the lifting data; throws as above.
SurfaceMap build_surface_map(SurfaceMesh mesh, const ArapOptions& options = {});

// Builds the lifting data for a given map (uv: #V, bijective).
SurfaceMap make_surface_map(SurfaceMesh mesh, std::vector<glm::dvec2> uv);

// The lifting data for a finished parameterization, which the map keeps. Throws
// std::runtime_error when it is not bijective: ARAP here keeps it bijective by construction, so
// that would be a bug to report, and lifting through a folded map would be wrong.
SurfaceMap make_surface_map(SurfaceMesh mesh, Parameterization parameterization);

}  // namespace paver
