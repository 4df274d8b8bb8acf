// The solver's CPU/GPU contract, written once and compiled as C++ (engine/solver/solver_kernels.h,
// compute/) and as GLSL (shaders/solver_*.comp include it through glslang's include path):
//   - the descriptor bindings, the parameter block (std140), the push constants, the control
//     slots and the flag bits;
//   - the pure per-item arithmetic of one iteration (eq. 3-16), so that the CPU reference and the
//     shaders cannot drift: only buffer access differs between the two sides.
// The code below is the common subset of both languages: GLSL's vec types (glm on the C++ side),
// uint32_t (GLSL's uint, by a macro here only), float literals with an `f`, uint literals with a `u`. Every temporary is PAVER_PRECISE: on the
// GPU `precise` forbids fusing and reordering, on the CPU the project builds with
// -ffp-contract=off, so both compute the same float32 operations in the same order.
#ifndef PAVER_SOLVER_CONTRACT_H
#define PAVER_SOLVER_CONTRACT_H

#ifdef __cplusplus
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace paver {
using glm::vec2;
using glm::vec3;
using glm::vec4;
using std::floor;
using std::sqrt;
using std::uint32_t;
#define PAVER_CONST inline constexpr
#define PAVER_FN inline
#define PAVER_PRECISE
#define PAVER_ALIGN16 alignas(16)
#define PAVER_IN(type) const type&
#else
#define uint32_t uint
#define PAVER_CONST const
#define PAVER_FN
#define PAVER_PRECISE precise
#define PAVER_ALIGN16
#define PAVER_IN(type) type
#endif

// ---- Layout -------------------------------------------------------------------------------------

// Workgroup size of every solver pass (local_size_x).
PAVER_CONST uint32_t kSolverGroupSize = 64u;

// Bindings of the solver's one descriptor set; kBindingParams is the uniform block, the rest are
// std430 storage buffers holding the SpringSystem / SolverSurface arrays of the same name.
PAVER_CONST uint32_t kBindingParams = 0u;
PAVER_CONST uint32_t kBindingUv = 1u;               // vec2 #V: the map
PAVER_CONST uint32_t kBindingSurfacePosition = 2u;  // vec4 #V: xyz of the surface's vertices
PAVER_CONST uint32_t kBindingSurfaceCurvature = 3u; // float #V: |H|
PAVER_CONST uint32_t kBindingTriangles = 4u;        // int 3#F
PAVER_CONST uint32_t kBindingGridStart = 5u;        // int: uv grid CSR starts
PAVER_CONST uint32_t kBindingGridTriangles = 6u;    // int: uv grid CSR triangles
PAVER_CONST uint32_t kBindingBoundarySegments = 7u; // vec4: each boundary segment's ends in the map, all loops
PAVER_CONST uint32_t kBindingBoundaryInward = 8u;   // vec2: a point inside next to each boundary segment
PAVER_CONST uint32_t kBindingPositionIn = 9u;       // vec2 #P
PAVER_CONST uint32_t kBindingPositionOut = 10u;     // vec2 #P
PAVER_CONST uint32_t kBindingStrayCount = 11u;      // uint #P
PAVER_CONST uint32_t kBindingTriangleHint = 12u;    // int #P
PAVER_CONST uint32_t kBindingPulledBack = 13u;      // uint #P
PAVER_CONST uint32_t kBindingLifted = 14u;          // vec4 #P: xyz position, w curvature
PAVER_CONST uint32_t kBindingNeighborStart = 15u;   // int #P + 1
PAVER_CONST uint32_t kBindingNeighbor = 16u;        // int #2E
PAVER_CONST uint32_t kBindingNeighborSpring = 17u;  // int #2E
PAVER_CONST uint32_t kBindingSpringA = 18u;         // int #E
PAVER_CONST uint32_t kBindingSpringB = 19u;         // int #E
PAVER_CONST uint32_t kBindingRestLength = 20u;      // float #E
PAVER_CONST uint32_t kBindingSpringFlags = 21u;     // uint #E
PAVER_CONST uint32_t kBindingTarget = 22u;          // float #E
PAVER_CONST uint32_t kBindingInitialTarget = 23u;   // float #E
PAVER_CONST uint32_t kBindingControl = 24u;         // uint kControlSlots
PAVER_CONST uint32_t kBindingBoundaryGridStart = 25u;     // int: uv grid CSR starts of the boundary bins
PAVER_CONST uint32_t kBindingBoundaryGridSegments = 26u;  // int: uv grid CSR boundary segments
PAVER_CONST uint32_t kBindingCount = 27u;

// The control block: one solve's state on the GPU, read back between batches.
PAVER_CONST uint32_t kControlDone = 0u;         // 1 once converged
PAVER_CONST uint32_t kControlIterations = 1u;   // iterations run
PAVER_CONST uint32_t kControlStrays = 2u;       // pull backs
PAVER_CONST uint32_t kControlMaxStep = 3u;      // this iteration's max step, float bits (steps >= 0, so uint order is float order)
PAVER_CONST uint32_t kControlError = 4u;        // kError* bits
PAVER_CONST uint32_t kControlLastMaxStep = 5u;  // the last finished iteration's max step, float bits
PAVER_CONST uint32_t kControlSlots = 8u;

PAVER_CONST uint32_t kErrorNonFinite = 1u;  // a particle position became NaN or infinite
PAVER_CONST uint32_t kErrorNotLifted = 2u;  // a particle could not be located on the map

PAVER_CONST uint32_t kRetired = 0xffffffffu;  // stray_count of a retired particle
// stray_count of a particle the designer pinned (design.edits): it never moves and never retires,
// while its springs still pull and push its neighbours.
PAVER_CONST uint32_t kPinned = 0xfffffffeu;
PAVER_CONST uint32_t kSpringVirtual = 1u;     // spring_flags: a bracing edge across a face
// A contact spring keeps two colliding elements apart: its rest length is the required 3D
// distance (no margin, no filter) and it only pushes, never pulls.
PAVER_CONST uint32_t kSpringContact = 2u;

// The parameter block (std140 on the GPU; the C++ struct is its mirror, checked below). The
// kernels' constants come first; the rest only the GPU needs (the CPU has them elsewhere).
struct PAVER_ALIGN16 SolverConstants {
  float c, m;                                     // eq. 5
  float alpha, beta;                              // eq. 8
  float gamma, lambda_r, lambda_l, lambda_g;      // eq. 8, eq. 13
  float dt, mu_compressed, mu_stretched, filter_max;  // eq. 14, eq. 16 and the clamp
  float curvature_min, curvature_inv_range;       // eq. 5 normalisation
  float threshold;                                // convergence: max settled step, surface units
  float grid_cell_size;                           // the uv grid
  vec2 centre;                                    // O(M^), eq. 12
  vec2 grid_origin;
  int grid_nx, grid_ny, boundary_count, particle_count;
  int spring_count;
  uint32_t filter_base_initial;  // 1: clamp against l_ab at initialisation, 0: current l_ab
  uint32_t stray_patience;       // pulls back in a row before a particle retires; 0 = never
  // A map that wraps (a band's seamless map): the plane repeats every (period, 0), and particles
  // live at u in [period_origin, period_origin + period). period = 0: it does not wrap.
  float period, period_origin;
  uint32_t pad0, pad1, pad2;
};

// Push constants of the lift pass (count_strays, always) and the spring pass (always).
struct SolverPush {
  uint32_t first;   // lift: 1 counts strays (0 for the closing lift); springs: 1 runs even when done
  uint32_t second;  // lift: 1 runs even when the solve is done (initial and closing lifts)
};

#ifdef __cplusplus
static_assert(sizeof(SolverConstants) == 128);
static_assert(offsetof(SolverConstants, dt) == 32);
static_assert(offsetof(SolverConstants, curvature_min) == 48);
static_assert(offsetof(SolverConstants, centre) == 64);  // std140: vec2 on 8 bytes
static_assert(offsetof(SolverConstants, grid_origin) == 72);
static_assert(offsetof(SolverConstants, grid_nx) == 80);
static_assert(offsetof(SolverConstants, spring_count) == 96);
static_assert(offsetof(SolverConstants, stray_patience) == 104);
static_assert(offsetof(SolverConstants, period) == 108);
static_assert(sizeof(SolverPush) == 8);
#endif

// ---- Arithmetic ----------------------------------------------------------------------------------

// min / max as GLSL defines them for non-NaN input (std::fmin is a library call).
PAVER_FN float min_f(float a, float b) { return b < a ? b : a; }
PAVER_FN float max_f(float a, float b) { return a < b ? b : a; }

PAVER_FN float length_2d(vec2 d) {
  PAVER_PRECISE float len = sqrt(d.x * d.x + d.y * d.y);
  return len;
}

PAVER_FN float length_3d(vec3 d) {
  PAVER_PRECISE float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return len;
}

// Barycentric coordinates of p in triangle (a, b, c); the same expression as uv_grid.cpp in double.
PAVER_FN vec3 barycentric(vec2 p, vec2 a, vec2 b, vec2 c) {
  PAVER_PRECISE vec2 v0 = b - a;
  PAVER_PRECISE vec2 v1 = c - a;
  PAVER_PRECISE vec2 v2 = p - a;
  PAVER_PRECISE float det = v0.x * v1.y - v0.y * v1.x;
  PAVER_PRECISE float w1 = (v2.x * v1.y - v2.y * v1.x) / det;
  PAVER_PRECISE float w2 = (v0.x * v2.y - v0.y * v2.x) / det;
  PAVER_PRECISE float w0 = 1.0f - w1 - w2;
  return vec3(w0, w1, w2);
}

// The best candidate's coordinates when p lies just outside every triangle (on a shared edge):
// negatives clamped to 0, renormalised.
PAVER_FN vec3 clamp_barycentric(vec3 b) {
  PAVER_PRECISE vec3 clamped = vec3(max_f(b.x, 0.0f), max_f(b.y, 0.0f), max_f(b.z, 0.0f));
  PAVER_PRECISE float sum = clamped.x + clamped.y + clamped.z;
  PAVER_PRECISE vec3 result = vec3(clamped.x / sum, clamped.y / sum, clamped.z / sum);
  return result;
}

// p with its u wrapped into the period (p itself when the map does not wrap).
// Positions are wrapped every lift, so a particle is at most one period out: compare first, and
// divide only for one farther away (a division per particle and per spring end costs a band
// 40% of a solver step against a disk).
PAVER_FN vec2 wrap_position(float period, float origin, vec2 p) {
  if (period <= 0.0f) return p;
  PAVER_PRECISE float offset = p.x - origin;
  if (offset >= 0.0f && offset < period) return p;
  PAVER_PRECISE float once = offset < 0.0f ? p.x + period : p.x - period;
  PAVER_PRECISE float once_offset = once - origin;
  if (once_offset >= 0.0f && once_offset < period) return vec2(once, p.y);
  PAVER_PRECISE float turns = floor(offset / period);
  PAVER_PRECISE float u = p.x - turns * period;
  return vec2(u, p.y);
}

// The copy of p nearest to `near` (p itself when the map does not wrap): a spring's other end
// across the seam.
PAVER_FN vec2 nearest_image(float period, vec2 p, vec2 near) {
  if (period <= 0.0f) return p;
  PAVER_PRECISE float half_period = 0.5f * period;
  PAVER_PRECISE float d = p.x - near.x;
  if (d >= -half_period && d <= half_period) return p;
  PAVER_PRECISE float once = d < 0.0f ? p.x + period : p.x - period;
  PAVER_PRECISE float once_d = once - near.x;
  if (once_d >= -half_period && once_d <= half_period) return vec2(once, p.y);
  PAVER_PRECISE float turns = floor((p.x - near.x) / period + 0.5f);
  PAVER_PRECISE float u = p.x - turns * period;
  return vec2(u, p.y);
}

// Squared distance from p to segment ab and, in `nudged`, the segment's nearest point moved 1% of
// the way towards `inward` (the NOTES' reading of strays: back onto the map, just inside).
struct BoundaryCandidate {
  float dist2;
  vec2 nudged;
};

PAVER_FN BoundaryCandidate boundary_candidate(vec2 p, vec2 a, vec2 b, vec2 inward) {
  PAVER_PRECISE vec2 ab = b - a;
  PAVER_PRECISE vec2 ap = p - a;
  PAVER_PRECISE float len2 = ab.x * ab.x + ab.y * ab.y;
  PAVER_PRECISE float t = len2 > 0.0f ? (ap.x * ab.x + ap.y * ab.y) / len2 : 0.0f;
  t = min_f(max_f(t, 0.0f), 1.0f);
  PAVER_PRECISE vec2 q = vec2(a.x + t * ab.x, a.y + t * ab.y);
  PAVER_PRECISE vec2 d = p - q;
  PAVER_PRECISE float dist2 = d.x * d.x + d.y * d.y;
  PAVER_PRECISE vec2 nudged = vec2(q.x + 0.01f * (inward.x - q.x), q.y + 0.01f * (inward.y - q.y));
  BoundaryCandidate result;
  result.dist2 = dist2;
  result.nudged = nudged;
  return result;
}

// The same on a map that wraps: the image of p nearest the segment is pulled back, and the nudged
// point moved back beside p (so one copy of the boundary serves every period). Plain
// boundary_candidate when the map does not wrap.
PAVER_FN BoundaryCandidate wrapped_boundary_candidate(float period, vec2 p, vec2 a, vec2 b, vec2 inward) {
  PAVER_PRECISE vec2 middle = vec2(0.5f * (a.x + b.x), 0.5f * (a.y + b.y));
  vec2 q = nearest_image(period, p, middle);
  BoundaryCandidate candidate = boundary_candidate(q, a, b, inward);
  PAVER_PRECISE float shift = p.x - q.x;
  PAVER_PRECISE vec2 back = vec2(candidate.nudged.x + shift, candidate.nudged.y);
  candidate.nudged = back;
  return candidate;
}

// The pull-back search (kernels::pull_back, solver_lift.comp) on a map that does not wrap: the
// boundary segments are binned in the point-location grid's cells, and square rings of cells
// around p's cell (clamped into the grid) are searched outwards. A scan of every segment made a
// real GPU wait on the one stray in a warp (about 900 segments on the dense wave, every
// iteration). The nearest segment wins, the lower index on a tie, exactly as the full scan.
PAVER_FN int clamped_cell(float coordinate, float origin, float cell_size, int cells) {
  PAVER_PRECISE float r = (coordinate - origin) / cell_size;
  // max_f(0, NaN) is 0: a NaN point (never lifted; the solvers stop on one first) gets cell 0 and
  // a search that ends, not an undefined int().
  r = min_f(max_f(0.0f, r), float(cells - 1));
  return int(r);
}

// Along one axis: how far p's coordinate lies inside the searched cells [lo, hi] of n, from the
// nearer of their sides that is not the grid's edge (3e38 when both are).
PAVER_FN float unsearched_gap(float coordinate, float origin, float cell_size, int n, int lo, int hi) {
  float nearest = 3.0e38f;
  if (hi + 1 < n) {
    PAVER_PRECISE float d = origin + float(hi + 1) * cell_size - coordinate;
    nearest = min_f(nearest, d);
  }
  if (lo > 0) {
    PAVER_PRECISE float d = coordinate - (origin + float(lo) * cell_size);
    nearest = min_f(nearest, d);
  }
  return nearest;
}

// How close to p a segment binned only in cells outside the searched block [x0, x1] x [y0, y1]
// could lie: the distance from p to the nearest side of the block that is not the grid's edge;
// -1 once the block covers the whole grid.
PAVER_FN float unsearched_distance(vec2 p, vec2 origin, float cell_size, int nx, int ny, int x0, int x1, int y0,
                                   int y1) {
  if (x0 <= 0 && y0 <= 0 && x1 + 1 >= nx && y1 + 1 >= ny) return -1.0f;
  PAVER_PRECISE float nearest = min_f(unsearched_gap(p.x, origin.x, cell_size, nx, x0, x1),
                                      unsearched_gap(p.y, origin.y, cell_size, ny, y0, y1));
  return max_f(nearest, 0.0f);  // p on a side (rounding of its cell): searched on
}

// Whether the search may stop: every unsearched segment lies farther than the best one found,
// with a margin far above float32 rounding of the squared distances (a segment that could tie
// is always searched, so the tie goes to the lower index as in a full scan).
PAVER_FN bool pull_back_search_done(float unsearched, float best_dist2, float cell_size) {
  if (unsearched < 0.0f) return true;
  PAVER_PRECISE float reach = unsearched * unsearched;
  return unsearched > 1e-5f * cell_size && reach > best_dist2 * 1.001f;
}

// Eq. 2 and 3: position and curvature at barycentric b of a triangle with corners (xyz, curvature).
PAVER_FN vec4 lift_barycentric(vec3 b, vec4 pi, vec4 pj, vec4 pk, float ki, float kj, float kk) {
  PAVER_PRECISE vec3 position = vec3(b.x * pi.x + b.y * pj.x + b.z * pk.x, b.x * pi.y + b.y * pj.y + b.z * pk.y,
                                     b.x * pi.z + b.y * pj.z + b.z * pk.z);
  PAVER_PRECISE float kappa = b.x * ki + b.y * kj + b.z * kk;
  return vec4(position.x, position.y, position.z, kappa);
}

// Whether a particle with this stray count takes steps (neither retired nor pinned).
PAVER_FN bool particle_moves(uint32_t count) { return count < kPinned; }

// New stray count of a particle after a lift that did (or did not) pull it back: +2 for a pull
// back, -1 otherwise, so a particle pushed out every iteration retires after `stray_patience`
// iterations and one that goes out every other iteration after about twice that, while an
// occasional stray recovers.
PAVER_FN uint32_t next_stray_count(PAVER_IN(SolverConstants) k, uint32_t count, bool pulled_back) {
  if (count >= kPinned) return count;  // retired and pinned particles stay so
  if (!pulled_back) return count > 0u ? count - 1u : 0u;
  uint32_t next = count + 2u;
  return k.stray_patience != 0u && next >= 2u * k.stray_patience ? kRetired : next;
}

// 3D target length L_ab (eq. 4-6).
PAVER_FN float target_length_3d(PAVER_IN(SolverConstants) k, float rest, float kappa_a, float kappa_b) {
  PAVER_PRECISE float normalised = (max_f(kappa_a, kappa_b) - k.curvature_min) * k.curvature_inv_range;
  normalised = min_f(max_f(normalised, 0.0f), 1.0f);
  PAVER_PRECISE float result = (k.c + k.m * normalised) * rest + rest;
  return result;
}

struct SpringState {
  float target;    // filtered 2D target l^{t+1}
  float ratio_3d;  // |P_a P_b| / L_ab: how far the spring is from its 3D target
};

// One spring: the 2D target from the local distortion and the adaptive filter (eq. 15, 16).
// d2 = p_b - p_a, d3 = P_b - P_a. `reset` restarts the filter from the unfiltered target: at
// initialisation, and when an end was just pulled back onto the map (its wound-up target would
// push it straight out again). `initial` is l_ab at initialisation (FilterBase::Initial).
PAVER_FN SpringState update_spring(PAVER_IN(SolverConstants) k, vec2 d2, vec3 d3, float kappa_a, float kappa_b,
                                   float rest, float previous, float initial, bool reset, uint32_t flags) {
  PAVER_PRECISE float len2 = length_2d(d2);
  PAVER_PRECISE float len3 = length_3d(d3);
  float target3 = (flags & kSpringContact) != 0u ? rest : target_length_3d(k, rest, kappa_a, kappa_b);
  // l_ab = L_ab |p_a p_b| / |P_a P_b|; a collapsed spring keeps the plain 3D target.
  PAVER_PRECISE float raw = len3 > 0.0f && len2 > 0.0f ? target3 * len2 / len3 : target3;
  PAVER_PRECISE float ratio = len3 / target3;
  SpringState state;
  state.ratio_3d = ratio;
  // Virtual springs only keep the structure: the filter's extra push would make them fight the
  // pattern's own springs (a chord across a curved face is shorter than the face), so they keep
  // the unfiltered target; so do contact springs, whose target is exact.
  if (reset || flags != 0u) {
    state.target = raw;
    return state;
  }
  float mu = len3 < target3 ? k.mu_compressed : k.mu_stretched;
  PAVER_PRECISE float w = 1.0f + mu * (1.0f - len3 / target3);
  float base = k.filter_base_initial != 0u ? initial : raw;
  PAVER_PRECISE float grown = w * previous;
  PAVER_PRECISE float upper = k.filter_max * base;
  state.target = min_f(max_f(grown, base), upper);
  return state;
}

// k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8), as (alpha s - beta) s + gamma with s = 1 / r^6:
// one division instead of two (divisions bound the move pass on a CPU).
PAVER_FN float spring_constant(PAVER_IN(SolverConstants) k, float r) {
  PAVER_PRECISE float r2 = r * r;
  PAVER_PRECISE float r6 = r2 * r2 * r2;
  PAVER_PRECISE float s = 1.0f / r6;
  PAVER_PRECISE float kc = (k.alpha * s - k.beta) * s + k.gamma;
  return kc;
}

// Contact springs only push: one longer than its target exerts nothing.
PAVER_FN bool spring_is_slack(uint32_t flags, float len, float target) {
  return (flags & kSpringContact) != 0u && len >= target;
}

// What a particle gathers over its springs for eq. 9-12.
struct SpringSums {
  vec2 force;         // sum of F_ab (eq. 7)
  vec2 centroid_sum;  // sum of p_b / l_ab (eq. 11 with p_b)
  float k_sum;        // sum of k_c (eq. 9)
  float w_sum;        // sum of 1 / l_ab (eq. 11)
  float stretch_sum;  // sum of |p_a p_b| - l_ab (eq. 12)
  int used;
};

PAVER_FN SpringSums no_spring_sums() {
  SpringSums s;
  s.force = vec2(0.0f);
  s.centroid_sum = vec2(0.0f);
  s.k_sum = 0.0f;
  s.w_sum = 0.0f;
  s.stretch_sum = 0.0f;
  s.used = 0;
  return s;
}

// Adds spring a-b: d = p_b - p_a, len = |d|, l = l_ab. `side` (+1 or -1) separates coincident
// ends along x, the lower index to the left, so the two sides push apart.
PAVER_FN SpringSums accumulate_spring(PAVER_IN(SolverConstants) k, SpringSums s, vec2 pb, vec2 d, float len, float l,
                               float side) {
  // Reciprocals once, products after: three divisions per spring instead of eight.
  PAVER_PRECISE float inv_l = 1.0f / l;
  // r is clamped at 0.1: below it k_c grows without bound (inf at r = 0).
  PAVER_PRECISE float ratio = len * inv_l;
  float kc = spring_constant(k, max_f(ratio, 0.1f));
  PAVER_PRECISE float tiny = 1e-6f * l;
  PAVER_PRECISE float inv_len = len > tiny ? 1.0f / len : 0.0f;
  PAVER_PRECISE vec2 unit = len > tiny ? vec2(d.x * inv_len, d.y * inv_len) : vec2(side, 0.0f);
  PAVER_PRECISE float f = kc * (len - l);
  SpringSums r;
  PAVER_PRECISE vec2 force = vec2(s.force.x + f * unit.x, s.force.y + f * unit.y);
  PAVER_PRECISE vec2 centroid_sum = vec2(s.centroid_sum.x + pb.x * inv_l, s.centroid_sum.y + pb.y * inv_l);
  PAVER_PRECISE float k_sum = s.k_sum + kc;
  PAVER_PRECISE float w_sum = s.w_sum + inv_l;
  PAVER_PRECISE float stretch_sum = s.stretch_sum + (len - l);
  r.force = force;
  r.centroid_sum = centroid_sum;
  r.k_sum = k_sum;
  r.w_sum = w_sum;
  r.stretch_sum = stretch_sum;
  r.used = s.used + 1;
  return r;
}

// The step dp * dt of a particle at pa with sums over at least one spring: R (eq. 9), L (eq. 10),
// G (eq. 12), combined (eq. 13) and scaled (eq. 14).
PAVER_FN vec2 particle_step(PAVER_IN(SolverConstants) k, vec2 pa, SpringSums s) {
  PAVER_PRECISE vec2 restoring = vec2(s.force.x / s.k_sum, s.force.y / s.k_sum);
  PAVER_PRECISE vec2 local_force = vec2(s.centroid_sum.x / s.w_sum - pa.x, s.centroid_sum.y / s.w_sum - pa.y);
  // On a map that wraps, the centre is a line along the band: G pulls across it only.
  PAVER_PRECISE vec2 to_centre = k.period > 0.0f ? vec2(0.0f, k.centre.y - pa.y) : k.centre - pa;
  PAVER_PRECISE float centre_dist = length_2d(to_centre);
  PAVER_PRECISE float g = centre_dist > 0.0f ? s.stretch_sum / float(s.used) / centre_dist : 0.0f;
  PAVER_PRECISE vec2 global_force = vec2(g * to_centre.x, g * to_centre.y);
  PAVER_PRECISE vec2 dp = vec2(k.lambda_r * restoring.x + k.lambda_l * local_force.x + k.lambda_g * global_force.x,
                               k.lambda_r * restoring.y + k.lambda_l * local_force.y + k.lambda_g * global_force.y);
  PAVER_PRECISE vec2 step_vector = vec2(dp.x * k.dt, dp.y * k.dt);
  return step_vector;
}

#ifdef __cplusplus
}  // namespace paver
#endif
#undef PAVER_CONST
#undef PAVER_FN
#undef PAVER_PRECISE
#undef PAVER_ALIGN16
#undef PAVER_IN
#ifndef __cplusplus
#undef uint32_t
#endif
#endif  // PAVER_SOLVER_CONTRACT_H
