#pragma once
// The bijection g between the surface M and its 2D map M^ (section 4.2) with everything lifting
// needs: vertex positions and uv, normals, mean curvature, and the point-location grid.
#include "map/bijective_map.h"
#include "mesh/surface_mesh.h"
#include "map/uv_grid.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace paver {

inline constexpr double kCurvatureLowPercentile = 0.05;
inline constexpr double kCurvatureHighPercentile = 0.95;

struct SurfaceMap;

// Eq. 5's normalised curvature: |H| = kappa placed between the map's curvature_min and
// curvature_max, clamped to [0, 1]; 0 on a surface whose curvature does not vary.
double normalised_curvature(const SurfaceMap& map, double kappa);

// The triangles of a map that wraps (a band's seamless map), laid out for point location: each
// triangle in one piece (its corners shifted by whole periods as needed), three times: first as
// is (triangle t of the mesh is triangle t here), then shifted by -T, then by +T.
struct MapDomain {
  std::vector<glm::dvec2> uv;         // domain vertices
  std::vector<int> vertex;            // the mesh vertex each one copies
  std::vector<glm::ivec3> triangles;  // 3 #F
};

struct SurfaceMap {
  SurfaceMesh mesh;                    // M: positions, triangles, boundary loop
  std::vector<glm::dvec2> uv;          // #V: M^, 2D area equals 3D area
  std::vector<glm::dvec3> normals;     // #V unit vertex normals
  std::vector<double> curvature;       // #V mean curvature |H|
  double curvature_min = 0, curvature_max = 0;  // |H| at the percentiles below: eq. 5's normalisation
  UvGrid grid;
  glm::dvec2 uv_min{0}, uv_max{0};     // bounding box of M^ (its centre is O(M^), eq. 12)
  Parameterization parameterization;   // how the map was made and how good it is

  // A map that wraps (docs/holes_and_bands.md, "Seamless bands"): the plane repeats every
  // T = (period, 0); points wrap into u in [period_origin, period_origin + period), and `grid`
  // is over `domain`. uv_min/uv_max then frame one period. 0 for a map that does not wrap.
  double period = 0;
  double period_origin = 0;
  MapDomain domain;

  // A band (two boundary loops) is mapped twice: this map, an annulus (which the adaptive pattern
  // paves), and its seamless map, or the reason it has none.
  std::shared_ptr<const SurfaceMap> seamless;
  std::string seamless_unavailable;

  // A closed surface's atlas (map/surface_charts.h): `mesh` is its charts side by side (the seam
  // vertices once per chart), every boundary loop a seam. Empty for an open surface.
  std::vector<int> chart_of_face;
  int closed_surface_vertices = 0, closed_surface_faces = 0;  // the closed surface as loaded
  // The closed surface as cut (faces split along the plane, seams not duplicated) and its vertex
  // normals: the metal under its pavement is thickened from it, so no wall stands at a seam.
  SurfaceMesh closed_surface;
  std::vector<glm::dvec3> closed_surface_normals;
  glm::dvec3 cut_normal{0.0};  // the normal of the plane it was cut by
};

inline bool map_wraps(const SurfaceMap& map) { return map.period > 0; }
inline bool is_atlas(const SurfaceMap& map) { return !map.chart_of_face.empty(); }
inline int chart_count(const SurfaceMap& map) {
  return is_atlas(map) ? 1 + *std::max_element(map.chart_of_face.begin(), map.chart_of_face.end()) : 1;
}
// A band: two boundary loops that are rims (not an atlas's seams).
inline bool is_band(const SurfaceMap& map) { return map.mesh.boundary_loops.size() == 2 && !is_atlas(map); }

// The free band elements keep along the boundary: the design's margin at rims. An atlas (a closed
// surface cut into charts) has no rims, only seams, so the margin is not used there: half the gap
// instead, so that two elements facing each other across a seam keep it. (Letting elements reach
// across seams and removing the pairs that collide there was measured worse: fill 0.75 and 0.62
// instead of 0.86 and 0.87 on the bead and the closed bunny head, tri.)
inline double boundary_margin(const SurfaceMap& map, double margin, double gap) {
  return is_atlas(map) ? 0.5 * gap : margin;
}

// Sets curvature_min / curvature_max from `curvature` (the percentiles below).
void set_curvature_range(SurfaceMap& map);

// p with its u wrapped into the map's period (p itself for a map that does not wrap).
glm::dvec2 wrap_point(const SurfaceMap& map, glm::dvec2 p);

// The copy of p (p + k T) nearest to `near`: the other end of a spring or an edge that crosses the
// seam. p itself for a map that does not wrap.
glm::dvec2 nearest_image(const SurfaceMap& map, glm::dvec2 p, glm::dvec2 near);

// Triangle t's corners in the map, in one piece.
std::array<glm::dvec2, 3> triangle_uv(const SurfaceMap& map, int t);

// The mesh triangle containing p (wrapped first), or -1; `bary` as uv_grid's locate.
int locate_on_map(const SurfaceMap& map, glm::dvec2 p, glm::dvec3& bary);

// Parameterizes the mesh (bijective, with map_options_for; a closed one as an atlas of charts cut across its
// longest axis, map/surface_charts.h) and builds the lifting data; throws as above.
SurfaceMap build_surface_map(SurfaceMesh mesh);

// Builds the lifting data for a given map (uv: #V, bijective).
SurfaceMap make_surface_map(SurfaceMesh mesh, std::vector<glm::dvec2> uv);

// The lifting data for a finished parameterization, which the map keeps. Throws
// std::runtime_error when it is not bijective: the map here keeps it bijective by construction, so
// that would be a bug to report, and lifting through a folded map would be wrong.
SurfaceMap make_surface_map(SurfaceMesh mesh, Parameterization parameterization);

}  // namespace paver
