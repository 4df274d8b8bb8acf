#pragma once
// One cache of surface maps per test binary: mapping is the slow part of most tests, and every
// test of a surface wants the same map (build_surface_map with the default options).
#include "map/lifting.h"
#include "map/surface_map.h"
#include "mesh/mesh_loader.h"
#include "test_meshes.h"

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace paver::test {

inline std::shared_ptr<const SurfaceMap> cached_map(const std::filesystem::path& path) {
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::shared_ptr<const SurfaceMap>> cache;
  std::lock_guard lock(mutex);
  auto& map = cache[path];
  if (!map) map = std::make_shared<const SurfaceMap>(build_surface_map(load_surface(path).mesh));
  return map;
}

// A bundled surface by name ("dome") or file name ("dome.obj").
inline std::shared_ptr<const SurfaceMap> bundled_map(std::string name) {
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".obj") == 0) name.resize(name.size() - 4);
  return cached_map(bundled_surface(name));
}

// A bundled surface or a scan in assets/scanned, by name.
inline std::shared_ptr<const SurfaceMap> named_map(const std::string& name) {
  for (const std::string& scan : scanned_mesh_names())
    if (scan == name) return cached_map(scanned_mesh(name));
  return bundled_map(name);
}

// The flat unit square [0, 1]^2 at z = 0 (16 x 16 quads), mapped once: its map is a similarity
// of it, so particles on it are measured in 3D after lifting.
inline const SurfaceMap& flat_unit_square() {
  static const SurfaceMap map =
      build_surface_map(grid_surface(16, 16, [](double u, double v) { return glm::dvec3(u, v, 0); }));
  return map;
}

// Map points lifted onto the surface.
inline std::vector<glm::dvec3> lifted_positions(const SurfaceMap& map, const std::vector<glm::dvec2>& uv) {
  LiftedPoints lifted;
  lifted.resize(uv.size());
  lift_points(map, uv, lifted);
  return lifted.position;
}

}  // namespace paver::test
