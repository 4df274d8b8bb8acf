// Tests for engine/solver/solver_kernels.h and engine/solver/spring_solver.cpp: each kernel
// against values worked out by hand from the paper's equations (section 5, NOTES.md), then the CPU
// solver on a flat square (an isometric map, so a perfect lattice is at rest) and on the dome.
#include "design/design.h"
#include "mesh/mesh_loader.h"
#include "pattern/pattern.h"
#include "pipeline/pavement.h"
#include "solver/solver_kernels.h"
#include "solver/solver_surface.h"
#include "solver/spring_solver.h"
#include "solver/spring_system.h"
#include "map/surface_map.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace paver {
namespace {

// ---------------------------------------------------------------------------------------------
// Hand-built fixtures for the kernels.

// The paper's constants (eq. 8, 13), dt = 0.5, no margins, centre O = (1, 5).
SolverConstants hand_constants() {
  SolverConstants k{};
  k.c = 0, k.m = 0;
  k.alpha = 10, k.beta = 5, k.gamma = 1;
  k.lambda_r = 0.94f, k.lambda_l = 0.04f, k.lambda_g = 0.02f;
  k.dt = 0.5f;
  k.mu_compressed = 1, k.mu_stretched = 0.5f, k.filter_max = 1.5f;
  k.curvature_min = 0, k.curvature_inv_range = 0;
  k.centre = glm::vec2(1, 5);
  k.filter_base_initial = 0;
  k.stray_patience = 10;
  return k;
}

struct HandSpring {
  int a, b;
  float target;
  std::uint32_t flags = 0;
};

// Particles at `positions`, springs with the given 2D targets (rest = target), CSR filled.
SpringSystem hand_system(const std::vector<glm::vec2>& positions, const std::vector<HandSpring>& springs) {
  SpringSystem sys;
  sys.position = positions;
  sys.stray_count.assign(positions.size(), 0u);
  sys.triangle_hint.assign(positions.size(), -1);
  for (const HandSpring& s : springs) {
    add_spring(sys, s.a, s.b, s.target, s.flags);
    sys.target.back() = s.target;
    sys.initial_target.back() = s.target;
  }
  rebuild_neighbors(sys);
  return sys;
}

glm::vec2 rotate(glm::vec2 v, double degrees) {
  const double t = degrees * std::numbers::pi / 180.0, c = std::cos(t), s = std::sin(t);
  return glm::vec2(float(c * v.x - s * v.y), float(s * v.x + c * v.y));
}

// ---------------------------------------------------------------------------------------------
// Kernels.

TEST(SolverKernels, SpringConstantShape) {
  const SolverConstants k = hand_constants();
  // With x = r^-6: k = 10 x^2 - 5 x + 1, discriminant 25 - 40 < 0, so k > 0 everywhere; the minimum
  // is at x = 1/4, i.e. r = 4^(1/6), where k = 10/16 - 5/4 + 1 = 0.375.
  for (float r = 0.3f; r < 5.0f; r += 0.01f) EXPECT_GT(spring_constant(k, r), 0.0f) << "r = " << r;
  const float r_min = float(std::pow(4.0, 1.0 / 6.0));
  const float k_min = spring_constant(k, r_min);
  EXPECT_NEAR(k_min, 0.375f, 1e-5f);
  EXPECT_GT(spring_constant(k, r_min * 1.01f), k_min);
  EXPECT_GT(spring_constant(k, r_min * 0.99f), k_min);
  // At rest, r = 1: 10 - 5 + 1 = 6.
  EXPECT_NEAR(spring_constant(k, 1.0f), 6.0f, 1e-5f);
  // r = 2: 10/4096 - 5/64 + 1 = 0.92431640625; r = 0.5: 10 * 4096 - 5 * 64 + 1 = 40641.
  EXPECT_NEAR(spring_constant(k, 2.0f), 0.92431640625f, 1e-6f);
  EXPECT_NEAR(spring_constant(k, 0.5f), 40641.0f, 1e-2f);
  // Compression is punished hard: 0.9^6 = 0.531441, 0.9^12 = 0.28243 -> 35.4068 - 9.4084 + 1 = 26.9987.
  EXPECT_NEAR(spring_constant(k, 0.9f), 26.99868f, 1e-3f);
  // Below the minimum, k decreases monotonically towards it.
  float previous = spring_constant(k, 0.3f);
  for (float r = 0.31f; r < r_min; r += 0.01f) {
    const float now = spring_constant(k, r);
    EXPECT_LT(now, previous) << "r = " << r;
    previous = now;
  }
  // Beyond it k rises back towards gamma = 1 but stays below it (10 x^2 < 5 x for x < 1/2).
  EXPECT_LT(spring_constant(k, 4.0f), 1.0f);
  EXPECT_GT(spring_constant(k, 4.0f), spring_constant(k, 2.0f));
}

TEST(SolverKernels, TargetLength3d) {
  SolverConstants k = hand_constants();
  k.c = 0.1f, k.m = 0.4f;
  k.curvature_min = 0.2f, k.curvature_inv_range = 1.0f;  // kappa_max = 1.2
  // Edge curvature = max(0.7, 0.45) = 0.7, normalised (0.7 - 0.2) * 1 = 0.5:
  // L = (0.1 + 0.4 * 0.5) * 5 + 5 = 6.5 (eq. 5, 6). Order of the ends does not matter.
  EXPECT_NEAR(target_length_3d(k, 5.0f, 0.7f, 0.45f), 6.5f, 1e-5f);
  EXPECT_NEAR(target_length_3d(k, 5.0f, 0.45f, 0.7f), 6.5f, 1e-5f);
  // Above kappa_max the normalised curvature clamps to 1: (0.1 + 0.4) * 5 + 5 = 7.5.
  EXPECT_NEAR(target_length_3d(k, 5.0f, 3.0f, 0.0f), 7.5f, 1e-5f);
  // Below kappa_min it clamps to 0: 0.1 * 5 + 5 = 5.5.
  EXPECT_NEAR(target_length_3d(k, 5.0f, 0.0f, 0.1f), 5.5f, 1e-5f);
  // A negative m shrinks the margin: c + m = 0 at full curvature gives D_ab itself.
  k.m = -0.1f;
  EXPECT_NEAR(target_length_3d(k, 5.0f, 1.2f, 1.2f), 5.0f, 1e-5f);
  // Constant curvature (inv_range 0): the m term vanishes whatever kappa is.
  k.m = 0.4f, k.curvature_inv_range = 0.0f;
  EXPECT_NEAR(target_length_3d(k, 5.0f, 0.7f, 100.0f), 5.5f, 1e-5f);
  // No margins: L = D_ab.
  k.c = 0, k.m = 0;
  EXPECT_NEAR(target_length_3d(k, 5.0f, 0.7f, 0.45f), 5.0f, 1e-6f);
}

TEST(SolverKernels, UpdateSpring) {
  SolverConstants k = hand_constants();
  // 2D length 2, rest 5.
  const glm::vec2 pa(0, 0), pb(2, 0);
  const glm::vec3 Pa(0, 0, 0), Pb4(0, 0, 4), Pb6(0, 3.6f, 4.8f);  // |P_a P_b| = 4 and 6
  const float kappa = 0;

  // (a) reset: l = L |p| / |P| = 5 * 2 / 4 = 2.5; ratio |P| / L = 0.8.
  {
    const auto s = update_spring(k, pb - pa, Pb4 - Pa, kappa, kappa, 5, 123.0f, 77.0f, true, 0);
    EXPECT_NEAR(s.target, 2.5f, 1e-6f);
    EXPECT_NEAR(s.ratio_3d, 0.8f, 1e-6f);
  }
  // The margin enters through L: c = 0.2 gives L = 6, l = 6 * 2 / 4 = 3, ratio 4 / 6.
  {
    SolverConstants kc = k;
    kc.c = 0.2f;
    const auto s = update_spring(kc, pb - pa, Pb4 - Pa, kappa, kappa, 5, 0, 0, true, 0);
    EXPECT_NEAR(s.target, 3.0f, 1e-6f);
    EXPECT_NEAR(s.ratio_3d, 4.0f / 6.0f, 1e-6f);
  }

  // (b) compressed (|P| = 4 < L = 5): w = 1 + mu_c (1 - 4/5) = 1.2, applied to the previous target
  // and clamped to [base, 1.5 base]; base = raw = 2.5 -> [2.5, 3.75].
  {
    auto f = [&](float previous) {
      return update_spring(k, pb - pa, Pb4 - Pa, kappa, kappa, 5, previous, 2.0f, false, 0).target;
    };
    EXPECT_NEAR(f(2.6f), 3.12f, 1e-5f);   // 1.2 * 2.6 = 3.12, inside the clamp
    EXPECT_NEAR(f(3.3f), 3.75f, 1e-5f);   // 1.2 * 3.3 = 3.96 > 3.75
    EXPECT_NEAR(f(1.0f), 2.5f, 1e-5f);    // 1.2 * 1.0 = 1.2 < 2.5
  }
  // ... base = initial = 2.0 (filter_base_initial = 1) -> [2.0, 3.0].
  {
    SolverConstants ki = k;
    ki.filter_base_initial = 1;
    auto f = [&](float previous) {
      return update_spring(ki, pb - pa, Pb4 - Pa, kappa, kappa, 5, previous, 2.0f, false, 0).target;
    };
    EXPECT_NEAR(f(2.4f), 2.88f, 1e-5f);  // 1.2 * 2.4
    EXPECT_NEAR(f(2.6f), 3.0f, 1e-5f);   // 3.12 > 3.0
    EXPECT_NEAR(f(1.5f), 2.0f, 1e-5f);   // 1.8 < 2.0
  }

  // (c) stretched (|P| = 6 > L = 5): w = 1 + 0.5 (1 - 6/5) = 0.9; raw = 5 * 2 / 6 = 5/3;
  // clamp [5/3, 2.5].
  {
    auto f = [&](float previous) {
      return update_spring(k, pb - pa, Pb6 - Pa, kappa, kappa, 5, previous, 2.0f, false, 0);
    };
    EXPECT_NEAR(f(2.0f).target, 1.8f, 1e-5f);          // 0.9 * 2.0
    EXPECT_NEAR(f(1.8f).target, 5.0f / 3.0f, 1e-5f);   // 1.62 < 5/3
    EXPECT_NEAR(f(3.0f).target, 2.5f, 1e-5f);          // 2.7 > 2.5
    EXPECT_NEAR(f(2.0f).ratio_3d, 1.2f, 1e-6f);
  }

  // (d) virtual and contact springs take the unfiltered target whatever the previous one.
  {
    SolverConstants km = k;
    km.c = 0.2f, km.m = 0.4f, km.curvature_inv_range = 1.0f;  // kappa 0 -> L = 1.2 * 5 = 6
    const auto v = update_spring(km, pb - pa, Pb4 - Pa, kappa, kappa, 5, 9.0f, 9.0f, false, kSpringVirtual);
    EXPECT_NEAR(v.target, 3.0f, 1e-6f);  // 6 * 2 / 4
    EXPECT_NEAR(v.ratio_3d, 4.0f / 6.0f, 1e-6f);
    // Contact: L = rest = 5 exactly (no c, no m): 5 * 2 / 4 = 2.5, ratio 0.8.
    const auto c = update_spring(km, pb - pa, Pb4 - Pa, 1.0f, 1.0f, 5, 9.0f, 9.0f, false, kSpringContact);
    EXPECT_NEAR(c.target, 2.5f, 1e-6f);
    EXPECT_NEAR(c.ratio_3d, 0.8f, 1e-6f);
  }

  // A collapsed spring (both ends at one 2D point) keeps the plain 3D target.
  {
    const auto s = update_spring(k, pa - pa, Pa - Pa, kappa, kappa, 5, 0, 0, true, 0);
    EXPECT_EQ(s.target, 5.0f);
  }
}

TEST(SolverKernels, MoveParticleTwoSpringChain) {
  const SolverConstants k = hand_constants();
  // p0 = (0,0), p1 = (1.2,0), p2 = (2,0); l01 = 1 (stretched by 0.2, r = 1.2),
  // l12 = 0.5 (|p1 p2| = 0.8, stretched by 0.3, r = 1.6).
  const SpringSystem sys = hand_system({{0, 0}, {1.2f, 0}, {2, 0}}, {{0, 1, 1.0f}, {1, 2, 0.5f}});
  auto kc = [](double r) { return 10 / std::pow(r, 12) - 5 / std::pow(r, 6) + 1; };
  // k(1.2) = 10/8.9161 - 5/2.985984 + 1 = 0.4470767; k(1.6) = 10/281.475 - 5/16.777216 + 1 = 0.7375039.
  const double k01 = kc(1.2), k12 = kc(1.6);
  EXPECT_NEAR(k01, 0.4470767, 1e-6);
  EXPECT_NEAR(k12, 0.7375039, 1e-6);

  // Middle particle.
  // R (eq. 7, 9): F01 = k01 (1.2 - 1) (-1, 0), F12 = k12 (0.8 - 0.5) (1, 0);
  //   R = (-0.2 k01 + 0.3 k12) / (k01 + k12) = 0.1112933 along x.
  const double Rx = (-0.2 * k01 + 0.3 * k12) / (k01 + k12);
  EXPECT_NEAR(Rx, 0.1112933, 1e-6);
  // L (eq. 10-11 with p_b): C = (p0 / 1 + p2 / 0.5) / (1/1 + 1/0.5) = (4, 0) / 3; L = (4/3 - 1.2, 0).
  //   (With the printed p_a, C would be p1 and L zero.)
  const double Lx = 4.0 / 3.0 - 1.2;
  // G (eq. 12): ((1.2 - 1) + (0.8 - 0.5)) / 2 = 0.25 towards O - p1 = (-0.2, 5), |.| = sqrt(25.04).
  const double n = std::sqrt(25.04), Gx = 0.25 * -0.2 / n, Gy = 0.25 * 5 / n;
  // dp = 0.94 R + 0.04 L + 0.02 G = (0.1097492, 0.0049960); step = dp * 0.5.
  const double dpx = 0.94 * Rx + 0.04 * Lx + 0.02 * Gx, dpy = 0.02 * Gy;
  EXPECT_NEAR(dpx, 0.1097492, 1e-6);
  EXPECT_NEAR(dpy, 0.0049960, 1e-6);
  const kernels::Move m1 = kernels::move_particle(k, sys, 1, sys.position);
  EXPECT_NEAR(m1.position.x, 1.2 + 0.5 * dpx, 1e-5);  // 1.2548746
  EXPECT_NEAR(m1.position.y, 0.5 * dpy, 1e-5);        // 0.0024980
  EXPECT_NEAR(m1.step, 0.5 * std::hypot(dpx, dpy), 1e-5);  // 0.0549314

  // End particle 0, one spring: R = k01 * 0.2 (1, 0) / k01 = (0.2, 0); L = p1 - p0 = (1.2, 0);
  // G = 0.2 (1, 5) / sqrt(26). dp = (0.188 + 0.048 + 0.004/sqrt(26), 0.02/sqrt(26)).
  const double s26 = std::sqrt(26.0);
  const double dp0x = 0.94 * 0.2 + 0.04 * 1.2 + 0.02 * 0.2 / s26, dp0y = 0.02 * 0.2 * 5 / s26;
  const kernels::Move m0 = kernels::move_particle(k, sys, 0, sys.position);
  EXPECT_NEAR(m0.position.x, 0.5 * dp0x, 1e-5);
  EXPECT_NEAR(m0.position.y, 0.5 * dp0y, 1e-5);
  EXPECT_NEAR(m0.step, 0.5 * std::hypot(dp0x, dp0y), 1e-5);

  // Equal targets 1 and 1 with deviations +0.2 and -0.2: both forces point to -x with magnitude
  // 0.2 k, so R = (-0.2, 0) whatever k; C = (p0 + p2) / 2 = (1, 0), L = (-0.2, 0);
  // G: sum of deviations 0, so G = 0. dp = (-0.188 - 0.008, 0) -> p1' = 1.2 - 0.098 = 1.102.
  const SpringSystem even = hand_system({{0, 0}, {1.2f, 0}, {2, 0}}, {{0, 1, 1.0f}, {1, 2, 1.0f}});
  const kernels::Move me = kernels::move_particle(k, even, 1, even.position);
  EXPECT_NEAR(me.position.x, 1.102f, 1e-5f);
  EXPECT_NEAR(me.position.y, 0.0f, 1e-5f);
  EXPECT_NEAR(me.step, 0.098f, 1e-5f);
}

TEST(SolverKernels, ContactSpringsOnlyPush) {
  SolverConstants k = hand_constants();
  k.centre = glm::vec2(0, -4);
  // Stretched or exactly at rest: the contact spring is skipped, the lone particle stays put.
  for (float x : {1.5f, 1.0f}) {
    const SpringSystem sys = hand_system({{0, 0}, {x, 0}}, {{0, 1, 1.0f, kSpringContact}});
    const kernels::Move m = kernels::move_particle(k, sys, 0, sys.position);
    EXPECT_EQ(m.position, glm::vec2(0, 0)) << "x = " << x;
    EXPECT_EQ(m.step, 0.0f);
  }
  // Compressed (len 0.5, l 1): F = k (0.5 - 1) (1, 0), R = (-0.5, 0); L = p1 - p0 = (0.5, 0);
  // G = (0.5 - 1) * unit((0,-4) - p0) = (0, 0.5). dp = (-0.47 + 0.02, 0.01), step dp * 0.5.
  {
    const SpringSystem sys = hand_system({{0, 0}, {0.5f, 0}}, {{0, 1, 1.0f, kSpringContact}});
    const kernels::Move m = kernels::move_particle(k, sys, 0, sys.position);
    EXPECT_NEAR(m.position.x, -0.225f, 1e-5f);
    EXPECT_NEAR(m.position.y, 0.005f, 1e-5f);
    EXPECT_NEAR(m.step, std::hypot(0.225f, 0.005f), 1e-5f);
  }
  // A stretched contact beside an ordinary spring changes nothing: not in R, C, G or |N(a)|.
  {
    const SpringSystem with = hand_system({{0, 0}, {1.5f, 0}, {0, 3}},
                                          {{0, 1, 1.0f}, {0, 2, 2.0f, kSpringContact}});
    const SpringSystem without = hand_system({{0, 0}, {1.5f, 0}, {0, 3}}, {{0, 1, 1.0f}});
    const kernels::Move a = kernels::move_particle(k, with, 0, with.position);
    const kernels::Move b = kernels::move_particle(k, without, 0, without.position);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.step, b.step);
  }
}

TEST(SolverKernels, RetiredNeighboursAreIgnored) {
  const SolverConstants k = hand_constants();
  // The chain of MoveParticleTwoSpringChain with particle 2 retired moves particle 1 exactly as the
  // chain without spring 1-2 does.
  SpringSystem sys = hand_system({{0, 0}, {1.2f, 0}, {2, 0}}, {{0, 1, 1.0f}, {1, 2, 0.5f}});
  sys.stray_count[2] = kRetired;
  const SpringSystem cut = hand_system({{0, 0}, {1.2f, 0}, {2, 0}}, {{0, 1, 1.0f}});
  const kernels::Move a = kernels::move_particle(k, sys, 1, sys.position);
  const kernels::Move b = kernels::move_particle(k, cut, 1, cut.position);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.step, b.step);
  // By hand: R = (-0.2, 0), L = p0 - p1 = (-1.2, 0), G = 0.2 * (-0.2, 5) / sqrt(25.04);
  // dp.x = -0.188 - 0.048 - 0.0008 / sqrt(25.04).
  const double n = std::sqrt(25.04);
  EXPECT_NEAR(a.position.x, 1.2 + 0.5 * (-0.188 - 0.048 + 0.02 * 0.2 * -0.2 / n), 1e-5);
  EXPECT_NEAR(a.position.y, 0.5 * (0.02 * 0.2 * 5 / n), 1e-5);
  // The retired particle itself does not move.
  const kernels::Move r = kernels::move_particle(k, sys, 2, sys.position);
  EXPECT_EQ(r.position, glm::vec2(2, 0));
  EXPECT_EQ(r.step, 0.0f);
  // A particle whose only neighbour is retired has no forces at all.
  SpringSystem lone = hand_system({{0, 0}, {3, 0}}, {{0, 1, 1.0f}});
  lone.stray_count[1] = kRetired;
  const kernels::Move l = kernels::move_particle(k, lone, 0, lone.position);
  EXPECT_EQ(l.position, glm::vec2(0, 0));
  EXPECT_EQ(l.step, 0.0f);
}

// The stray count after a sequence of lifts (true = pulled back onto the map), starting from 0.
std::uint32_t stray_count_after(const SolverConstants& k, const std::vector<bool>& pulls) {
  std::uint32_t count = 0;
  for (bool pulled : pulls) count = next_stray_count(k, count, pulled);
  return count;
}

// Stated in terms of behaviour (when a particle retires), not of the counter's values.
TEST(SolverKernels, NextStrayCount) {
  SolverConstants k = hand_constants();
  k.stray_patience = 3;
  // Never pulled back: nothing to count.
  EXPECT_EQ(stray_count_after(k, {false, false, false}), 0u);
  // Pulled back `patience` times in a row retires, on exactly the last of them.
  EXPECT_NE(stray_count_after(k, {true, true}), kRetired);
  EXPECT_EQ(stray_count_after(k, {true, true, true}), kRetired);
  // A run broken by an iteration inside the map retires later than an unbroken one.
  EXPECT_NE(stray_count_after(k, {true, false, true, true}), kRetired);
  // A single stray recovers: after quiet iterations the count is back to 0.
  EXPECT_EQ(stray_count_after(k, {true, false, false, false, false}), 0u);
  // Retired stays retired, whatever follows.
  EXPECT_EQ(next_stray_count(k, kRetired, false), kRetired);
  EXPECT_EQ(next_stray_count(k, kRetired, true), kRetired);
  EXPECT_EQ(stray_count_after(k, {true, true, true, false, false, false, false}), kRetired);
  // Patience 1 retires on the first pull back.
  k.stray_patience = 1;
  EXPECT_EQ(stray_count_after(k, {true}), kRetired);
  EXPECT_EQ(stray_count_after(k, {false}), 0u);
  // Patience 0 never retires.
  k.stray_patience = 0;
  EXPECT_NE(stray_count_after(k, std::vector<bool>(1000, true)), kRetired);
}

// A regular hexagon of radius 2 around particle 0 at the constants' centre: spokes 1..6 and rim
// springs i -> i+1, each with target = scale * its current length.
SpringSystem hexagon(glm::vec2 centre, float scale) {
  std::vector<glm::vec2> p{centre};
  for (int i = 0; i < 6; ++i) {
    const double t = i * std::numbers::pi / 3;
    p.emplace_back(float(centre.x + 2 * std::cos(t)), float(centre.y + 2 * std::sin(t)));
  }
  std::vector<HandSpring> springs;
  // Same expression as move_particle's length, so that r is 1 (or 1 / scale) to the last bit.
  auto add = [&](int a, int b) {
    const glm::vec2 d = p[b] - p[a];
    springs.push_back({a, b, scale * std::sqrt(d.x * d.x + d.y * d.y)});
  };
  for (int i = 1; i <= 6; ++i) add(0, i);
  for (int i = 1; i <= 6; ++i) add(i, i % 6 + 1);
  return hand_system(p, springs);
}

TEST(SolverKernels, HexagonIsInEquilibrium) {
  SolverConstants k = hand_constants();
  k.lambda_g = 0;
  k.centre = glm::vec2(3, -1);
  {
    const SpringSystem sys = hexagon(k.centre, 1.0f);
    // Centre: springs at rest (R = 0), C = mean of the rim = centre (L = 0).
    const kernels::Move mc = kernels::move_particle(k, sys, 0, sys.position);
    EXPECT_LT(mc.step, 1e-6f);
    // Rim particle at angle 0 (radius 2): R = 0; C = (centre + two rim neighbours at +-60 deg) / 3
    // = centre + (2 * 2 cos 60, 0) / 3 = centre + (2/3, 0), so L = (2/3 - 2, 0) = (-4/3, 0):
    // step = 0.04 * 4/3 * 0.5 = 0.0266667 inwards.
    std::vector<kernels::Move> m;
    for (int i = 1; i <= 6; ++i) m.push_back(kernels::move_particle(k, sys, i, sys.position));
    for (int i = 0; i < 6; ++i) {
      const glm::vec2 step = m[i].position - sys.position[i + 1];
      const glm::vec2 next_step = m[(i + 1) % 6].position - sys.position[(i + 1) % 6 + 1];
      const glm::vec2 turned = rotate(step, 60);
      EXPECT_NEAR(turned.x, next_step.x, 1e-5f) << "rim " << i;
      EXPECT_NEAR(turned.y, next_step.y, 1e-5f) << "rim " << i;
      const glm::vec2 outward = rotate(glm::vec2(1, 0), 60.0 * i);
      EXPECT_NEAR(glm::dot(step, outward), -0.04f * 4.0f / 3.0f * 0.5f, 1e-5f) << "rim " << i;
      EXPECT_NEAR(m[i].step, 0.04f * 4.0f / 3.0f * 0.5f, 1e-5f) << "rim " << i;
    }
  }
  {
    // Targets 10% longer: every spring has len - l = -0.2 (len 2, l 2.2), r = 1/1.1.
    // Rim at angle 0: spoke d = (-2, 0) gives k * (-0.2 / 2) * (-2, 0) = k (0.2, 0); rim springs
    // d = (-1, +-sqrt3) give k * (-0.1) * (-1, +-sqrt3): x parts 0.1 k each, y parts cancel.
    // R = k (0.4, 0) / 3k = (0.4/3, 0). C unchanged (equal targets): L = (-4/3, 0).
    // dp = 0.94 * 0.4/3 - 0.04 * 4/3 = 0.125333 - 0.053333 = 0.072; step = 0.036 outwards.
    const SpringSystem sys = hexagon(k.centre, 1.1f);
    const kernels::Move mc = kernels::move_particle(k, sys, 0, sys.position);
    EXPECT_LT(mc.step, 1e-6f);
    for (int i = 0; i < 6; ++i) {
      const kernels::Move m = kernels::move_particle(k, sys, i + 1, sys.position);
      const glm::vec2 step = m.position - sys.position[i + 1];
      const glm::vec2 outward = rotate(glm::vec2(1, 0), 60.0 * i);
      EXPECT_NEAR(glm::dot(step, outward), 0.036f, 1e-5f) << "rim " << i;
      EXPECT_NEAR(outward.x * step.y - outward.y * step.x, 0.0f, 1e-5f) << "rim " << i << " moves sideways";
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The CPU solver.

constexpr double kSide = 100;  // the flat square [0, 100]^2 at z = 0
constexpr int kQuads = 20;
constexpr double kSpacing = 6;  // D

SurfaceMesh flat_square() {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= kQuads; ++j)
    for (int i = 0; i <= kQuads; ++i) positions.emplace_back(kSide * i / kQuads, kSide * j / kQuads, 0.0);
  auto id = [](int i, int j) { return j * (kQuads + 1) + i; };
  for (int j = 0; j < kQuads; ++j)
    for (int i = 0; i < kQuads; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make_surface(std::move(positions), faces, "flat square").mesh;
}

struct Scene {
  SurfaceMap map;
  SolverSurface surface;
};

Scene make_scene(SurfaceMesh mesh) {
  Scene s{build_surface_map(std::move(mesh)), {}};
  s.surface = make_solver_surface(s.map);
  return s;
}

const Scene& flat_scene() {
  static const Scene scene = make_scene(flat_square());
  return scene;
}

const Scene& dome_scene() {
  static const Scene scene = make_scene(load_surface(std::string(PAVER_SOURCE_DIR) + "/assets/surfaces/dome.obj").mesh);
  return scene;
}

// The braced honeycomb with edge length `spacing`, placed at the map's origin.
Pattern hex_pattern(const Scene& scene, double spacing) {
  PatternDesign design;
  design.tessellation = Tessellation::Hexagon;
  design.spacing = spacing;
  design.bracing = true;
  return build_pattern(scene.map, make_design_cell(design), {});
}

const Pattern& flat_pattern() {
  static const Pattern pattern = hex_pattern(flat_scene(), kSpacing);
  return pattern;
}

// No margins, no gravity: on an isometric map a perfect lattice has every spring at its target.
SolverParams at_rest_params() {
  SolverParams p;
  p.c = 0, p.m = 0, p.lambda_g = 0;
  return p;
}

int degree(const SpringSystem& sys, int a) { return sys.neighbor_start[a + 1] - sys.neighbor_start[a]; }

TEST(SpringSolver, PerfectLatticeOnAPlaneDoesNotMove) {
  const Scene& scene = flat_scene();
  SpringSystem initial = make_spring_system(flat_pattern());
  // At rest means at the lattice's own lengths: without the small aim past contact that
  // make_spring_system adds (every spring would push by 0.1%).
  for (int s = 0; s < initial.spring_count(); ++s) initial.rest_length[s] = float(flat_pattern().edge_rest_length[s]);
  // A braced honeycomb vertex has 3 pattern edges and 3 long diagonals (one per hexagon it is on).
  int full = 0;
  for (int a = 0; a < initial.particle_count(); ++a) full = std::max(full, degree(initial, a));
  ASSERT_EQ(full, 6);
  const double tolerance = 1e-3 * kSpacing;
  {
    // One step with the local-centric force on: an interior particle has every spring at its
    // target (R = 0) and a point-symmetric one-ring (C = p_a, L = 0), so it stays. A boundary
    // particle's one-ring is partial, C != p_a, and it moves by lambda_l dt |L| = 0.012 |L|, with
    // |L| a fair fraction of D for a particle with neighbours on one side only.
    SpringSystem sys = initial;
    CpuSpringSolver solver(scene.surface, sys, at_rest_params(), kSpacing, 1);
    solver.step();
    int interior = 0;
    double boundary_moved = 0;
    for (int a = 0; a < sys.particle_count(); ++a) {
      const double moved = glm::length(sys.position[a] - initial.position[a]);
      if (degree(sys, a) != full) {
        boundary_moved = std::max(boundary_moved, moved);
        continue;
      }
      ++interior;
      EXPECT_LE(moved, tolerance) << "particle " << a;
    }
    EXPECT_GT(interior, sys.particle_count() / 3);
    EXPECT_GT(boundary_moved, tolerance);
  }
  {
    // That boundary motion travels inwards about one ring per iteration (eq. 10-11 on partial
    // one-rings, as the paper has it), so over many steps only lambda_l = 0 keeps the lattice at
    // rest: then R is the only force and every spring is at its target, boundary ones included.
    SpringSystem sys = initial;
    SolverParams params = at_rest_params();
    params.lambda_l = 0;
    CpuSpringSolver solver(scene.surface, sys, params, kSpacing, 1);
    for (int i = 0; i < 50; ++i) solver.step();
    for (int a = 0; a < sys.particle_count(); ++a)
      EXPECT_LE(glm::length(sys.position[a] - initial.position[a]), tolerance) << "particle " << a;
  }
}

TEST(SpringSolver, DeterministicAcrossThreadCounts) {
  const Scene& scene = dome_scene();
  // D = 6 as in the paper's dome (Fig. 9: ~700 particles, ~1900 springs), and D = 3 so that both
  // loops are longer than the solver's grain and really split across threads.
  for (double spacing : {kSpacing, kSpacing / 2}) {
    const SpringSystem initial = make_spring_system(hex_pattern(scene, spacing));
    if (spacing < kSpacing) {
      ASSERT_GT(initial.particle_count(), 2048);
      ASSERT_GT(initial.spring_count(), 2048);
    }
    std::vector<SpringSystem> result;
    for (int threads : {1, 2, 0}) {
      SpringSystem sys = initial;
      CpuSpringSolver solver(scene.surface, sys, SolverParams{}, spacing, threads);
      for (int i = 0; i < 100; ++i) solver.step();
      result.push_back(std::move(sys));
    }
    for (size_t r = 1; r < result.size(); ++r) {
      ASSERT_EQ(result[r].position.size(), result[0].position.size());
      EXPECT_EQ(std::memcmp(result[r].position.data(), result[0].position.data(),
                            result[0].position.size() * sizeof(glm::vec2)),
                0)
          << "D " << spacing << ", run " << r;
      EXPECT_EQ(result[r].target, result[0].target) << "D " << spacing << ", run " << r;
      EXPECT_EQ(result[r].stray_count, result[0].stray_count) << "D " << spacing << ", run " << r;
    }
  }
}

TEST(SpringSolver, StopsWhenConverged) {
  {
    // The dome's lattice is far from its targets: three iterations are not enough.
    const Scene& scene = dome_scene();
    SpringSystem sys = make_spring_system(hex_pattern(scene, kSpacing));
    SolverParams params;
    params.iterations = 3;
    const SolveReport report = CpuSpringSolver(scene.surface, sys, params, kSpacing).solve();
    EXPECT_EQ(report.reason, StopReason::IterationLimit);
    EXPECT_EQ(report.iterations, 3);
    EXPECT_GE(report.last_max_step, params.threshold * kSpacing);
  }
  {
    // The perfect lattice on the plane only settles its boundary (L pulls the edge particles
    // towards their partial one-rings) and comes to rest before the limit.
    const Scene& scene = flat_scene();
    SpringSystem sys = make_spring_system(flat_pattern());
    SolverParams params = at_rest_params();
    params.threshold = 1e-3;
    params.iterations = 200;
    const SolveReport report = CpuSpringSolver(scene.surface, sys, params, kSpacing).solve();
    EXPECT_EQ(report.reason, StopReason::Converged);
    EXPECT_LT(report.iterations, params.iterations);
    EXPECT_LT(report.last_max_step, params.threshold * kSpacing);
  }
  {
    const Scene& scene = flat_scene();
    SpringSystem sys = make_spring_system(flat_pattern());
    int calls = 0;
    const SolveReport report =
        CpuSpringSolver(scene.surface, sys, SolverParams{}, kSpacing).solve([&](int iteration, const auto& positions) {
          ++calls;
          EXPECT_EQ(iteration, 1);
          EXPECT_EQ(positions.size(), sys.position.size());
          return false;
        });
    EXPECT_EQ(report.reason, StopReason::Observer);
    EXPECT_EQ(report.iterations, 1);
    EXPECT_EQ(calls, 1);
  }
}

TEST(SpringSolver, StraysArePulledBack) {
  const Scene& scene = flat_scene();
  SpringSystem sys = make_spring_system(flat_pattern());
  // The particle nearest the centre of the map, thrown far outside it.
  const glm::vec2 centre = scene.surface.centre;
  int moved = 0;
  for (int a = 0; a < sys.particle_count(); ++a)
    if (glm::length(sys.position[a] - centre) < glm::length(sys.position[moved] - centre)) moved = a;
  const glm::vec2 extent = glm::vec2(scene.map.uv_max - scene.map.uv_min);
  sys.position[moved] = centre + glm::vec2(10 * extent.x, 0);
  glm::vec3 bary;
  ASSERT_LT(kernels::locate(scene.surface, sys.position[moved], bary), 0);

  SolverParams params;
  params.iterations = 1;
  CpuSpringSolver solver(scene.surface, sys, params, kSpacing, 1);
  // The first lift (in the constructor) already brought it back and counted it.
  EXPECT_GE(kernels::locate(scene.surface, sys.position[moved], bary), 0);
  EXPECT_NE(sys.stray_count[moved], 0u);
  EXPECT_NE(sys.stray_count[moved], kRetired);
  const SolveReport report = solver.solve();
  EXPECT_EQ(report.iterations, 1);
  EXPECT_GE(kernels::locate(scene.surface, sys.position[moved], bary), 0);
  EXPECT_GE(bary.x, 0.0f);
  EXPECT_GE(bary.y, 0.0f);
  EXPECT_GE(bary.z, 0.0f);
  // Only the thrown particle ever left the map: its neighbours pull it inwards, into the convex
  // hull of itself and them, which lies in the (convex) square.
  EXPECT_EQ(report.strays_pulled_back, 1);
  EXPECT_NE(sys.stray_count[moved], kRetired);  // one pull back is not enough to retire
  for (int a = 0; a < sys.particle_count(); ++a)
    EXPECT_GE(kernels::locate(scene.surface, sys.position[a], bary), 0) << "particle " << a;
}

// ---------------------------------------------------------------------------------------------
// Regression: a spring whose ends coincide (or nearly: r = |p_a p_b| / l_ab below ~7e-4 in float)
// made k_c(r) NaN or infinite (alpha / r^12 - beta / r^6 is inf - inf at r = 0), and the NaN was
// then hidden by the pull back (it landed on boundary_inward[0]). move_particle now clamps r and
// gives coincident ends a direction; lift_all refuses non-finite positions.

TEST(SolverKernels, CoincidentEndsGiveAFiniteMove) {
  const SolverConstants k = hand_constants();
  for (float x : {0.0f, 5e-4f}) {
    const SpringSystem sys = hand_system({{0, 0}, {x, 0}, {1, 0}}, {{0, 1, 1.0f}, {0, 2, 1.0f}});
    const kernels::Move m = kernels::move_particle(k, sys, 0, sys.position);
    EXPECT_TRUE(std::isfinite(m.position.x) && std::isfinite(m.position.y)) << "|p0 p1| = " << x;
    EXPECT_TRUE(std::isfinite(m.step)) << "|p0 p1| = " << x;
  }
}

TEST(SpringSolver, CoincidentParticlesStayFinite) {
  const Scene& scene = flat_scene();
  // How two particles come to coincide: two neighbours pushed out past a convex corner of the map
  // are both pulled back onto the corner vertex (the nearest boundary point of each) and nudged by
  // the same rule to the same point.
  const std::vector<glm::vec4>& boundary = scene.surface.boundary_segments;
  const glm::vec2 centre = scene.surface.centre;
  glm::vec2 corner(boundary[0].x, boundary[0].y);
  for (glm::vec4 segment : boundary) {
    const glm::vec2 q(segment.x, segment.y);
    if (glm::length(q - centre) > glm::length(corner - centre)) corner = q;
  }
  const glm::vec2 out = glm::normalize(corner - centre);  // the corner's bisector, outwards
  const glm::vec2 side(-out.y, out.x);
  SpringSystem sys = hand_system({corner + 5.0f * out, corner + 7.0f * out + 0.5f * side}, {{0, 1, 0.0f}});
  sys.rest_length[0] = float(kSpacing);
  CpuSpringSolver solver(scene.surface, sys, SolverParams{}, kSpacing, 1);
  ASSERT_EQ(sys.position[0], sys.position[1]) << "both strays land on one point";
  solver.step();
  EXPECT_TRUE(std::isfinite(sys.position[0].x) && std::isfinite(sys.position[1].x));
  solver.solve();
  EXPECT_NE(sys.position[0], scene.surface.boundary_inward[0]) << "teleported to boundary segment 0";
  EXPECT_NE(sys.position[1], scene.surface.boundary_inward[0]) << "teleported to boundary segment 0";
}

}  // namespace
}  // namespace paver
