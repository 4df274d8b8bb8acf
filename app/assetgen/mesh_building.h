#pragma once
// The triangle mesh the generators build, and the steps they share: rows of vertices, the
// "zipper" between two rows, fans around a centre, and orientation towards a given side.
#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <vector>

namespace paver::assetgen {

struct Mesh {
  std::vector<glm::dvec3> v;          // #V positions
  std::vector<std::array<int, 3>> f;  // #F triangles, vertex indices

  int add(glm::dvec3 p) {
    v.push_back(p);
    return static_cast<int>(v.size()) - 1;
  }
};

// A row of vertices with their parameter along the row: t in [0, 1] for an open row (first at
// 0, last at 1), t in [0, 1) for a closed ring. The parameter only breaks ties in stitch().
struct Row {
  std::vector<int> idx;
  std::vector<double> t;
};

// Open row of `segments` + 1 vertices at t = j / segments.
Row make_row(Mesh& m, int segments, const std::function<glm::dvec3(double)>& at);

// Closed ring of n vertices at t = j / n.
Row make_ring(Mesh& m, int n, const std::function<glm::dvec3(double)>& at);

// Triangulates the band between rows a and b ("zipper"): each step adds one triangle and
// advances along the row whose next vertex makes the shorter diagonal, which joins rows of
// different vertex counts without slivers. Winding is (a_i, b_j, b_j+1) / (a_i, b_j, a_i+1);
// orient() fixes the side afterwards, so builders need not track handedness.
void stitch(Mesh& m, const Row& a, const Row& b, bool closed);

// Disk from a centre vertex and closed rings around it, innermost first.
void stitch_rings(Mesh& m, int centre, const std::vector<Row>& rings);

// The side normals should point to, as a direction at a point.
using Outward = std::function<glm::dvec3(glm::dvec3)>;

glm::dvec3 face_normal(const Mesh& m, const std::array<int, 3>& t);  // not normalized
glm::dvec3 centroid(const Mesh& m, const std::array<int, 3>& t);

// Flips every face when most of them point against `outward`.
void orient(Mesh& m, const Outward& outward);

// The mesh without the vertices no face uses (left behind where faces were cut away), renumbered.
Mesh drop_unused_vertices(const Mesh& m);

// Repeats build(h) with the spacing h rescaled so the face count approaches `target`
// (faces scale with 1 / h^2). Deterministic: a fixed number of rounds.
Mesh fit_faces(const std::function<Mesh(double)>& build, double h, int target);

}  // namespace paver::assetgen
