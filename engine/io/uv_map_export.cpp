#include "io/uv_map_export.h"

#include "io/atomic_file.h"

#include <cstdio>

namespace paver {

void write_uv_map_obj(const std::filesystem::path& path, const SurfaceMesh& mesh,
                      const std::vector<glm::dvec2>& uv) {
  write_file_atomically(path, [&](std::ostream& out) {
    char line[128];
    out << "# paver parameterization: " << mesh.vertex_count() << " vertices, " << mesh.face_count()
        << " faces; vt is the 2D map, its area equals the surface's\n";
    for (const auto& p : mesh.positions) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
      out << line;
    }
    for (const auto& q : uv) {
      std::snprintf(line, sizeof line, "vt %.9g %.9g\n", q.x, q.y);
      out << line;
    }
    for (const auto& t : mesh.triangles) {
      std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", t.x + 1, t.x + 1, t.y + 1, t.y + 1, t.z + 1, t.z + 1);
      out << line;
    }
  });
}

}  // namespace paver
