#pragma once
// How an element's shape sits on the surface: its shape's vertex v (unit diameter, +Z up) goes to
// centre + diameter * (v.x t + v.y b + v.z n). The one rule for every consumer: the mesh
// exporters (io/element_export) and the renderer's instances (app/render), so that the preview
// shows what is exported (tested).
#include <glm/vec3.hpp>

namespace paver {

// Columns of the rotation that takes +Z onto the unit normal n. For n.z >= 0 it is the shortest
// arc (the identity for +Z, so an upright element keeps its turn about Z); for n.z < 0 it is a half
// turn about X followed by the shortest arc from -Z. Either way the divisor 1 + |n.z| stays >= 1,
// so no normal, -Z included, makes it blow up; and t x b = n, so triangles keep facing outwards.
struct ElementFrame {
  glm::dvec3 t, b, n;
};

// `normal` need not be unit; a zero or non-finite one leaves the element upright (+Z).
ElementFrame element_frame(glm::dvec3 normal);

// Where shape vertex `v` of an element at `centre` with `diameter` lands.
inline glm::dvec3 place_shape_vertex(const ElementFrame& f, const glm::dvec3& centre, double diameter,
                                     const glm::dvec3& v) {
  const glm::dvec3 local = diameter * v;
  return centre + local.x * f.t + local.y * f.b + local.z * f.n;
}

}  // namespace paver
