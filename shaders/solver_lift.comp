#version 450
// Pass 1 of an iteration, per particle: locate in M^, pull strays back, lift P and kappa
// (eq. 2, 3). Mirrors kernels::lift_particle and CpuSpringSolver::lift_all.
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

layout(push_constant) uniform Push {
  uint count_strays;  // 0 for the closing lift after the last iteration
  uint always;        // 1: run even when the solve is done (initial and closing lifts)
} pc;

vec3 barycentric(vec2 p, vec2 a, vec2 b, vec2 c) {
  precise vec2 v0 = b - a;
  precise vec2 v1 = c - a;
  precise vec2 v2 = p - a;
  precise float det = v0.x * v1.y - v0.y * v1.x;
  precise float w1 = (v2.x * v1.y - v2.y * v1.x) / det;
  precise float w2 = (v0.x * v2.y - v0.y * v2.x) / det;
  precise float w0 = 1.0 - w1 - w2;
  return vec3(w0, w1, w2);
}

vec3 corner_barycentric(int t, vec2 p) {
  return barycentric(p, uv[triangles[3 * t]], uv[triangles[3 * t + 1]], uv[triangles[3 * t + 2]]);
}

int locate(vec2 p, out vec3 bary) {
  bary = vec3(0.0);
  precise float rx = (p.x - P.grid_origin.x) / P.grid_cell_size;
  precise float ry = (p.y - P.grid_origin.y) / P.grid_cell_size;
  if (!(rx >= 0.0 && ry >= 0.0 && rx < float(P.grid_nx) && ry < float(P.grid_ny))) return -1;
  int cell = int(ry) * P.grid_nx + int(rx);
  int best = -1;
  float best_min = -1e-5;
  for (int i = grid_start[cell]; i < grid_start[cell + 1]; ++i) {
    int t = grid_triangles[i];
    vec3 b = corner_barycentric(t, p);
    float lowest = min_f(b.x, min_f(b.y, b.z));
    if (lowest >= 0.0) {
      bary = b;
      return t;
    }
    if (lowest > best_min) {
      best_min = lowest;
      best = t;
      bary = b;
    }
  }
  if (best >= 0) {
    precise vec3 clamped = vec3(max_f(bary.x, 0.0), max_f(bary.y, 0.0), max_f(bary.z, 0.0));
    precise float sum = clamped.x + clamped.y + clamped.z;
    bary = vec3(clamped.x / sum, clamped.y / sum, clamped.z / sum);
  }
  return best;
}

vec2 pull_back(vec2 p, out int segment) {
  segment = 0;
  float best = uintBitsToFloat(0x7f800000u);  // +inf
  vec2 result = p;
  int n = P.boundary_count;
  for (int i = 0; i < n; ++i) {
    vec2 a = boundary_uv[i];
    vec2 b = boundary_uv[i + 1 == n ? 0 : i + 1];
    precise vec2 ab = b - a;
    precise vec2 ap = p - a;
    precise float len2 = ab.x * ab.x + ab.y * ab.y;
    precise float t = len2 > 0.0 ? (ap.x * ab.x + ap.y * ab.y) / len2 : 0.0;
    t = min_f(max_f(t, 0.0), 1.0);
    precise vec2 q = vec2(a.x + t * ab.x, a.y + t * ab.y);
    precise vec2 d = p - q;
    precise float dist2 = d.x * d.x + d.y * d.y;
    if (dist2 < best) {
      best = dist2;
      segment = i;
      vec2 inward = boundary_inward[i];
      precise vec2 nudged = vec2(q.x + 0.01 * (inward.x - q.x), q.y + 0.01 * (inward.y - q.y));
      result = nudged;
    }
  }
  return result;
}

uint next_stray_count(uint count, bool pulled) {
  if (count == kRetired) return kRetired;
  if (!pulled) return count > 0u ? count - 1u : 0u;
  uint next = count + 2u;
  return P.stray_patience != 0u && next >= 2u * P.stray_patience ? kRetired : next;
}

void main() {
  int a = int(gl_GlobalInvocationID.x);
  if (a >= P.particle_count) return;
  if (pc.always == 0u && solver_done()) return;
  vec2 before = position_in[a];
  if (isnan(before.x) || isnan(before.y) || isinf(before.x) || isinf(before.y)) {
    atomicOr(control[4], kErrorNonFinite);
    return;
  }
  vec2 p = before;
  vec3 b = vec3(0.0);
  int t = -1;
  int hint = triangle_hint[a];
  if (hint >= 0) {
    b = corner_barycentric(hint, p);
    if (b.x >= 0.0 && b.y >= 0.0 && b.z >= 0.0) t = hint;
  }
  if (t < 0) t = locate(p, b);
  if (t < 0) {
    int segment;
    p = pull_back(p, segment);
    t = locate(p, b);
    if (t < 0) {
      p = boundary_inward[segment];
      t = locate(p, b);
    }
    if (t < 0) {
      atomicOr(control[4], kErrorNotLifted);
      return;
    }
  }
  triangle_hint[a] = t;
  position_in[a] = p;
  int i = triangles[3 * t], j = triangles[3 * t + 1], k = triangles[3 * t + 2];
  vec4 pi = surface_position[i], pj = surface_position[j], pk = surface_position[k];
  precise vec3 lifted_position = vec3(b.x * pi.x + b.y * pj.x + b.z * pk.x, b.x * pi.y + b.y * pj.y + b.z * pk.y,
                                      b.x * pi.z + b.y * pj.z + b.z * pk.z);
  precise float kappa = b.x * surface_curvature[i] + b.y * surface_curvature[j] + b.z * surface_curvature[k];
  lifted[a] = vec4(lifted_position, kappa);
  if (pc.count_strays == 0u) return;
  bool pulled = p != before;
  pulled_back[a] = pulled ? 1u : 0u;
  stray_count[a] = next_stray_count(stray_count[a], pulled);
  if (pulled) atomicAdd(control[2], 1u);
}
