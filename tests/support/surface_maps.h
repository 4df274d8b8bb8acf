#pragma once
// One cache of surface maps per test binary: mapping is the slow part of most tests, and every
// test of a surface wants the same map (build_surface_map with the default options).
#include "map/surface_map.h"
#include "mesh/mesh_loader.h"
#include "test_meshes.h"

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

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

}  // namespace paver::test
