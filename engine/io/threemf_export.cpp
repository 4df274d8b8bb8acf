#include "io/threemf_export.h"

#include "core/float32_rounding.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "elements/element_frame.h"
#include "io/atomic_file.h"
#include "io/shape_table.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <glm/common.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace paver {
namespace {

// Owns one lib3mf handle: every object the C API hands out is released once.
class Handle {
public:
  Handle() = default;
  explicit Handle(NMR::PLib3MFBase* h) : h_(h) {}
  ~Handle() {
    if (h_) NMR::lib3mf_release(h_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  NMR::PLib3MFBase* get() const { return h_; }
  NMR::PLib3MFBase** out() { return &h_; }

private:
  NMR::PLib3MFBase* h_ = nullptr;
};

class Writer3mf {
public:
  explicit Writer3mf(const std::filesystem::path& path) : path_(path) {}

  void check(LIB3MFRESULT result, const Handle& on, const char* what) const {
    if (result == LIB3MF_OK) return;
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (on.get()) NMR::lib3mf_getlasterror(on.get(), &code, &message);
    throw InputError("cannot write " + path_.string() + ": " + what + " failed (lib3mf: " +
                     (message ? std::string(message) : "error " + std::to_string(result)) + ")");
  }

private:
  std::filesystem::path path_;
};

NMR::eModelUnit model_unit(Units units) {
  switch (units) {
    case Units::Millimetre: return NMR::MODELUNIT_MILLIMETER;
    case Units::Centimetre: return NMR::MODELUNIT_CENTIMETER;
    case Units::Metre: return NMR::MODELUNIT_METER;
    case Units::Inch: return NMR::MODELUNIT_INCH;
  }
  return NMR::MODELUNIT_MILLIMETER;
}

// Adds a mesh object; a closed, consistently oriented one is a printable "model", anything else
// a "surface" (3MF forbids open meshes as models; only a custom shape can be one).
void add_mesh_object(const Writer3mf& w, const Handle& model, Handle& object, const std::string& name,
                     std::vector<NMR::MODELMESHVERTEX>& vertices, std::vector<NMR::MODELMESHTRIANGLE>& triangles) {
  w.check(NMR::lib3mf_model_addmeshobject(model.get(), object.out()), model, "adding an object");
  w.check(NMR::lib3mf_meshobject_setgeometry(object.get(), vertices.data(), DWORD(vertices.size()),
                                             triangles.data(), DWORD(triangles.size())),
          object, "setting a mesh");
  w.check(NMR::lib3mf_object_setnameutf8(object.get(), name.c_str()), object, "naming an object");
  BOOL manifold = false;
  w.check(NMR::lib3mf_meshobject_ismanifoldandoriented(object.get(), &manifold), object, "checking a mesh");
  w.check(NMR::lib3mf_object_settype(object.get(), manifold ? NMR::MODELOBJECTTYPE_MODEL : NMR::MODELOBJECTTYPE_SURFACE),
          object, "setting an object's type");
}

// The middle of the piece's bounding box, rounded to 6 significant digits (and so to a float that
// prints back as the same digits), so that the build items carry it exactly as lib3mf prints
// them: a piece in survey coordinates (5,400,003 m) moved 3 m when its float middle was printed.
glm::dvec3 middle_of(const SurfaceMesh* surface, const Elements& elements) {
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  const auto add = [&](const glm::dvec3& p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  };
  if (surface)
    for (const glm::dvec3& p : surface->positions) add(p);
  for (const glm::dvec3& p : elements.position) add(p);
  if (!(low.x <= high.x)) return glm::dvec3(0);
  const glm::dvec3 middle = 0.5 * (low + high);
  glm::dvec3 printable;
  for (int axis = 0; axis < 3; ++axis) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.6g", middle[axis]);
    printable[axis] = rounded_to_float32(std::strtod(digits, nullptr));
  }
  return printable;
}

}  // namespace

double expected_3mf_bytes(std::size_t elements, std::size_t surface_vertices, std::size_t surface_faces) {
  // A component with its transform is about 150 bytes of XML; a vertex 60, a triangle 45.
  return 150.0 * double(elements) + 60.0 * double(surface_vertices) + 45.0 * double(surface_faces) + 65536.0;
}

void write_pavement_3mf(const std::filesystem::path& path, const SurfaceMesh* surface, const Elements& elements,
                        Units units, const ElementMeshOptions& options, const char* surface_name) {
  const ShapeTable shapes(elements, options.custom, path);
  const Writer3mf w(path);
  Handle model;
  w.check(NMR::lib3mf_createmodel(model.out()), model, "creating the model");
  w.check(NMR::lib3mf_model_setunit(model.get(), model_unit(units)), model, "setting the unit");
  w.check(NMR::lib3mf_model_addmetadatautf8(model.get(), "Application", "Paver"), model, "adding metadata");

  std::vector<NMR::MODELMESHVERTEX> vertices;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  const auto triangles_of = [&](const auto& source) {
    triangles.clear();
    for (const glm::ivec3& t : source)
      triangles.push_back({{DWORD(t.x), DWORD(t.y), DWORD(t.z)}});
  };

  // lib3mf writes transforms with 6 significant digits: placed about the middle of the piece, a
  // stone is off by at most 5e-6 of the piece's size (0.15 um on a 30 mm pendant) wherever the
  // piece sits; the middle itself, already at 6 digits, goes into the build items exactly.
  const glm::dvec3 middle = middle_of(surface, elements);
  NMR::MODELTRANSFORM to_middle{};
  for (int row = 0; row < 3; ++row) {
    to_middle.m_fFields[row][row] = 1;
    to_middle.m_fFields[row][3] = float(middle[row]);
  }
  // An open surface cannot be a build item that slicers take: 3MF allows only closed meshes as
  // printable "model" objects, and PrusaSlicer reads nothing else (a build item of type "surface"
  // made it refuse the whole file: "Found item with invalid object id"). It is left out; the
  // surface is in elements.glb.
  if (surface && surface->face_count() > 0 && surface->boundary_loops.empty()) {
    vertices.clear();
    for (const glm::dvec3& position : surface->positions) {
      const glm::dvec3 p = position - middle;
      vertices.push_back({{float(p.x), float(p.y), float(p.z)}});
    }
    triangles_of(surface->triangles);
    Handle object, item;
    add_mesh_object(w, model, object, surface_name, vertices, triangles);
    w.check(NMR::lib3mf_model_addbuilditem(model.get(), object.get(), &to_middle, item.out()), model,
            "adding the surface");
  }

  std::array<Handle, ShapeTable::kKinds> shape_objects;
  for (std::size_t k = 0; k < ShapeTable::kKinds; ++k) {
    const auto kind = static_cast<ShapeKind>(k);
    if (!shapes.used(kind)) continue;
    const ShapeMesh& shape = shapes[kind];
    vertices.clear();
    for (const glm::vec3& p : shape.positions) vertices.push_back({{p.x, p.y, p.z}});
    triangles_of(shape.triangles);
    add_mesh_object(w, model, shape_objects[k], std::string(enum_name(kind)) + " (unit diameter)", vertices,
                    triangles);
  }

  // The stones are components of one object with one build item: lib3mf 1.8 adds build items in
  // time linear in their number (quadratic overall: 10 s for 40,000), components in constant time.
  // The beads (the metal's prongs) are an object of their own, not stones.
  const auto add_group = [&](const char* name, bool beads) {
    const auto in_group = [&](std::size_t i) { return (elements.kind[i] == ElementKind::Bead) == beads; };
    bool any = false;
    for (std::size_t i = 0; i < elements.size() && !any; ++i) any = in_group(i);
    if (!any) return;
    Handle stones, item;
    w.check(NMR::lib3mf_model_addcomponentsobject(model.get(), stones.out()), model, "adding the stones");
    w.check(NMR::lib3mf_object_setnameutf8(stones.get(), name), stones, "naming the stones");
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if ((i & 0xffff) == 0 && options.stop && options.stop->load()) throw Interrupted();
      if (!in_group(i)) continue;
      const ElementFrame f = element_frame(elements.normal[i]);
      const double d = elements.diameter[i];
      NMR::MODELTRANSFORM transform{};
      const std::array<glm::dvec3, 3> columns = {f.t * d, f.b * d, f.n * d};
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) transform.m_fFields[row][col] = float(columns[std::size_t(col)][row]);
        transform.m_fFields[row][3] = float(elements.position[i][row] - middle[row]);
      }
      Handle component;
      w.check(NMR::lib3mf_componentsobject_addcomponent(stones.get(), shape_objects[std::size_t(elements.shape[i])].get(),
                                                         &transform, component.out()),
              stones, "adding an element");
    }
    w.check(NMR::lib3mf_model_addbuilditem(model.get(), stones.get(), &to_middle, item.out()), model,
            "adding the stones");
  };
  add_group("stones", false);
  add_group("beads", true);

  if (options.stop && options.stop->load()) throw Interrupted();
  write_file_atomically_by_name(path, [&](const std::filesystem::path& temporary) {
    Handle writer;
    w.check(NMR::lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model, "creating the writer");
    w.check(NMR::lib3mf_writer_writetofileutf8(writer.get(), temporary.string().c_str()), writer,
            "writing the file (is the disk full?)");
  });
}

}  // namespace paver
