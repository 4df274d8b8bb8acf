// The subtractive solid (engine/cut): the shell, the seat cutter and the boolean, checked against
// volumes worked out by hand and by an independent edge and volume count.
#include "cut/seat_cutter.h"
#include "cut/cut_outputs.h"
#include "cut/finger_side.h"
#include "cut/seat_rules.h"
#include "cut/solid_cut.h"
#include "cut/thick_shell.h"

#include "closed_mesh_checks.h"
#include "input_error_assertions.h"
#include "core/input_error.h"
#include "map/surface_map.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "temp_folder.h"
#include "test_meshes.h"
#include "threemf_read_back.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

namespace paver {
namespace {

// A flat plate's top: a size x size square in z = 0 as a grid of cells, normals +Z.
SurfaceMap flat_plate(double size, int cells) {
  SurfaceMesh m;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) m.positions.emplace_back(size * i / cells, size * j / cells, 0.0);
  const auto at = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      m.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  std::vector<int>& loop = m.boundary_loops.emplace_back();
  for (int i = 0; i < cells; ++i) loop.push_back(at(i, 0));
  for (int j = 0; j < cells; ++j) loop.push_back(at(cells, j));
  for (int i = cells; i > 0; --i) loop.push_back(at(i, cells));
  for (int j = cells; j > 0; --j) loop.push_back(at(0, j));
  SurfaceMap map;
  map.normals.assign(m.positions.size(), glm::dvec3(0, 0, 1));
  map.mesh = std::move(m);
  return map;
}

Elements stones_on_plate(const std::vector<glm::dvec2>& centres, double diameter, ShapeKind shape) {
  Elements e;
  for (const glm::dvec2& c : centres)
    e.push_back(ElementKind::Vertex, 0, 0, c, {c.x, c.y, 0.0}, {0, 0, 1}, diameter, shape);
  return e;
}

TEST(SeatCutter, IsAClosedSolidWhoseVolumeIsTheFrustumsSum) {
  const std::vector<glm::dvec2> profile = seat_profile(0.6, 2.0);
  const SurfaceMesh seat = solid_of_revolution(profile, kSeatSegments);
  EXPECT_EQ(test::unpaired_edges(seat), 0u);
  const double by_formula = solid_of_revolution_volume(profile, kSeatSegments, -10, 10);
  EXPECT_NEAR(test::signed_volume(seat), by_formula, 1e-12) << "outward-oriented, and the formula is right";
  // The handle is the girdle's radius plus 1% and the hole 40% of the stone.
  EXPECT_DOUBLE_EQ(profile.front().x, 0.51);
  EXPECT_DOUBLE_EQ(profile.back().x, kSeatHoleRadius);
  EXPECT_DOUBLE_EQ(profile.front().y, 0.6);
  EXPECT_DOUBLE_EQ(profile.back().y, -2.0);
}

TEST(ThickShell, IsClosedOrientedAndAreaTimesThicknessOnAPlate) {
  const SurfaceMap plate = flat_plate(10, 5);
  const SurfaceMesh shell = thick_shell(plate.mesh, plate.normals, 0.8);
  EXPECT_EQ(test::unpaired_edges(shell), 0u);
  EXPECT_NEAR(test::signed_volume(shell), 80.0, 1e-9);
  EXPECT_THROW(thick_shell(plate.mesh, plate.normals, 0.0), InputError);
  EXPECT_THROW(thick_shell(plate.mesh, plate.normals, std::nan("")), InputError);
}

// A ring's finger side (issue 43): a crowned band about a tilted axis, its shell's inside on the
// cylinder of the size to within rounding, closed and oriented; a size the band cannot take, a
// band facing its axis, and a surface with one rim are refused.
TEST(FingerSide, IsACylinderAboutTheBandsOwnAxis) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.2, 1)), centre(4, -2, 7);
  const glm::dvec3 e1 = glm::normalize(glm::cross(axis, glm::dvec3(1, 0, 0))), e2 = glm::cross(axis, e1);
  const auto radius = [](double v) { return 10 + 0.5 * std::sin(std::numbers::pi * v); };
  SurfaceMap band;
  band.mesh = test::band_surface(96, 8, [&](double u, double v) {
    const double a = 2 * std::numbers::pi * u;
    return centre + radius(v) * (std::cos(a) * e1 + std::sin(a) * e2) + 6 * (v - 0.5) * axis;
  });
  for (const glm::dvec3& p : band.mesh.positions) {
    const glm::dvec3 r = p - centre - glm::dot(p - centre, axis) * axis;
    band.normals.push_back(glm::normalize(r));
  }
  const FingerSide side = check_finger_side(band, 17.3, 1.2, "--inside-diameter 17.3");
  EXPECT_NEAR(glm::dot(side.axis.direction, axis) * glm::dot(side.axis.direction, axis), 1.0, 1e-9);
  EXPECT_NEAR(side.thinnest(), 10 - 8.65, 1e-9);
  EXPECT_NEAR(side.thickest(), 10.5 - 8.65, 1e-9);
  const SurfaceMesh shell = ring_shell(band.mesh, side);
  EXPECT_EQ(test::unpaired_edges(shell), 0u);
  const std::size_t n = band.mesh.positions.size();
  for (std::size_t v = n; v < 2 * n; ++v) {
    const glm::dvec3 r = shell.positions[v] - centre;
    ASSERT_NEAR(glm::length(r - glm::dot(r, axis) * axis), 8.65, 1e-9);
  }
  const double height = 6, polygon = 96 / (2 * std::numbers::pi) * std::sin(2 * std::numbers::pi / 96);
  EXPECT_GT(test::signed_volume(shell), polygon * std::numbers::pi * (100 - 8.65 * 8.65) * height);
  EXPECT_LT(test::signed_volume(shell), std::numbers::pi * (10.5 * 10.5 - 8.65 * 8.65) * height);

  EXPECT_THROW(check_finger_side(band, 18, 1.2, "--inside-diameter 18"), InputError);  // 1.0 of metal < 1.2
  SurfaceMap inward = band;
  for (glm::dvec3& normal : inward.normals) normal = -normal;
  EXPECT_THROW(check_finger_side(inward, 17.3, 1.2, "--inside-diameter 17.3"), InputError);
  EXPECT_THROW(check_finger_side(flat_plate(10, 5), 17.3, 1.2, "--inside-diameter 17.3"), InputError);
  SurfaceMap washer;  // two rims around one axis, but flat: its normals lie along the axis
  washer.mesh = test::band_surface(64, 4, [](double u, double v) {
    const double a = 2 * std::numbers::pi * u;
    return glm::dvec3((10 + 2 * v) * std::cos(a), (10 + 2 * v) * std::sin(a), 0.0);
  });
  washer.normals.assign(washer.mesh.positions.size(), glm::dvec3(0, 0, 1));
  EXPECT_THROW(check_finger_side(washer, 17.3, 0.5, "--inside-diameter 17.3"), InputError);
}

// Production rules (issue 43) on two gems 1.0 apart on a flat plate, worked out by hand: a seat is
// 1% of d wider than its stone each side, a gem reaches `below` d under its girdle's middle.
TEST(SeatRules, CuletMetalAndSeatWallsAreMeasuredAndBrokenRulesNameTheirStones) {
  Elements stones;
  const double d = 0.8;
  for (int k = 0; k < 3; ++k)
    stones.push_back(ElementKind::Vertex, k, 0, {double(k), 0.0}, {1.0 * k, 0.0, 0.0}, {0, 0, 1}, d, ShapeKind::Gem);
  stones.id = {10, 11, 12};
  stones.position[2] = {5, 0, 0};  // far from both
  double below = 0, above = 0;
  for (const glm::vec3& v : make_builtin_shape(ShapeKind::Gem).positions) {
    below = std::max(below, -double(v.z));
    above = std::max(above, double(v.z));
  }
  const ShapeTable shapes(stones, nullptr, "cut");
  const SeatCheck loose = check_seats(stones, shapes, CutterKind::Seat, 0.5, nullptr, {});
  EXPECT_NEAR(loose.least_culet_metal, 0.5 - below * d, 1e-6);
  EXPECT_NEAR(loose.least_seat_wall, 1.0 - (1 + 2 * kSeatClearance) * d, 1e-12);
  EXPECT_NEAR(loose.highest_table, above * d, 1e-6);
  EXPECT_TRUE(loose.breaks.empty()) << "no rule set, none broken";
  EXPECT_NEAR(check_seats(stones, shapes, CutterKind::Element, 0.5, nullptr, {}).least_seat_wall, 1.0 - d, 1e-12)
      << "an element cutter is the stone itself";

  const SeatCheck strict = check_seats(stones, shapes, CutterKind::Seat, 0.5, nullptr, {0.2, 0.2, std::nullopt});
  ASSERT_EQ(strict.breaks.size(), 2u);
  EXPECT_EQ(strict.breaks[0].rule, "culet clearance");
  EXPECT_EQ(strict.breaks[0].stone_ids, (std::vector<int>{10, 11, 12})) << "every culet has too little metal";
  EXPECT_EQ(strict.breaks[1].rule, "seat wall");
  EXPECT_EQ(strict.breaks[1].stone_ids, (std::vector<int>{10, 11})) << "the third stone stands apart";
  const std::vector<std::string> problems = seat_rule_problems(strict);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[1].find("2 stones stand with less than 0.2 of metal between their seats"), std::string::npos)
      << problems[1];
  EXPECT_NE(problems[1].find("ids 10, 11)"), std::string::npos) << problems[1];
  EXPECT_TRUE(check_seats(stones, shapes, CutterKind::Seat, 0.5, nullptr, {0.1, 0.15, std::nullopt}).breaks.empty());
}

// Stones set deeper (--seat-depth) on the same plate: their culets lose that much metal and their
// tables that much height; a table ceiling (--table-height) names the stones above it, and a
// depth past the crown sinks the tables below the metal, which always breaks.
TEST(SeatRules, ASeatDepthLowersTheStonesAndTheTablesAreRuled) {
  Elements stones;
  const double d = 0.8;
  stones.push_back(ElementKind::Vertex, 0, 0, {0.0, 0.0}, {0.0, 0.0, 0.0}, {0, 0, 1}, d, ShapeKind::Gem);
  stones.push_back(ElementKind::Vertex, 1, 0, {1.0, 0.0}, {1.0, 0.0, 0.0}, {0, 0, 1}, 1.2 * d, ShapeKind::Gem);
  stones.id = {4, 7};
  double below = 0, above = 0;
  for (const glm::vec3& v : make_builtin_shape(ShapeKind::Gem).positions) {
    below = std::max(below, -double(v.z));
    above = std::max(above, double(v.z));
  }
  const ShapeTable shapes(stones, nullptr, "cut");
  const Elements seated = seated_stones(stones, 0.05);
  EXPECT_EQ(seated.position[1], glm::dvec3(1.0, 0.0, -0.05)) << "along the normal, below the surface";
  const SeatCheck set = check_seats(stones, shapes, CutterKind::Seat, 1.0, nullptr, {}, 0.05);
  EXPECT_NEAR(set.least_culet_metal, 1.0 - below * 1.2 * d - 0.05, 1e-6);
  EXPECT_NEAR(set.highest_table, above * 1.2 * d - 0.05, 1e-6);
  EXPECT_NEAR(set.lowest_table, above * d - 0.05, 1e-6);
  EXPECT_EQ(set.seat_depth, 0.05);
  EXPECT_TRUE(set.breaks.empty());
  // The larger stone's table stands above a ceiling between the two.
  const double ceiling = (above * 1.1 * d) - 0.05;
  const SeatCheck ruled = check_seats(stones, shapes, CutterKind::Seat, 1.0, nullptr, {{}, {}, ceiling}, 0.05);
  ASSERT_EQ(ruled.breaks.size(), 1u);
  EXPECT_EQ(ruled.breaks[0].rule, "table height");
  EXPECT_EQ(ruled.breaks[0].stone_ids, (std::vector<int>{7}));
  EXPECT_NEAR(ruled.breaks[0].worst, above * 1.2 * d - 0.05, 1e-6) << "the highest table";
  const std::vector<std::string> too_high = seat_rule_problems(ruled);
  ASSERT_EQ(too_high.size(), 1u);
  EXPECT_NE(too_high[0].find("1 stone has tables more than"), std::string::npos) << too_high[0];
  EXPECT_NE(too_high[0].find("--seat-depth"), std::string::npos) << too_high[0];
  // Deeper than the small stone's crown: its table lies under the metal.
  const double sunk = above * 1.1 * d;
  const SeatCheck under = check_seats(stones, shapes, CutterKind::Seat, 1.0, nullptr, {}, sunk);
  ASSERT_EQ(under.breaks.size(), 1u);
  EXPECT_EQ(under.breaks[0].rule, "table below the metal");
  EXPECT_EQ(under.breaks[0].stone_ids, (std::vector<int>{4}));
  EXPECT_LT(under.lowest_table, 0);
  EXPECT_NE(seat_rule_problems(under)[0].find("tables below the metal"), std::string::npos);
}

// The volume the seats take out of a flat plate is worked out by hand: each seat is a stack of
// regular-polygon frustums, of which the part between the plate's faces goes.
TEST(SolidCut, SeatsInAFlatPlateRemoveExactlyTheirVolumeWithinIt) {
  const double size = 10, thickness = 1, d = 1.5;
  const SurfaceMap plate = flat_plate(size, 8);
  const Elements stones = stones_on_plate({{2.5, 2.5}, {5, 2.5}, {7.5, 2.5}, {2.5, 5}, {5, 5}, {7.5, 7.5}}, d,
                                          ShapeKind::Gem);
  const CutSolid cut = cut_pavement(plate, stones, {.cutter = CutterKind::Seat, .thickness = thickness});

  const std::vector<glm::dvec2> profile = seat_profile(cutter_reach_above(), cutter_reach_below(thickness, d));
  const double seat_in_plate = d * d * d * solid_of_revolution_volume(profile, kSeatSegments, -thickness / d, 0);
  EXPECT_NEAR(cut.shell_volume, size * size * thickness, 1e-9);
  // Within the snapping of the written points to a millionth of the piece's size.
  EXPECT_NEAR(cut.volume, size * size * thickness - 6 * seat_in_plate, 1e-6 * size * size * thickness);
  EXPECT_EQ(cut.cutters, 6);
  EXPECT_EQ(cut.united_cutters, 0);
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u) << "closed, edge-manifold and consistently oriented";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
  EXPECT_NEAR(test::signed_volume(cut.mesh), cut.volume, 1e-6) << "the written mesh has the volume reported";
  // The gems' culets lie a pavilion and half a girdle below the surface: inside a 1 mm plate.
  EXPECT_NEAR(cut.deepest_stone, (kGemPavilionDepth + kGemGirdleHalf) * d, 1e-6);
  EXPECT_EQ(stones_stand_out_warning(cut, thickness, Units::Millimetre), "");
}

// cut.3mf is the metal alone, one printable model in one build item, so that a slicer slices it as
// it is: the stones in it stopped PrusaSlicer ("no extrusions in the first layer: gem").
class MetalFiles : public test::TempFolderTest {};

TEST_F(MetalFiles, HoldTheMetalAlone) {
  const double d = 2, thickness = 1;
  const SurfaceMap plate = flat_plate(10, 8);
  const CutSolid cut = cut_pavement(plate, stones_on_plate({{3, 3}, {6, 4}}, d, ShapeKind::Gem),
                                    {.cutter = CutterKind::Seat, .thickness = thickness});
  const Elements stones = stones_on_plate({{3, 3}, {6, 4}}, d, ShapeKind::Gem);
  write_cut_files(dir_, cut, stones, nullptr, Units::Millimetre);
  const test::ReadBack3mf r = test::read_3mf(dir_ / "cut.3mf");
  ASSERT_EQ(r.meshes.size(), 1u);
  EXPECT_EQ(r.meshes.begin()->second.name, "metal");
  EXPECT_EQ(r.meshes.begin()->second.type, DWORD(NMR::MODELOBJECTTYPE_MODEL));
  EXPECT_EQ(r.meshes.begin()->second.triangles, cut.mesh.triangles.size());
  EXPECT_TRUE(r.components.empty()) << "no stones in the metal's file";
  EXPECT_EQ(r.build_items.size(), 1u);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir_ / "cut.stl"));
  // The stones alone, for the setter: the stones' object, no metal, no beads.
  const test::ReadBack3mf alone = test::read_3mf(dir_ / "stones.3mf");
  EXPECT_EQ(alone.components.size(), stones.size()) << "one component per stone";
  EXPECT_TRUE(alone.bead_components.empty());
  for (const auto& [id, mesh] : alone.meshes) EXPECT_NE(mesh.name, "metal");
}

TEST(SolidCut, StonesDeeperThanTheMetalAreWarnedOf) {
  const double d = 1.5, thin = 0.4;
  const CutSolid cut = cut_pavement(flat_plate(10, 8), stones_on_plate({{5, 5}}, d, ShapeKind::Gem),
                                    {.cutter = CutterKind::Seat, .thickness = thin});
  const std::string warning = stones_stand_out_warning(cut, thin, Units::Millimetre);
  // 0.66 mm deep in 0.4 mm of metal: the culet stands 0.26 mm out of the back.
  EXPECT_NE(warning.find("reach 0.66 mm below the surface"), std::string::npos) << warning;
  EXPECT_NE(warning.find("by up to 0.26 mm"), std::string::npos) << warning;
  EXPECT_NEAR(cut_json(cut, CutterKind::Seat, thin, Units::Millimetre)["stones_stand_out_behind"].get<double>(), 0.44 * d - thin, 1e-6);
}

// A closed bead's metal is a hollow shell of the whole surface: thickened from the closed surface
// (no wall at the charts' seams: exactly two faces per surface face), closed, and cut by the seats
// of stones on both charts.
TEST(SolidCut, AClosedBeadIsAHollowShellWithNoWallAtItsSeams) {
  const auto map = test::bundled_map("bead");
  ASSERT_TRUE(is_atlas(*map));
  const double thickness = 0.4;
  const SurfaceMesh shell = thick_shell(map->closed_surface, map->closed_surface_normals, thickness);
  EXPECT_EQ(shell.face_count(), 2 * map->closed_surface.face_count());
  EXPECT_EQ(test::unpaired_edges(shell), 0u);
  const double area = surface_area(map->closed_surface);
  Design design;
  design.pattern.spacing = 1.6;
  design.elements.vertex.shape = ShapeKind::Gem;
  const Pavement p = make_pavement(*map, design);
  ASSERT_GT(p.elements.size(), 40u);
  const CutSolid cut = cut_pavement(*map, p.elements, {.cutter = CutterKind::Seat, .thickness = thickness});
  // Thinner than area x thickness inside a convex surface, by about thickness x mean curvature.
  EXPECT_GT(cut.shell_volume, 0.8 * area * thickness);
  EXPECT_LT(cut.shell_volume, area * thickness);
  EXPECT_LT(cut.volume, cut.shell_volume);
  EXPECT_GT(cut.volume, 0.5 * cut.shell_volume);
  EXPECT_EQ(cut.cutters, int(p.elements.size()));
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u) << "closed, edge-manifold and consistently oriented";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
  EXPECT_NEAR(test::signed_volume(cut.mesh), cut.volume, 1e-6 * cut.volume);
}

// The paper's way (Fig. 14): the element itself is the cutter. A sphere centred on the top face
// takes out its lower half (the UV sphere has a ring on its equator, so exactly half its volume).
// A cut past the machine's memory swapped for minutes and was killed (14,000 seats: over 6.4 GB
// and 11 minutes before it was stopped): it is refused before it starts, with its figures.
TEST(SolidCut, ACutBeyondTheMemoryIsRefusedWithItsFigures) {
  Elements stones, beads;
  for (int i = 0; i < 1000; ++i) {
    stones.push_back(ElementKind::Vertex, i, 0, {double(i), 0}, {1.2 * i, 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Gem);
    beads.push_back(ElementKind::Bead, i, 0, {double(i), 0}, {1.2 * i + 0.6, 0.5, 0}, {0, 0, 1}, 0.2, ShapeKind::Sphere);
  }
  const CutOptions seats{.cutter = CutterKind::Seat, .thickness = 1};
  EXPECT_NEAR(estimated_cut_bytes(stones, seats), 1000 * kCutBytesPerSeatCutter, 1.0);
  CutOptions with_beads = seats;
  with_beads.beads = &beads;
  EXPECT_GT(estimated_cut_bytes(stones, with_beads), estimated_cut_bytes(stones, seats));
  EXPECT_NO_THROW(refuse_cut_beyond_memory(stones, seats, 1e9));
  const std::string why = test::error_of([&] { refuse_cut_beyond_memory(stones, seats, 0.1e9); });
  EXPECT_NE(why.find("--subtract: cutting 1000 seats would take about 0.5 GB"), std::string::npos) << why;
  EXPECT_NE(why.find("than the 0.1 GB this machine has free"), std::string::npos) << why;
}

TEST(SolidCut, SpheresAsCuttersTakeOutTheirLowerHalf) {
  const double d = 2;
  const SurfaceMap plate = flat_plate(10, 4);
  const Elements spheres = stones_on_plate({{3, 3}, {7, 6}}, d, ShapeKind::Sphere);
  const CutSolid cut = cut_pavement(plate, spheres, {.cutter = CutterKind::Element, .thickness = 1.5});
  SurfaceMesh sphere;
  for (const glm::vec3& p : make_builtin_shape(ShapeKind::Sphere).positions) sphere.positions.emplace_back(p);
  sphere.triangles = make_builtin_shape(ShapeKind::Sphere).triangles;
  const double half_sphere = 0.5 * d * d * d * test::signed_volume(sphere);
  EXPECT_NEAR(cut.volume, 150.0 - 2 * half_sphere, 1e-6 * 150.0);
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u);
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
}

// Stones set closer than their seats' clearance: the touching seats are united before the cut, and
// the result is still one closed solid that lost less than two separate seats would take.
TEST(SolidCut, TouchingSeatsAreUnitedFirst) {
  const double d = 1.5, thickness = 1;
  const SurfaceMap plate = flat_plate(10, 4);
  const Elements stones = stones_on_plate({{4, 5}, {4 + 1.01 * d, 5}, {8, 8}}, d, ShapeKind::Gem);
  const CutSolid cut = cut_pavement(plate, stones, {.cutter = CutterKind::Seat, .thickness = thickness});
  EXPECT_EQ(cut.united_cutters, 2);
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u);
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
  const std::vector<glm::dvec2> profile = seat_profile(cutter_reach_above(), cutter_reach_below(thickness, d));
  const double seat_in_plate = d * d * d * solid_of_revolution_volume(profile, kSeatSegments, -thickness / d, 0);
  EXPECT_LT(cut.volume, 100.0 - 2 * seat_in_plate);
  EXPECT_GT(cut.volume, 100.0 - 3 * seat_in_plate);
}

// Beads are metal: joined to the cut solid, each adds its upper half (the UV sphere's equator lies
// on the flat top).
TEST(SolidCut, BeadsJoinTheMetalWithTheirUpperHalves) {
  const double d = 1.5, thickness = 1, bead = 0.4;
  const SurfaceMap plate = flat_plate(10, 4);
  const Elements stones = stones_on_plate({{3, 3}}, d, ShapeKind::Gem);
  Elements beads;
  for (const glm::dvec2 c : {glm::dvec2(7, 7), glm::dvec2(7, 3)})
    beads.push_back(ElementKind::Bead, 0, 0, c, {c.x, c.y, 0.0}, {0, 0, 1}, bead, ShapeKind::Sphere);
  const CutSolid cut = cut_pavement(plate, stones, {.cutter = CutterKind::Seat, .thickness = thickness, .beads = &beads});
  EXPECT_EQ(cut.beads, 2);
  const std::vector<glm::dvec2> profile = seat_profile(cutter_reach_above(), cutter_reach_below(thickness, d));
  const double seat_in_plate = d * d * d * solid_of_revolution_volume(profile, kSeatSegments, -thickness / d, 0);
  SurfaceMesh sphere;
  for (const glm::vec3& p : make_builtin_shape(ShapeKind::Sphere).positions) sphere.positions.emplace_back(p);
  sphere.triangles = make_builtin_shape(ShapeKind::Sphere).triangles;
  const double half_bead = 0.5 * bead * bead * bead * test::signed_volume(sphere);
  EXPECT_NEAR(cut.volume, 100.0 - seat_in_plate + 2 * half_bead, 1e-6 * 100);
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u);
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
}

TEST(SolidCut, AShellThatFoldsIntoItselfIsRefusedWithTheThickness) {
  // A plate bent into a sharp ridge: offset downwards by 3, its two sides cross under the ridge.
  SurfaceMap plate = flat_plate(4, 4);
  for (std::size_t v = 0; v < plate.mesh.positions.size(); ++v) {
    glm::dvec3& p = plate.mesh.positions[v];
    p.z = -3 * std::abs(p.x - 2);
    plate.normals[v] = glm::normalize(glm::dvec3(p.x < 2 ? -3 : (p.x > 2 ? 3 : 0), 0, 1));
  }
  try {
    cut_pavement(plate, {}, {.cutter = CutterKind::Seat, .thickness = 3});
    FAIL() << "a folded shell was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--thickness 3: the metal folds into itself"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace paver
