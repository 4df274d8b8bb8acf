#include "document.h"

#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <numeric>

namespace paver::studio {
namespace {

Design with_dt(double dt) {
  Design d;
  d.solver.dt = dt;
  return d;
}

TEST(Document, EveryChangeIsAnUndoStepAndANewRevision) {
  Document doc;
  const auto revision = doc.revision;
  ASSERT_TRUE(change_design(doc, with_dt(0.25)));
  EXPECT_TRUE(doc.dirty);
  EXPECT_EQ(doc.revision, revision + 1);
  EXPECT_EQ(doc.history.undo_count(), 1u);
  EXPECT_LE(doc.run_due, Clock::now()) << "a plain change runs at once";

  ASSERT_TRUE(undo(doc));
  EXPECT_EQ(doc.design.solver.dt, SolverParams{}.dt);
  EXPECT_EQ(doc.revision, revision + 2);
  ASSERT_TRUE(redo(doc));
  EXPECT_EQ(doc.design.solver.dt, 0.25);
  EXPECT_EQ(doc.revision, revision + 3);
  EXPECT_FALSE(redo(doc));
}

TEST(Document, ChangesThatChangeNothingAreNotRecorded) {
  Document doc;
  const auto revision = doc.revision;
  EXPECT_TRUE(change_design(doc, Design{}));
  EXPECT_EQ(doc.revision, revision);
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_FALSE(doc.dirty);
}

TEST(Document, ADragIsOneUndoStepAndWaitsToRun) {
  Document doc;
  for (double dt : {0.31, 0.32, 0.33}) ASSERT_TRUE(change_design(doc, with_dt(dt), true));
  EXPECT_EQ(doc.history.undo_count(), 1u);
  EXPECT_GT(doc.run_due, Clock::now()) << "the run waits for the slider to rest";
  end_gesture(doc);
  ASSERT_TRUE(change_design(doc, with_dt(0.5)));
  EXPECT_EQ(doc.history.undo_count(), 2u);
  ASSERT_TRUE(undo(doc));
  EXPECT_EQ(doc.design.solver.dt, 0.33);
  ASSERT_TRUE(undo(doc));
  EXPECT_EQ(doc.design.solver.dt, SolverParams{}.dt);
}

TEST(Document, AnInvalidDesignIsReportedAndTheDesignKept) {
  Document doc;
  ASSERT_TRUE(change_design(doc, with_dt(0.25)));
  const auto revision = doc.revision;
  EXPECT_FALSE(change_design(doc, with_dt(-1)));
  EXPECT_EQ(doc.design.solver.dt, 0.25);
  EXPECT_EQ(doc.revision, revision);
  EXPECT_EQ(doc.messages.error_count, 1);
  // The field a designer sees, then the key a design file has.
  EXPECT_NE(doc.messages.error.find("Optimize > step size (dt) (solver.dt) must be"), std::string::npos)
      << doc.messages.error;
  EXPECT_TRUE(doc.messages.status.starts_with("error: "));
  EXPECT_TRUE(doc.messages.error_kept_design) << "the dialog may say the design is unchanged";
  report_error(doc, "a run failed");
  EXPECT_FALSE(doc.messages.error_kept_design) << "a run's error comes after the design changed";
}

TEST(Document, UnsavedMeansDifferentFromWhatWasLoadedOrSaved) {
  Document doc;
  EXPECT_FALSE(doc.dirty);
  ASSERT_TRUE(change_design(doc, with_dt(0.25)));
  EXPECT_TRUE(doc.dirty);
  ASSERT_TRUE(undo(doc));
  EXPECT_FALSE(doc.dirty) << "undone back to the default design: nothing to save";
  ASSERT_TRUE(redo(doc));
  EXPECT_TRUE(doc.dirty);
}

TEST(Document, SaveAsFromABundledDesignStartsUnderANewNameInTheWorkingFolder) {
  const std::filesystem::path bundled = test::source_dir() / "assets/designs/dome_hex_d6.json";
  EXPECT_EQ(save_as_start(bundled), std::filesystem::current_path() / "dome_hex_d6_mine.json");
  EXPECT_EQ(save_as_start("/tmp/mine.json"), "/tmp/mine.json") << "any other design starts at its own file";
}

TEST(Document, SaveRefusesToOverwriteABundledDesign) {
  const std::filesystem::path bundled = test::source_dir() / "assets/designs/dome_hex_d6.json";
  const std::string before = [&] {
    std::ifstream in(bundled);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  Document doc;
  ASSERT_TRUE(open_design_file(doc, bundled));
  Design d = doc.design;
  d.solver.dt = 0.123;
  ASSERT_TRUE(change_design(doc, d));
  EXPECT_FALSE(save_design_file(doc, bundled));
  EXPECT_NE(doc.messages.error.find("is a design bundled with Paver"), std::string::npos) << doc.messages.error;
  std::ifstream in(bundled);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
  EXPECT_TRUE(doc.dirty);
}

TEST(Document, DesignFilesRoundTripAndABadOneChangesNothing) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("paver_document_" + std::to_string(getpid()) + ".json");
  Document doc;
  ASSERT_TRUE(change_design(doc, with_dt(0.2)));
  ASSERT_TRUE(save_design_file(doc, file));
  EXPECT_FALSE(doc.dirty);
  EXPECT_EQ(doc.design_path, file);

  Document other;
  ASSERT_TRUE(open_design_file(other, file));
  EXPECT_EQ(other.design.solver.dt, 0.2);
  EXPECT_FALSE(other.dirty);
  EXPECT_TRUE(other.history.can_undo()) << "loading a design is undoable";

  EXPECT_FALSE(open_design_file(other, "/nonexistent/design.json"));
  EXPECT_EQ(other.design.solver.dt, 0.2);
  EXPECT_NE(other.messages.error.find("/nonexistent/design.json"), std::string::npos);
  std::filesystem::remove(file);
}

TEST(Document, AResultCarriesItsRatiosAndHistogram) {
  Document doc;
  const SurfaceMap& map = *test::bundled_map("dome");
  Design d;
  d.pattern.spacing = 6;
  auto pavement = std::make_shared<const Pavement>(make_pavement(map, d));
  set_result(doc, pavement, doc.revision, 12.5);
  const PavementResult& r = doc.result;
  EXPECT_EQ(r.neighbour_ratios.size(), pavement->elements.size());
  ASSERT_EQ(r.ratio_histogram.size(), std::size_t(kHistogramBins));
  EXPECT_EQ(std::accumulate(r.ratio_histogram.begin(), r.ratio_histogram.end(), 0.0f), float(pavement->elements.size()));
  EXPECT_LT(r.latency_ms, 0) << "measured once it is on screen";
  // The report panel's verdict is the one report.json carries.
  EXPECT_EQ(r.verdict.ok, judge_pavement(pavement->after).ok);
  EXPECT_EQ(r.verdict.problems, judge_pavement(pavement->after).problems);
  EXPECT_TRUE(r.verdict.ok) << "the dome at D = 6 is fit to use";
}

}  // namespace
// A designer's trial: the last result's "ok: 949 elements" stayed on screen while a 10k run solved,
// and an old run's error after another change. A new run makes a run's status and error stale; an
// edit's own status line stays.
TEST(Document, ANewRunMakesTheLastRunsStatusAndErrorStale) {
  Document doc;
  report_run_status(doc, "ok: 949 elements, 0 contact violations; 200 iterations (converged)");
  mark_run_started(doc);
  EXPECT_EQ(doc.messages.status.rfind("solving the changed design", 0), 0u) << doc.messages.status;
  report_run_error(doc, "the pattern places no element on this surface", true);
  EXPECT_FALSE(doc.messages.error.empty());
  mark_run_started(doc);
  EXPECT_TRUE(doc.messages.error.empty()) << "the old run's error no longer applies";
  EXPECT_EQ(doc.messages.status.rfind("solving", 0), 0u) << doc.messages.status;
  EXPECT_EQ(doc.messages.error_count, 1) << "a script still sees that an error happened";
  report_status(doc, "pinned element 12");
  mark_run_started(doc);
  EXPECT_EQ(doc.messages.status, "pinned element 12") << "what the edit did stays said";
  report_error(doc, "cannot read design.json", true);
  mark_run_started(doc);
  EXPECT_EQ(doc.messages.error, "cannot read design.json") << "an error of the user's action, not a run's, stays";
}

// A designer's trial: "ok: 481 elements" over a dome with visible holes. The status line says the
// verdict with its problems, then the bare spots and the stones removed that the views mark; a
// removed stone whose place another took since is no hole and gets no ghost.
TEST(Document, TheRunsStatusCountsTheBareSpotsAndTheRemovedStonesItMarks) {
  auto p = std::make_shared<Pavement>();
  p->design.units = Units::Millimetre;
  for (int i = 0; i < 3; ++i)
    p->elements.push_back(ElementKind::Vertex, i, 0, {2.0 * i, 0}, {2.0 * i, 0, 0}, {0, 0, 1}, 1.8, ShapeKind::Gem);
  p->resolution.removed_places = {{{2, 0.2}, {2, 0.2, 0}, 1.8}, {{9, 9}, {9, 9, 0}, 1.8}};
  p->after.elements = 3;
  p->after.fill = 0.95;
  p->after.edges.measured = true;
  p->after.edges.spot_stone = 1.44;
  p->after.edges.bare_spots = 2;
  p->after.edges.spots = {BareSpot{{5, 5, 0}, {5, 5}}, BareSpot{{7, 5, 0}, {7, 5}}};
  Document doc;
  set_result(doc, p, doc.revision, 10);
  ASSERT_EQ(doc.result.ghosts.size(), 1u) << "the removal at (2, 0.2) lies under a stone standing there now";
  EXPECT_EQ(doc.result.ghosts[0].position, glm::dvec3(9, 9, 0));
  const std::string ok = run_status_text(doc.result);
  EXPECT_EQ(ok.rfind("ok: 3 elements, 0 contact violations; 2 bare spots where a 1.44 mm stone still fits; 1 stone "
                     "removed where they still collided (marked in the views)", 0), 0u) << ok;

  p->after.fill = 0.5;  // now the verdict's own problem comes first
  set_result(doc, p, doc.revision, 10);
  const std::string bare = run_status_text(doc.result);
  EXPECT_EQ(bare.rfind("NOT OK: bare patches: 50%", 0), 0u) << bare;
  EXPECT_NE(bare.find("2 bare spots"), std::string::npos) << bare;

  p->after.fill = 0.95;
  p->after.edges.bare_spots = 0;
  p->after.edges.spots.clear();
  p->resolution.removed_places.clear();
  set_result(doc, p, doc.revision, 10);
  const std::string clean = run_status_text(doc.result);
  EXPECT_EQ(clean.find("marked"), std::string::npos) << "nothing to look for: " << clean;
}

// With no surface open, no spacing is too large to type (the engine's bound is the map across).
TEST(Document, NoSurfaceNoLargestSpacing) {
  Document doc;
  EXPECT_TRUE(std::isinf(largest_spacing(doc)));
}

}  // namespace paver::studio
