#include "io/mesh_formats.h"

#include "core/input_error.h"
#include "io/gltf_export.h"
#include "io/threemf_export.h"

#include <array>
#include <utility>

namespace paver {
namespace {

using Flag = bool MeshFormats::*;
struct FormatName {
  std::string_view name;
  Flag flag;
  std::string_view file;
};
constexpr std::array<FormatName, 5> kFormats = {{{"ply", &MeshFormats::ply, "elements.ply"},
                                                 {"obj", &MeshFormats::obj, "elements.obj"},
                                                 {"stl", &MeshFormats::stl, "elements.stl"},
                                                 {"glb", &MeshFormats::glb, "elements.glb"},
                                                 {"3mf", &MeshFormats::threemf, "paved.3mf"}}};

std::string known_names() {
  std::string text;
  for (const auto& f : kFormats) {
    if (!text.empty()) text += ", ";
    text += f.name;
  }
  return text;
}

}  // namespace

MeshFormats parse_mesh_formats(std::string_view list) {
  MeshFormats formats{false, false, false, false, false};
  bool any = false;
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    const std::string_view name = list.substr(0, comma);
    list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    if (name.empty()) continue;
    bool found = false;
    for (const auto& f : kFormats)
      if (f.name == name) {
        formats.*f.flag = true;
        found = any = true;
      }
    if (!found)
      throw InputError("unknown mesh format '" + std::string(name) + "'; use a comma-separated list of " +
                       known_names());
  }
  if (!any) throw InputError("no mesh format named; use a comma-separated list of " + known_names());
  return formats;
}

std::string mesh_formats_text(const MeshFormats& formats) {
  std::string text;
  for (const auto& f : kFormats)
    if (formats.*f.flag) {
      if (!text.empty()) text += ',';
      text += f.name;
    }
  return text;
}

std::vector<std::string> mesh_file_names(const MeshFormats& formats) {
  std::vector<std::string> names;
  for (const auto& f : kFormats)
    if (formats.*f.flag) names.emplace_back(f.file);
  return names;
}

std::vector<std::string> all_mesh_file_names() { return mesh_file_names({true, true, true, true, true}); }

double expected_mesh_bytes(const ElementMeshSize& size, const MeshFormats& formats, const SurfaceMesh& surface) {
  const auto v = double(size.vertices), f = double(size.faces);
  double bytes = 0;
  if (formats.ply) bytes += 15.0 * v + 13.0 * f;  // binary PLY
  if (formats.obj) bytes += 36.0 * v + 26.0 * f;  // OBJ text, about
  if (formats.stl) bytes += 50.0 * f;             // binary STL
  if (formats.glb) bytes += expected_glb_bytes(size.elements, surface.positions.size(), surface.triangles.size());
  if (formats.threemf)
    bytes += expected_3mf_bytes(size.elements, surface.positions.size(), surface.triangles.size());
  return bytes;
}

}  // namespace paver
