// Rows along a world axis (placement.align): on the bundled curved facade, whose map turns a grid
// 26.6 degrees off the floor, the paved rows run level with align x (measured on the pavement's
// own neighbour directions, in 3D), the resolved design repeats the same lattice without the key,
// and an axis normal to a flat wall is refused with the key named.
#include "core/input_error.h"
#include "io/design_io.h"
#include "pattern/row_alignment.h"
#include "pipeline/pavement.h"
#include "pipeline/run_pipeline.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace paver {
namespace {

// The median, over V-elements, of the angle between the 3D direction to the nearest other
// V-element and `axis`, folded into [0, 45] degrees (a grid's rows and columns are both rows).
double median_grid_angle_to(const Elements& e, glm::dvec3 axis) {
  std::vector<glm::dvec3> centres;
  for (std::size_t i = 0; i < e.size(); ++i)
    if (e.kind[i] == ElementKind::Vertex) centres.push_back(e.position[i]);
  std::vector<double> angles;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    double nearest = 1e300;
    glm::dvec3 to(0);
    for (std::size_t j = 0; j < centres.size(); ++j) {
      const double d = glm::length(centres[j] - centres[i]);
      if (j != i && d < nearest) nearest = d, to = centres[j] - centres[i];
    }
    const double c = std::abs(glm::dot(glm::normalize(to), axis));
    double degrees = std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;  // [0, 90]
    angles.push_back(std::min(degrees, 90.0 - degrees));
  }
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

Design facade_grid() {
  Design d = load_design(test::source_dir() / "assets/designs/facade_grid_discs.json");
  d.elements.edge.clear();  // the V-elements' rows alone
  return d;
}

TEST(RowAlignment, AlignXLaysTheFacadesRowsLevel) {
  const SurfaceMap& map = *test::bundled_map("facade");
  Design design = facade_grid();
  const Pavement plain = make_pavement(map, design);
  design.placement.align = AlignAxis::X;
  const Pavement aligned = make_pavement(map, design);
  const double before = median_grid_angle_to(plain.elements, {1, 0, 0});
  const double after = median_grid_angle_to(aligned.elements, {1, 0, 0});
  EXPECT_GT(before, 10.0) << "the map's own orientation is off the floor (the case align is for)";
  EXPECT_LT(after, 2.0) << "rows along x";
  ASSERT_TRUE(aligned.row_alignment.has_value());
  EXPECT_EQ(aligned.row_alignment->axis, AlignAxis::X);
  EXPECT_LT(aligned.row_alignment->spread_deg, 2.0) << "a facade's x runs one way on its map";
  EXPECT_LT(aligned.row_alignment->axis_to_surface_deg, 15.0) << "x lies nearly in the facade";
  EXPECT_FALSE(plain.row_alignment.has_value());
  // As many elements either way: turning the lattice costs no coverage here.
  EXPECT_NEAR(double(aligned.elements.size()), double(plain.elements.size()), 0.05 * double(plain.elements.size()));
}

TEST(RowAlignment, TheResolvedDesignRepeatsTheSameLatticeWithoutTheKey) {
  const SurfaceMap& map = *test::bundled_map("facade");
  Design design = facade_grid();
  design.placement.align = AlignAxis::Y;
  const Pavement first = make_pavement(map, design);
  EXPECT_EQ(first.design.placement.align, AlignAxis::None);
  EXPECT_DOUBLE_EQ(first.design.placement.rotation_deg, first.row_alignment->rotation_deg);
  // design.json holds the resolved design: read back, it lays the same elements.
  const Design again = design_from_json(design_to_json(first.design), "design.json");
  const Pavement second = make_pavement(map, again);
  EXPECT_EQ(second.elements.position, first.elements.position);
  // The user's rotation goes on top of the alignment.
  design.placement.rotation_deg = 10;
  const Pavement turned = make_pavement(map, design);
  EXPECT_NEAR(turned.design.placement.rotation_deg, first.row_alignment->rotation_deg + 10, 1e-9);
}

TEST(RowAlignment, AnAxisNormalToAFlatWallIsRefused) {
  const SurfaceMap map = build_surface_map(test::grid_surface(8, 8, [](double u, double v) {
    return glm::dvec3(10 * u, 10 * v, 0);
  }));
  Design design;
  design.pattern.spacing = 1;
  design.placement.align = AlignAxis::Z;
  try {
    (void)make_pavement(map, design);
    FAIL() << "rows along the wall's own normal were accepted";
  } catch (const DesignError& e) {
    EXPECT_NE(std::string(e.what()).find("placement.align: the z axis is normal to the surface"), std::string::npos)
        << e.what();
  }
  design.placement.align = AlignAxis::Y;
  EXPECT_NO_THROW((void)make_pavement(map, design));
}

// What a run says when the axis cannot be followed well, rather than printing "rows along z".
TEST(RowAlignment, ASteepAxisATurningAxisAndABandAreSaid) {
  const auto warnings_for = [](const std::string& surface, Tessellation t, AlignAxis axis) {
    PipelineRequest request;
    request.map = test::bundled_map(surface);
    request.design.pattern.tessellation = t;
    request.design.placement.align = axis;
    return run_pipeline(request).warnings;
  };
  const auto said = [](const std::vector<std::string>& warnings, const std::string& part) {
    return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(part) != std::string::npos; });
  };
  // z meets the facade within about 11 degrees of its normal.
  EXPECT_TRUE(said(warnings_for("facade", Tessellation::Grid, AlignAxis::Z), "follow only the surface's slope"));
  EXPECT_FALSE(said(warnings_for("facade", Tessellation::Grid, AlignAxis::X), "placement.align"));
  // The vase wraps 270 degrees around z (its height): x turns with it on the map.
  EXPECT_TRUE(said(warnings_for("vase", Tessellation::Triangle, AlignAxis::X), "turns by about"));
  // A band's rows close around it.
  EXPECT_TRUE(said(warnings_for("bangle", Tessellation::Triangle, AlignAxis::Y), "is not used: this band is paved seamlessly"));
}

TEST(RowAlignment, TheKeyIsReadWrittenAndCheckedByName) {
  Design design;
  design.placement.align = AlignAxis::Z;
  const Design back = design_from_json(design_to_json(design), "d.json");
  EXPECT_EQ(back.placement.align, AlignAxis::Z);
  nlohmann::json bad = design_to_json(design);
  bad["placement"]["align"] = "up";
  try {
    (void)design_from_json(bad, "d.json");
    FAIL() << "align \"up\" was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("placement.align"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace paver
