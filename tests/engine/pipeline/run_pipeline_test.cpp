// Tests for engine/pipeline/run_pipeline.cpp and map_surface.cpp: the one pipeline gives what its
// stages give one by one, checks its inputs before any work, writes only when asked, and reports
// the pattern before the solver moves it.
#include "core/input_error.h"
#include "core/interrupted.h"
#include "io/design_io.h"
#include "io/element_export.h"
#include "mesh/mesh_loader.h"
#include "pipeline/run_pipeline.h"
#include "surface_maps.h"
#include "temp_folder.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <fstream>

namespace paver {
namespace {

namespace fs = std::filesystem;

class RunPipeline : public test::TempFolderTest {
protected:
  static PipelineRequest dome_request() {
    PipelineRequest r;
    r.surface_path = test::bundled_surface("dome");
    r.design = load_design(test::source_dir() / "assets/designs/dome_hex_d6.json");
    r.design_source = "dome_hex_d6.json";
    r.pavement.threads = 1;
    return r;
  }
};

TEST_F(RunPipeline, EqualsItsStagesCalledOneByOne) {
  std::vector<float> fractions;
  PipelineRequest request = dome_request();
  request.progress = [&](float f, const std::string&) { fractions.push_back(f); };
  const PipelineResult result = run_pipeline(request);

  const SurfaceMap map = build_surface_map(load_surface(test::bundled_surface("dome")).mesh);
  PavementOptions options;
  options.threads = 1;
  const Pavement direct = make_pavement(map, request.design, options);
  EXPECT_EQ(result.map->uv, map.uv);
  EXPECT_EQ(result.pavement.elements.position, direct.elements.position);
  EXPECT_EQ(result.pavement.elements.diameter, direct.elements.diameter);
  EXPECT_GT(result.pavement.elements.size(), 50u);
  // Counts agree with the pavement, and every stage is timed once, load first.
  EXPECT_EQ(result.counts.vertex_elements + result.counts.edge_elements, long(result.pavement.elements.size()));
  ASSERT_GE(result.timings.size(), 4u);
  EXPECT_EQ(result.timings.front().first, "load");
  EXPECT_EQ(result.timings[1].first, "parameterize");
  // Mapping progress moves forward and ends at 1.
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0f);
}

TEST_F(RunPipeline, WritesOnlyWhenAskedAndTheReportLast) {
  PipelineRequest request = dome_request();
  request.map = test::bundled_map("dome");
  request.pavement.optimize = false;
  run_pipeline(request);
  EXPECT_TRUE(fs::is_empty(dir_));

  request.out = dir_ / "out";
  request.extra_outputs = {dir_ / "out" / "extra.txt"};
  bool report_existed = true, out_existed = true;
  request.write_extras = [&](const PipelineResult& r, const fs::path& folder, StageTimings& timings,
                             nlohmann::json& sections) {
    sections["extra"] = {{"written", true}};
    report_existed = fs::exists(folder / "report.json");
    out_existed = fs::exists(dir_ / "out");
    std::ofstream(folder / "extra.txt") << r.pavement.elements.size();
    timings.emplace_back("extra", 1.0);
  };
  const PipelineResult result = run_pipeline(request);
  EXPECT_FALSE(report_existed) << "the extras must be written before report.json";
  EXPECT_FALSE(out_existed) << "the set must appear at once, when complete";
  for (const char* name : {"placements.csv", "elements.ply", "elements.obj", "design.json", "report.json", "extra.txt"})
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / name)) << name;
  std::ifstream in(dir_ / "out" / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["timings_ms"]["extra"].get<double>(), 1.0);
  EXPECT_EQ(report["elements"]["total"].get<long>(), long(result.pavement.elements.size()));
  EXPECT_EQ(report["design"]["source"], "dome_hex_d6.json");
  EXPECT_EQ(report["extra"]["written"], true) << "the extras' own report section";
}

TEST_F(RunPipeline, RefusesBadInputBeforeAnyWork) {
  // A bad design is refused before the surface is even read: this surface does not exist.
  PipelineRequest bad_design = dome_request();
  bad_design.surface_path = dir_ / "missing.obj";
  bad_design.design.solver.dt = 2;
  try {
    run_pipeline(bad_design);
    FAIL() << "accepted dt = 2";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'solver.dt'"), std::string::npos) << e.what();
  }

  // So is a design the unit cell cannot take (an E-element on an edge the cell lacks), even with
  // the spacing still to be derived from the surface.
  PipelineRequest bad_cell = dome_request();
  bad_cell.surface_path = dir_ / "missing.obj";
  bad_cell.design.pattern.spacing = 0;
  EdgeElementDesign on_edge_9;
  on_edge_9.cell_edges = {9};
  bad_cell.design.elements.edge = {on_edge_9};
  try {
    run_pipeline(bad_cell);
    FAIL() << "accepted cell edge 9";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("elements.edge[0].cell_edges: edge 9 does not exist"), std::string::npos)
        << e.what();
  }

  // An output that is an input is refused before anything is written or mapped.
  const fs::path surface = dir_ / "placements.csv";
  fs::copy_file(test::bundled_surface("dome"), surface);
  const auto before = fs::last_write_time(surface);
  PipelineRequest overwrite = dome_request();
  overwrite.surface_path = surface;
  overwrite.out = dir_;
  int mapped = 0;
  overwrite.progress = [&](float, const std::string&) { ++mapped; };
  EXPECT_THROW(run_pipeline(overwrite), InputError);
  EXPECT_EQ(mapped, 0);

  // So is an output folder that cannot be made (a file in the way).
  PipelineRequest blocked = dome_request();
  blocked.out = surface / "out";
  blocked.progress = [&](float, const std::string&) { ++mapped; };
  EXPECT_THROW(run_pipeline(blocked), InputError);
  EXPECT_EQ(mapped, 0);
  EXPECT_EQ(fs::last_write_time(surface), before);
  EXPECT_FALSE(fs::exists(dir_ / "report.json"));
}

TEST_F(RunPipeline, ReportsThePatternBeforeTheSolverMovesIt) {
  PipelineRequest request = dome_request();
  std::vector<glm::dvec2> pattern_points;
  double spacing = 0;
  request.pavement.on_pattern = [&](const Pattern& pattern, const Design& design) {
    pattern_points = pattern.points;
    spacing = design.pattern.spacing;
  };
  const PipelineResult result = run_pipeline(request);
  EXPECT_EQ(pattern_points, result.pavement.pattern.points);
  EXPECT_NE(pattern_points, result.pavement.points) << "the optimizer should have moved the points";
  EXPECT_EQ(spacing, result.pavement.design.pattern.spacing);
}

TEST_F(RunPipeline, TellsTheLoadersRepairsBeforeMapping) {
  // The dome plus a stray triangle far away: the loader keeps the largest component and says so.
  const fs::path surface = dir_ / "dome_and_speck.obj";
  fs::copy_file(test::bundled_surface("dome"), surface);
  const int n = int(load_surface(test::bundled_surface("dome")).mesh.vertex_count());
  std::ofstream(surface, std::ios::app) << "v 1000 0 0\nv 1001 0 0\nv 1000 1 0\nf " << n + 1 << " " << n + 2 << " "
                                        << n + 3 << "\n";
  PipelineRequest request = dome_request();
  request.surface_path = surface;
  request.pavement.optimize = false;
  std::vector<std::string> events;
  request.on_warning = [&](const std::string& w) { events.push_back("warning: " + w); };
  request.progress = [&](float f, const std::string&) {
    if (f > 0.1f && events.size() < 3) events.push_back("mapping");
  };
  const PipelineResult result = run_pipeline(request);
  ASSERT_FALSE(result.warnings.empty());
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.front().rfind("warning: ", 0), 0u) << "the warning must come before the mapping";
}

// An open custom shape (a pyramid without its base) was accepted silently, and every element was
// exported open; a closed one gives no warning.
TEST_F(RunPipeline, AnOpenCustomShapeIsWarnedAbout) {
  const auto pave_with = [&](const std::string& name, const std::string& obj) {
    std::ofstream(dir_ / name) << obj;
    PipelineRequest request = dome_request();
    request.design.elements.vertex.shape = ShapeKind::Custom;
    request.design.elements.custom_shape = (dir_ / name).string();
    request.pavement.optimize = false;
    std::vector<std::string> warned;
    request.on_warning = [&](const std::string& w) { warned.push_back(w); };
    run_pipeline(request);
    return warned;
  };
  const std::string pyramid = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 1\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
  const std::vector<std::string> open = pave_with("open.obj", pyramid);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_NE(open[0].find("open.obj: 4 edges have one face only"), std::string::npos) << open[0];
  EXPECT_TRUE(pave_with("closed.obj", pyramid + "f 1 4 3 2\n").empty());
}

// Element scale 1e-9 used to hang (boundary segments bucketed into billions of cells of a
// billionth of the part; the proximity grid's indices overflowed); 1e-300 then wrote elements of
// no size. Elements too small for a mesh file's float32 beside the part's coordinates are refused
// once D is known, before the solves; small ones that a file can draw pave like any other.
TEST_F(RunPipeline, TinyElementsPaveAndElementsTooSmallToDrawAreRefused) {
  for (const double scale : {1e-9, 1e-300}) {
    PipelineRequest request = dome_request();
    request.map = test::bundled_map("dome");
    request.design.elements.vertex.scale = scale;
    std::vector<std::string> stages;
    request.pavement.on_stage = [&](const std::string& stage) { stages.push_back(stage); };
    try {
      run_pipeline(request);
      ADD_FAILURE() << "scale " << scale << " was paved";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("elements.vertex.scale"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("too small to draw"), std::string::npos) << e.what();
    }
    EXPECT_EQ(std::count(stages.begin(), stages.end(), "optimize"), 0) << "refused before the solves";
  }
  PipelineRequest request = dome_request();
  request.map = test::bundled_map("dome");
  request.design.elements.vertex.scale = 1e-3;
  const PipelineResult result = run_pipeline(request);
  EXPECT_GT(result.pavement.elements.size(), 100u);
  EXPECT_EQ(result.pavement.after.contact_violations, 0);
  EXPECT_GT(result.pavement.after.neighbor_ratio.min, 100) << "elements a thousandth of D apart by D";
}

// Runs `request`, which must be refused over its output limit (the error names --max-output-gb);
// returns the stages that started before the refusal.
std::vector<std::string> stages_before_output_refusal(PipelineRequest request) {
  std::vector<std::string> stages;
  request.pavement.on_stage = [&](const std::string& stage) { stages.push_back(stage); };
  try {
    run_pipeline(request);
    ADD_FAILURE() << "a run over the output limit was not refused";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--max-output-gb"), std::string::npos) << error.what();
  }
  return stages;
}

// The output bound is checked from the pattern, before the solver runs: a design whose element
// meshes would pass the limit costs no solve (issue 11: a 23 GB PLY was written after one).
TEST_F(RunPipeline, RefusesTooLargeOutputBeforeTheSolve) {
  PipelineRequest request = dome_request();
  request.map = test::bundled_map("dome");
  request.out = dir_ / "out";
  int solver_iterations = 0;
  request.pavement.observer = [&](int, const std::vector<glm::vec2>&) {
    ++solver_iterations;
    return true;
  };
  // The same run, unbounded, to know its size; then a limit 10% below it.
  PipelineRequest unbounded = request;
  unbounded.out.reset();
  const PipelineResult full = run_pipeline(unbounded);
  const double bytes = expected_mesh_bytes(element_mesh_size(full.pavement.elements), request.formats, full.map->mesh);
  ASSERT_GT(solver_iterations, 0);
  solver_iterations = 0;
  request.max_output_bytes = 0.9 * bytes;
  const std::vector<std::string> stages = stages_before_output_refusal(request);
  EXPECT_EQ(solver_iterations, 0) << "the limit must be checked before the solve";
  EXPECT_EQ(stages, std::vector<std::string>{"pattern"}) << "and before any element is placed or measured";
  EXPECT_FALSE(fs::exists(dir_ / "out"));

  // The estimate from the pattern is the placed elements' size before boundary post-processing.
  const ElementMeshSize expected = expected_element_mesh_size(full.pavement.pattern, full.pavement.design.elements);
  const Design& used = full.pavement.design;
  const PlacedElements initial = place_all_elements(*request.map, full.pavement.pattern, full.pavement.pattern.points,
                                                    used.elements, used.pattern.spacing,
                                                    edge_anchor(used.pattern.topology), false);
  EXPECT_EQ(expected.elements, initial.elements.size());
  EXPECT_EQ(expected.faces, element_mesh_size(initial.elements).faces);
}

// A band lays out dozens of patterns while it closes and picks its rows and shift: a clear excess
// is refused from the map's area before any of them (15 GB of files on a ring took 36 s to refuse).
TEST_F(RunPipeline, AClearlyTooLargeOutputIsRefusedBeforeABandsPatternIsLaidOut) {
  PipelineRequest request;
  request.map = test::bundled_map("ring_band");
  request.design.pattern.tessellation = Tessellation::Triangle;
  request.design.pattern.spacing = 0.5;
  request.out = dir_ / "out";
  request.max_output_bytes = 1e5;
  const std::vector<std::string> stages = stages_before_output_refusal(request);
  EXPECT_TRUE(stages.empty()) << "refused at stage " << stages.front();
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// A stop (Ctrl-C) ends the run at the next stage with Interrupted, and nothing is written.
TEST_F(RunPipeline, AStoppedRunWritesNothing) {
  std::atomic<bool> stop{false};
  PipelineRequest request = dome_request();
  request.out = dir_ / "out";
  request.pavement.stop = &stop;
  request.pavement.observer = [&](int iteration, const std::vector<glm::vec2>&) {
    if (iteration >= 5) stop = true;
    return true;
  };
  EXPECT_THROW(run_pipeline(request), Interrupted);
  EXPECT_TRUE(fs::is_empty(dir_)) << "an interrupted run must leave nothing behind";
}

TEST_F(RunPipeline, MappingStopsWhenAsked) {
  int polls = 0;
  const MappedSurface mapped = map_surface_file(test::bundled_surface("dome"), {}, [&] { return ++polls > 2; });
  EXPECT_EQ(mapped.map, nullptr);
  EXPECT_EQ(polls, 3);
}

}  // namespace
}  // namespace paver
