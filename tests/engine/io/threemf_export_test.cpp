#include "io/threemf_export.h"

#include "core/input_error.h"
#include "elements/element_frame.h"
#include "export_samples.h"
#include "io/shape_table.h"
#include "temp_folder.h"
#include "threemf_read_back.h"

#include <gtest/gtest.h>
#include <Model/COM/NMR_DLLInterfaces.h>

#include <map>
#include <string>
#include <vector>

namespace paver {
namespace {

class ThreeMfExport : public test::TempFolderTest {};

TEST_F(ThreeMfExport, HoldsTheSurfaceOneObjectPerShapeAndAComponentPerElementInOrder) {
  const Elements elements = test::every_shape_elements();
  const SurfaceMesh surface = test::unit_cube_surface();
  const std::filesystem::path path = dir_ / "paved.3mf";
  write_pavement_3mf(path, &surface, elements, Units::Millimetre);
  const test::ReadBack3mf r = test::read_3mf(path);

  EXPECT_EQ(r.unit, DWORD(NMR::MODELUNIT_MILLIMETER));
  ASSERT_EQ(r.meshes.size(), 5u) << "the surface and the four built-in shapes";
  ASSERT_EQ(r.build_items.size(), 2u) << "the surface and the stones";
  // Both items move their object by the same offset (the piece's middle).
  EXPECT_EQ(test::apply_3mf(r.build_items[0], {0, 0, 0}), test::apply_3mf(r.build_items[1], {0, 0, 0}));
  const ShapeTable shapes(elements, nullptr, path);
  std::map<std::string, DWORD> id_by_name;
  for (const auto& [id, m] : r.meshes) {
    id_by_name[m.name] = id;
    if (m.name == "surface") {
      EXPECT_EQ(m.type, DWORD(NMR::MODELOBJECTTYPE_MODEL)) << "a closed surface is a printable solid";
      EXPECT_EQ(m.triangles, 12u);
      for (std::size_t v = 0; v < surface.positions.size(); ++v)
        EXPECT_LT(glm::length(test::apply_3mf(r.build_items[0], m.positions[v]) - surface.positions[v]), 1e-6);
    } else {
      EXPECT_EQ(m.type, DWORD(NMR::MODELOBJECTTYPE_MODEL)) << m.name << ": built-in stones are closed solids";
    }
  }
  ASSERT_EQ(r.components.size(), elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::string name = std::string(enum_name(elements.shape[i])) + " (unit diameter)";
    ASSERT_TRUE(id_by_name.count(name)) << name;
    EXPECT_EQ(r.components[i].object, id_by_name[name]) << i;
    // Each of the shared object's vertices lands where the PLY/OBJ writers put it (float32 file).
    const test::ReadBack3mf::Mesh& m = r.meshes.at(id_by_name[name]);
    const ElementFrame frame = element_frame(elements.normal[i]);
    for (const glm::dvec3& v : m.positions) {
      const glm::dvec3 expected = place_shape_vertex(frame, elements.position[i], elements.diameter[i], v);
      const glm::dvec3 placed = test::apply_3mf(r.build_items[1], test::apply_3mf(r.components[i].transform, v));
      EXPECT_LT(glm::length(placed - expected), 1e-5 * 10) << i << ": 6 digits of a piece 10 units wide";
    }
  }
}

// A piece far from the origin keeps its stones where they are on it: lib3mf writes 6
// significant digits, so coordinates are written about the piece's middle, and only the middle
// itself (the same for surface and stones) is rounded that coarsely.
TEST_F(ThreeMfExport, APieceFarFromTheOriginKeepsItsStonesInPlaceOnIt) {
  Elements elements = test::every_shape_elements();
  SurfaceMesh surface = test::unit_cube_surface();
  const glm::dvec3 far(1e5, -2e5, 3e4);
  for (glm::dvec3& p : elements.position) p += far;
  for (glm::dvec3& p : surface.positions) p += far;
  write_pavement_3mf(dir_ / "far.3mf", &surface, elements, Units::Millimetre);
  const test::ReadBack3mf r = test::read_3mf(dir_ / "far.3mf");
  ASSERT_EQ(r.components.size(), elements.size());
  ASSERT_EQ(r.build_items.size(), 2u);
  const test::ReadBack3mf::Mesh* written_surface = nullptr;
  for (const auto& [id, m] : r.meshes)
    if (m.name == "surface") written_surface = &m;
  ASSERT_NE(written_surface, nullptr);
  const glm::dvec3 corner = written_surface->positions[0];  // surface vertex 0, about the middle
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const glm::dvec3 local = test::apply_3mf(r.components[i].transform, {0, 0, 0});
    EXPECT_LT(glm::length((local - corner) - (elements.position[i] - surface.positions[0])), 1e-5) << i;
  }
}

// The middle goes into the build items as lib3mf prints it, 6 significant digits: a piece in survey
// coordinates keeps its place too (its float middle, 5400003, printed as 5.4e+06, moved it 3 m).
TEST_F(ThreeMfExport, APieceInSurveyCoordinatesStaysWhereItIs) {
  Elements elements = test::every_shape_elements();
  SurfaceMesh surface = test::unit_cube_surface();
  const glm::dvec3 far(500006.15, 5400003.27, 120.5);
  for (glm::dvec3& p : elements.position) p += far;
  for (glm::dvec3& p : surface.positions) p += far;
  write_pavement_3mf(dir_ / "survey.3mf", &surface, elements, Units::Metre);
  const test::ReadBack3mf r = test::read_3mf(dir_ / "survey.3mf");
  ASSERT_EQ(r.build_items.size(), 2u);
  const test::ReadBack3mf::Mesh* written_surface = nullptr;
  for (const auto& [id, m] : r.meshes)
    if (m.name == "surface") written_surface = &m;
  ASSERT_NE(written_surface, nullptr);
  // Both build items carry the middle; the surface's vertices are written about it.
  for (std::size_t v = 0; v < surface.positions.size(); ++v)
    EXPECT_LT(glm::length(test::apply_3mf(r.build_items.front(), written_surface->positions[v]) - surface.positions[v]),
              1e-3)
        << v;
}

TEST_F(ThreeMfExport, BeadsAreAnObjectOfTheirOwn) {
  // The metal's beads sat inside the object named "stones".
  Elements elements = test::every_shape_elements();
  const std::size_t stones = elements.size();
  elements.push_back(ElementKind::Bead, -1, -1, {0, 0}, {1, 1, 0}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  elements.push_back(ElementKind::Bead, -1, -1, {0, 0}, {2, 1, 0}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  const SurfaceMesh surface = test::unit_square_surface();
  write_pavement_3mf(dir_ / "beads.3mf", &surface, elements, Units::Millimetre);
  const test::ReadBack3mf r = test::read_3mf(dir_ / "beads.3mf");
  EXPECT_EQ(r.components.size(), stones);
  EXPECT_EQ(r.bead_components.size(), 2u);
  EXPECT_EQ(r.build_items.size(), 2u) << "the stones and the beads (an open surface is left out)";
}

// PrusaSlicer reads only objects of type "model" and refuses the whole file when a build item or a
// component names any other ("Found item with invalid object id"): an open surface, which 3MF
// does not allow as a model, is left out, and everything the build names is a model.
TEST_F(ThreeMfExport, EverythingTheBuildNamesIsAModelAsSlicersRequire) {
  const Elements elements = test::every_shape_elements();
  const SurfaceMesh open = test::unit_square_surface();
  write_pavement_3mf(dir_ / "open.3mf", &open, elements, Units::Millimetre);
  const test::ReadBack3mf r = test::read_3mf(dir_ / "open.3mf");
  EXPECT_EQ(r.build_items.size(), 1u) << "the stones alone";
  for (const auto& [id, m] : r.meshes) {
    EXPECT_NE(m.name, "surface");
    EXPECT_EQ(m.type, DWORD(NMR::MODELOBJECTTYPE_MODEL)) << m.name;
  }
  for (const auto& c : r.components) EXPECT_TRUE(r.meshes.count(c.object)) << "a component names object " << c.object;
}

TEST_F(ThreeMfExport, TheModelUnitIsTheDesigns) {
  const Elements elements = test::every_shape_elements();
  for (const auto& [units, unit] : {std::pair{Units::Inch, NMR::MODELUNIT_INCH}, std::pair{Units::Metre, NMR::MODELUNIT_METER},
                                    std::pair{Units::Centimetre, NMR::MODELUNIT_CENTIMETER}}) {
    write_pavement_3mf(dir_ / "units.3mf", nullptr, elements, units);
    EXPECT_EQ(test::read_3mf(dir_ / "units.3mf").unit, DWORD(unit));
  }
}

TEST_F(ThreeMfExport, AnUnwritableFolderIsAnInputErrorAndLeavesNoFile) {
  EXPECT_THROW(write_pavement_3mf(dir_ / "missing" / "paved.3mf", nullptr, test::every_shape_elements(), Units::Millimetre),
               InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

}  // namespace
}  // namespace paver
