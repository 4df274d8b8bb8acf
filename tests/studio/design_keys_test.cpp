#include "design_keys.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace paver::studio {
namespace {

std::string error_of(const Design& d, const std::string& key, const std::string& value) {
  try {
    set_design_key(d, key, value);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DesignKeys, KeysBecomeJsonPointers) {
  EXPECT_EQ(design_key_pointer("solver.dt"), "/solver/dt");
  EXPECT_EQ(design_key_pointer("elements.edge[0].t"), "/elements/edge/0/t");
  EXPECT_EQ(design_key_pointer("elements.edge.1.scale"), "/elements/edge/1/scale");
  EXPECT_EQ(design_key_pointer("placement.offset[1]"), "/placement/offset/1");
  for (const char* bad : {"", ".dt", "solver.", "solver..dt", "solver/dt", "edge[x]", "edge[", "edge[]"})
    EXPECT_THROW(design_key_pointer(bad), InputError) << bad;
}

TEST(DesignKeys, EveryKindOfValue) {
  Design d;
  d.elements.edge.push_back({});
  EXPECT_EQ(set_design_key(d, "solver.dt", "0.25").solver.dt, 0.25);
  EXPECT_EQ(set_design_key(d, "solver.iterations", "300").solver.iterations, 300);
  EXPECT_EQ(set_design_key(d, "placement.rotation_deg", "-15.5").placement.rotation_deg, -15.5);
  EXPECT_EQ(set_design_key(d, "elements.vertex.scale", "0.5").elements.vertex.scale, 0.5);
  EXPECT_FALSE(set_design_key(d, "elements.vertex.enabled", "false").elements.vertex.enabled);
  EXPECT_EQ(set_design_key(d, "elements.vertex.shape", "gem").elements.vertex.shape, ShapeKind::Gem);
  EXPECT_EQ(set_design_key(d, "elements.vertex.shape", "\"disc\"").elements.vertex.shape, ShapeKind::Disc);
  EXPECT_EQ(set_design_key(d, "pattern.tessellation", "grid").pattern.tessellation, Tessellation::Grid);
  EXPECT_EQ(set_design_key(d, "placement.offset", "[1.5, -2]").placement.offset, glm::dvec2(1.5, -2));
  EXPECT_EQ(set_design_key(d, "placement.offset[1]", "3").placement.offset, glm::dvec2(0, 3));
  EXPECT_EQ(set_design_key(d, "elements.edge[0].t", "0.25").elements.edge[0].t, 0.25);
  EXPECT_EQ(set_design_key(d, "solver.filter_base", "initial").solver.filter_base, FilterBase::Initial);
  // The jeweller's keys, as the studio's Stones fields and scripts set them.
  EXPECT_EQ(set_design_key(d, "elements.margin", "0.5").elements.margin, 0.5);
  EXPECT_TRUE(set_design_key(d, "elements.beads.enabled", "true").elements.beads.enabled);
  EXPECT_EQ(set_design_key(d, "elements.beads.scale", "1.25").elements.beads.scale, 1.25);
  EXPECT_EQ(set_design_key(d, "units", "in").units, Units::Inch);
  EXPECT_EQ(set_design_key(d, "placement.align", "x").placement.align, AlignAxis::X);
  EXPECT_EQ(d.solver.dt, SolverParams{}.dt) << "the given design is untouched";
}

TEST(DesignKeys, UnknownKeysAndBadValuesAreNamed) {
  const Design d;
  EXPECT_NE(error_of(d, "solver.nope", "1").find("set solver.nope: no such design key"), std::string::npos);
  EXPECT_NE(error_of(d, "elements.edge[0].t", "0.5").find("no such design key"), std::string::npos);
  EXPECT_NE(error_of(d, "solver.dt", "fast").find("solver.dt"), std::string::npos);
  EXPECT_NE(error_of(d, "solver.iterations", "2.5").find("solver.iterations"), std::string::npos);
  EXPECT_NE(error_of(d, "elements.vertex.shape", "cube").find("elements.vertex.shape"), std::string::npos);
  EXPECT_NE(error_of(d, "elements.vertex.scale", "2").find("elements.vertex.scale"), std::string::npos);
  EXPECT_NE(error_of(d, "elements.margin", "-1").find("elements.margin"), std::string::npos);
  EXPECT_NE(error_of(d, "elements.beads.scale", "3").find("elements.beads.scale"), std::string::npos);
}

}  // namespace
}  // namespace paver::studio
