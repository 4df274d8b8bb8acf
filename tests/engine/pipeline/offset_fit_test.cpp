// placement.fit_offset on the bundled facade with windows, grid rows laid along x (where whole
// rows meet a window's edge or miss it), with element edits, and where it is not used (a band, an
// adaptive pattern).
#include "io/design_io.h"
#include "pipeline/offset_fit.h"
#include "pipeline/pavement.h"
#include "pipeline/run_pipeline.h"
#include "report/verdict.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace paver {
namespace {

Design windows_grid_along_x() {
  Design d = load_design(test::source_dir() / "assets/designs/facade_windows_grid_discs.json");
  d.placement.align = AlignAxis::X;
  return d;
}

// The ranking's first: no quarter-cell shift, laid out here through make_pavement itself, lays out
// more; the design's offset is the no-shift try.
TEST(OffsetFit, NoQuarterCellShiftLaysOutMoreThanTheBestRanked) {
  const SurfaceMap& map = *test::bundled_map("facade_windows");
  Design design = windows_grid_along_x();
  design.placement.fit_offset = true;
  PavementOptions laid_out;
  laid_out.optimize = false;
  const Pavement fitted = make_pavement(map, design, laid_out);
  ASSERT_TRUE(fitted.offset_fit.has_value());
  const OffsetFit& fit = *fitted.offset_fit;
  EXPECT_EQ(fit.tries, 64) << "a pattern of a few hundred points takes the full 8 x 8 shifts";
  ASSERT_GE(fit.finalists.size(), 3u);
  const std::size_t best_laid_out = fit.finalists.front().laid_out;
  for (std::size_t f = 1; f < fit.finalists.size(); ++f) EXPECT_LE(fit.finalists[f].laid_out, best_laid_out);
  EXPECT_EQ(fitted.before.elements, long(fit.chosen.laid_out)) << "the chosen shift's count is the laid-out pavement's";
  EXPECT_FALSE(fitted.design.placement.fit_offset);
  EXPECT_EQ(fitted.design.placement.offset, fit.chosen.offset);

  design.placement.fit_offset = false;
  long fewest = 1L << 40;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Design shifted = design;
      shifted.placement.offset = (i / 4.0) * fitted.cell.a1 + (j / 4.0) * fitted.cell.a2;
      const long count = make_pavement(map, shifted, laid_out).before.elements;
      EXPECT_LE(count, long(best_laid_out)) << "shift (" << i << "/4, " << j << "/4)";
      if (i == 0 && j == 0) {
        EXPECT_EQ(count, long(fit.at_design.laid_out));
      }
      fewest = std::min(fewest, count);
    }
  // The case the fit is for: the shift matters here.
  EXPECT_GT(long(best_laid_out), fewest + 30);
}

// The finalists are paved in full and the one that keeps the most is laid: more V-elements than
// at the design's offset, no contact, and the resolved design repeats the pavement.
TEST(OffsetFit, TheFittedPavementKeepsTheMostAndItsDesignRepeatsIt) {
  const SurfaceMap& map = *test::bundled_map("facade_windows");
  Design design = windows_grid_along_x();
  const Pavement plain = make_pavement(map, design);
  design.placement.fit_offset = true;
  const Pavement fitted = make_pavement(map, design);
  ASSERT_TRUE(fitted.offset_fit.has_value());
  const OffsetFit& fit = *fitted.offset_fit;
  EXPECT_TRUE(judge_pavement(fitted.after).ok) << "a fitted pavement is judged like any other";
  EXPECT_EQ(fitted.after.contact_violations, 0);
  EXPECT_EQ(fit.chosen.kept, long(fitted.elements.size())) << "the finalist paved quietly is the pavement laid";
  EXPECT_EQ(fit.at_design.kept, long(plain.elements.size())) << "the design's own offset is among the finalists";
  for (const OffsetCandidate& c : fit.finalists) EXPECT_LE(c.kept, fit.chosen.kept);
  EXPECT_GT(fitted.after.vertex_elements, plain.after.vertex_elements + 10)
      << "at the design's offset a row of discs runs along a window's edge and is lost";
  // design.json holds the found offset with fit_offset false: read back, the same elements.
  const Design again = design_from_json(design_to_json(fitted.design), "design.json");
  EXPECT_FALSE(again.placement.fit_offset);
  const Pavement repeated = make_pavement(map, again);
  EXPECT_FALSE(repeated.offset_fit.has_value());
  EXPECT_EQ(repeated.elements.position, fitted.elements.position);
}

// Element edits name the elements of the lattice at the design's offset: under them no fit is made,
// and the run says so (the studio keeps a fitted offset in the design at the first edit).
TEST(OffsetFit, UnderElementEditsNoFitIsMadeAndTheRunSaysSo) {
  PipelineRequest request;
  request.map = test::bundled_map("facade_windows");
  request.design = windows_grid_along_x();
  request.design.pattern.topology = Topology::Lattice;  // edits name the elements of one topology
  request.design.placement.fit_offset = true;
  request.design.edits.deleted.push_back({3, {0, 0}});
  const PipelineResult result = run_pipeline(request);
  EXPECT_FALSE(result.pavement.offset_fit.has_value());
  EXPECT_EQ(result.pavement.design.placement.offset, glm::dvec2(0));
  EXPECT_TRUE(std::any_of(result.warnings.begin(), result.warnings.end(), [](const std::string& w) {
    return w.find("fit_offset (--fit-offset) is not used: this design's element edits") != std::string::npos;
  }));
}

// A band's rows are shifted across it for the most elements on every run; the design.json a run
// writes holds the shift, and run again it lays the same stones (the tries once started from the
// design's offset and moved the rows half a row further on every run).
TEST(BandOffset, TheWrittenDesignOfABandRepeatsItsStones) {
  const SurfaceMap& map = *test::bundled_map("bangle");
  const Design design = load_design(test::source_dir() / "assets/designs/bangle_tri_gems.json");
  const Pavement first = make_pavement(map, design);
  ASSERT_TRUE(first.seamless);
  Design written = design_from_json(design_to_json(first.design), "design.json");
  const Pavement second = make_pavement(map, written);
  // The same offset, but for a rounding: the band's closure is made again from the written D.
  EXPECT_NEAR(second.design.placement.offset.x, first.design.placement.offset.x, 1e-12);
  EXPECT_NEAR(second.design.placement.offset.y, first.design.placement.offset.y, 1e-12);
  EXPECT_EQ(second.elements.position, first.elements.position);
}

// Topology auto that grows the adaptive pattern where the lattice tore starts it from the design's
// own placement: rows along an axis are its own turn (and reported), and the lattice's fitted
// offset is not carried over (it once cost 21 of 980 elements here, under a warning that the fit
// was not used).
TEST(OffsetFit, AutosAdaptivePatternOnTheBunnyHeadStartsFromTheDesignsOwnPlacement) {
  const SurfaceMap& map = *test::named_map("bunnyhead_three_loops");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.placement.align = AlignAxis::X;
  const Pavement plain = make_pavement(map, design);
  ASSERT_EQ(plain.design.pattern.topology, Topology::Adaptive) << "the case: auto grew the adaptive pattern";
  EXPECT_TRUE(plain.row_alignment.has_value()) << "its own turn, reported";
  design.placement.fit_offset = true;
  const Pavement fitted = make_pavement(map, design);
  ASSERT_EQ(fitted.design.pattern.topology, Topology::Adaptive);
  EXPECT_FALSE(fitted.offset_fit.has_value());
  EXPECT_EQ(fitted.elements.position, plain.elements.position) << "the lattice's fit is not the adaptive pattern's";
}

TEST(OffsetFit, ABandAndAnAdaptivePatternSayItWasNotUsed) {
  const auto warnings_for = [](const std::string& surface, Topology topology) {
    PipelineRequest request;
    request.map = test::bundled_map(surface);
    request.design.pattern.tessellation = Tessellation::Triangle;
    request.design.pattern.topology = topology;
    request.design.placement.fit_offset = true;
    return run_pipeline(request).warnings;
  };
  const auto said = [](const std::vector<std::string>& warnings, const std::string& part) {
    return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(said(warnings_for("bangle", Topology::Lattice), "fit_offset (--fit-offset) is not used: this band"));
  EXPECT_TRUE(said(warnings_for("dome", Topology::Adaptive), "fit_offset (--fit-offset) is not used: the adaptive"));
  EXPECT_FALSE(said(warnings_for("dome", Topology::Lattice), "fit_offset"));
}

}  // namespace
}  // namespace paver
