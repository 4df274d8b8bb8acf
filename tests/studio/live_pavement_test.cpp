#include "live_pavement.h"

#include "surface_maps.h"
#include "test_meshes.h"

#include "paver/compute/vulkan_context.h"
#include "paver/compute/vulkan_spring_solver.h"
#include "pipeline/pavement.h"
#include "map/surface_map.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <thread>

namespace paver::studio {
namespace {

using namespace std::chrono_literals;

class LivePavementTest : public testing::Test {
protected:
  static void SetUpTestSuite() {
    map_ = test::bundled_map("dome");
  }
  static void TearDownTestSuite() { map_.reset(); }

  static Design design() {
    Design d;
    d.pattern.spacing = 6;
    return d;
  }

  // Polls until `done` holds; false after 60 s.
  static bool eventually(const std::function<bool()>& done) {
    for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 60s;) {
      if (done()) return true;
      std::this_thread::sleep_for(2ms);
    }
    return false;
  }

  static std::shared_ptr<const SurfaceMap> map_;
};
std::shared_ptr<const SurfaceMap> LivePavementTest::map_;

TEST_F(LivePavementTest, FinishesWithTheOneCallPavement) {
  LivePavement live;
  live.start({map_, design(), 7, {}, false, 0, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Finished; }));
  const auto outcome = live.take_outcome();
  ASSERT_TRUE(outcome);
  ASSERT_TRUE(outcome->pavement) << outcome->error;
  EXPECT_EQ(outcome->revision, 7u);
  EXPECT_FALSE(live.take_outcome()) << "an outcome is taken once";
  EXPECT_EQ(live.state(), RunState::Finished);

  // Watching and steering the run changes nothing in its result.
  const Pavement direct = make_pavement(*map_, design());
  EXPECT_EQ(outcome->pavement->solve.iterations, direct.solve.iterations);
  EXPECT_EQ(outcome->pavement->elements.position, direct.elements.position);
}

TEST_F(LivePavementTest, StepsPausesAndResumes) {
  LivePavement live;
  live.start({map_, design(), 1, {}, true, 5, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused; }));
  EXPECT_EQ(live.iteration(), 5);
  const auto first = live.snapshot_since(0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->iteration, 5) << "a pause publishes exactly where it stopped";
  EXPECT_EQ(first->points.size(), first->pattern->points.size());
  EXPECT_FALSE(live.snapshot_since(first->sequence)) << "nothing newer while paused";

  live.step(3);
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused && live.iteration() == 8; }));
  const auto second = live.snapshot_since(first->sequence);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->iteration, 8);
  EXPECT_NE(second->points, first->points) << "the particles moved";

  live.resume();
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Finished; }));
  const auto outcome = live.take_outcome();
  ASSERT_TRUE(outcome && outcome->pavement);
  EXPECT_EQ(outcome->pavement->elements.position, make_pavement(*map_, design()).elements.position);
}

TEST_F(LivePavementTest, ResetDropsTheRunAndANewRunReplacesTheOld) {
  LivePavement live;
  live.start({map_, design(), 1, {}, true, 0, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused; }));
  live.reset();
  EXPECT_EQ(live.state(), RunState::Idle);
  EXPECT_FALSE(live.take_outcome());
  EXPECT_EQ(live.revision(), 1u) << "reset keeps the revision, so it is not started again by itself";

  live.start({map_, design(), 2, {}, true, 0, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused; }));
  Design other = design();
  other.solver.dt = 0.2;
  live.start({map_, other, 3, {}, false, 0, {}});  // the paused run is abandoned, not waited for
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Finished; }));
  const auto outcome = live.take_outcome();
  ASSERT_TRUE(outcome && outcome->pavement);
  EXPECT_EQ(outcome->revision, 3u);
  EXPECT_EQ(outcome->pavement->design.solver.dt, 0.2);
}

TEST_F(LivePavementTest, ADesignTheCellCannotTakeFailsAsAnInputError) {
  LivePavement live;
  Design bad = design();
  bad.elements.edge.push_back({.t = 0.5, .scale = 0.5, .shape = ShapeKind::Sphere, .cell_edges = {99}});
  live.start({map_, bad, 4, {}, false, 0, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Finished; }));
  const auto outcome = live.take_outcome();
  ASSERT_TRUE(outcome);
  EXPECT_FALSE(outcome->pavement);
  EXPECT_TRUE(outcome->input_error);
  EXPECT_NE(outcome->error.find("cell_edges"), std::string::npos) << outcome->error;
}

}  // namespace
}  // namespace paver::studio

// The same on the Vulkan solver (lavapipe in CI): steps stop at batch boundaries, an abandoned
// run and its replacement share one solver session safely, and the result is the CPU's.
namespace paver::studio {
namespace {

struct VulkanSolver {
  std::shared_ptr<gpu::VulkanContext> context;
  SolverFactory factory;
};

const VulkanSolver& vulkan_solver() {
  static const VulkanSolver v = [] {
    VulkanSolver out;
    gpu::ContextOptions options;
    options.validation = true;
    auto context = gpu::VulkanContext::create(options);
    if (!context) return out;
    auto session = gpu::VulkanSolverSession::create(context.value());
    if (!session) return out;
    out.context = context.value();
    out.factory = gpu::vulkan_solver_factory(session.value(), 16);
    return out;
  }();
  return v;
}

TEST_F(LivePavementTest, VulkanSolverStepsByBatchesAndMatchesTheCpu) {
  if (!vulkan_solver().factory) {
    std::fprintf(stderr, "\n*** NO VULKAN DEVICE: LivePavementTest.VulkanSolver... is SKIPPED ***\n\n");
    GTEST_SKIP() << "no Vulkan device";
  }
  LivePavement live;
  live.start({map_, design(), 1, vulkan_solver().factory, true, 5, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused; }));
  EXPECT_EQ(live.iteration(), 16) << "the first batch boundary at or past iteration 5";
  live.step(3);
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Paused && live.iteration() > 16; }));
  EXPECT_EQ(live.iteration(), 32);

  // Abandon it while paused and start another at once: both use the one session.
  Design other = design();
  other.solver.dt = 0.25;
  live.start({map_, other, 2, vulkan_solver().factory, false, 0, {}});
  ASSERT_TRUE(eventually([&] { return live.state() == RunState::Finished; }));
  const auto outcome = live.take_outcome();
  ASSERT_TRUE(outcome && outcome->pavement) << (outcome ? outcome->error : "no outcome");
  const Pavement cpu = make_pavement(*map_, other);
  EXPECT_EQ(outcome->pavement->elements.size(), cpu.elements.size());
  EXPECT_EQ(outcome->pavement->after.contact_violations, 0);
  if (vulkan_solver().context->device().type == "cpu") {
    EXPECT_EQ(outcome->pavement->elements.position, cpu.elements.position) << "bit-identical on lavapipe";
  }
  for (const auto& m : vulkan_solver().context->validation_messages()) ADD_FAILURE() << "validation: " << m;
}

}  // namespace
}  // namespace paver::studio
