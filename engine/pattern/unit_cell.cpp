#include "pattern/unit_cell.h"

#include "core/input_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <tuple>

namespace paver {
namespace {

// A directed half-edge of the periodic graph leaving vertex `from` of cell (0,0).
struct HalfEdge {
  int to;
  glm::ivec2 offset;
  double angle;
};

// Outgoing half-edges of every cell vertex, sorted counter-clockwise by angle.
std::vector<std::vector<HalfEdge>> outgoing(const UnitCell& cell) {
  std::vector<std::vector<HalfEdge>> out(cell.vertices.size());
  for (const auto& e : cell.edges) {
    if (e.is_virtual) continue;
    const glm::dvec2 d = cell.edge_vector(e);
    out[e.from].push_back({e.to, e.offset, std::atan2(d.y, d.x)});
    out[e.to].push_back({e.from, -e.offset, std::atan2(-d.y, -d.x)});
  }
  for (auto& list : out)
    std::sort(list.begin(), list.end(), [](const HalfEdge& a, const HalfEdge& b) { return a.angle < b.angle; });
  return out;
}

// The face to the left of the half-edge (v, cell) -> (h.to, cell + h.offset), walked
// counter-clockwise: at each corner turn to the next edge clockwise from the way back.
CellFace face_left_of(const std::vector<std::vector<HalfEdge>>& out, int v, glm::ivec2 cell,
                      const HalfEdge& first) {
  CellFace face;
  int cur = v;
  glm::ivec2 cur_cell = cell;
  HalfEdge h = first;
  const size_t limit = 64;
  while (face.size() < limit) {
    face.push_back({cur, cur_cell});
    const int next = h.to;
    const glm::ivec2 next_cell = cur_cell + h.offset;
    const auto& list = out[next];
    // Find the twin (next -> cur) and take the one before it in counter-clockwise order.
    size_t twin = 0;
    for (size_t i = 0; i < list.size(); ++i)
      if (list[i].to == cur && list[i].offset == -h.offset) twin = i;
    const HalfEdge& turn = list[(twin + list.size() - 1) % list.size()];
    cur = next, cur_cell = next_cell, h = turn;
    if (cur == v && cur_cell == cell && h.to == first.to && h.offset == first.offset) return face;
  }
  return {};
}

int find_edge(const UnitCell& cell, int from, int to, glm::ivec2 offset) {
  for (size_t i = 0; i < cell.edges.size(); ++i) {
    const auto& e = cell.edges[i];
    if ((e.from == from && e.to == to && e.offset == offset) ||
        (e.from == to && e.to == from && e.offset == -offset))
      return int(i);
  }
  return -1;
}

std::string describe(int from, int to, glm::ivec2 offset) {
  std::ostringstream s;
  s << from << "->" << to << " @ (" << offset.x << "," << offset.y << ")";
  return s.str();
}

}  // namespace

std::string describe_edge(const CellEdge& e) { return describe(e.from, e.to, e.offset); }

UnitCell make_unit_cell(Tessellation tessellation, double spacing) {
  UnitCell c;
  c.tessellation = tessellation;
  c.spacing = spacing;
  const double d = spacing, h = std::sqrt(3.0) / 2 * spacing;
  switch (tessellation) {
    case Tessellation::Triangle:
      c.a1 = {d, 0}, c.a2 = {d / 2, h};
      c.vertices = {{0, 0}};
      c.edges = {{0, 0, {1, 0}}, {0, 0, {0, 1}}, {0, 0, {-1, 1}}};
      break;
    case Tessellation::Grid:
      c.a1 = {d, 0}, c.a2 = {0, d};
      c.vertices = {{0, 0}};
      c.edges = {{0, 0, {1, 0}}, {0, 0, {0, 1}}};
      break;
    case Tessellation::Hexagon:
      // Honeycomb: lattice vectors sqrt(3) D long, two vertices D apart.
      c.a1 = {2 * h, 0}, c.a2 = {h, 1.5 * d};
      c.vertices = {{0, 0}, {0, d}};
      c.edges = {{0, 1, {0, 0}}, {0, 1, {0, -1}}, {0, 1, {1, -1}}};
      break;
  }
  for (auto& e : c.edges) e.rest_length = glm::length(c.edge_vector(e));
  return c;
}

std::vector<CellFace> cell_faces(const UnitCell& cell) {
  const auto out = outgoing(cell);
  for (const auto& list : out)
    if (list.size() < 2) return {};
  // Each face is found once per translation class: key it by its corners relative to its
  // lexicographically smallest corner.
  std::map<std::vector<std::tuple<int, int, int>>, bool> seen;
  std::vector<CellFace> faces;
  for (int v = 0; v < int(out.size()); ++v) {
    for (const auto& h : out[v]) {
      CellFace face = face_left_of(out, v, {0, 0}, h);
      if (face.size() < 3) continue;
      // Skip the unbounded orientation: a real face has positive area.
      double area = 0;
      for (size_t i = 0; i < face.size(); ++i) {
        const glm::dvec2 a = cell.position(face[i].vertex, face[i].cell);
        const glm::dvec2 b = cell.position(face[(i + 1) % face.size()].vertex, face[(i + 1) % face.size()].cell);
        area += a.x * b.y - a.y * b.x;
      }
      if (area <= 0) continue;
      auto min_corner = *std::min_element(face.begin(), face.end(), [](const auto& a, const auto& b) {
        return std::tie(a.cell.x, a.cell.y, a.vertex) < std::tie(b.cell.x, b.cell.y, b.vertex);
      });
      std::vector<std::tuple<int, int, int>> key;
      for (const auto& c : face) key.emplace_back(c.cell.x - min_corner.cell.x, c.cell.y - min_corner.cell.y, c.vertex);
      std::sort(key.begin(), key.end());
      if (seen.emplace(key, true).second) faces.push_back(std::move(face));
    }
  }
  return faces;
}

void apply_operator(UnitCell& cell, const EdgeOperator& op) {
  const int nv = static_cast<int>(cell.vertices.size());
  const std::string name = std::string(enum_name(op.kind)) + " " + describe(op.from, op.to, op.offset);
  if (op.from < 0 || op.from >= nv || op.to < 0 || op.to >= nv)
    throw InputError(name + ": the unit cell of this tessellation has vertices 0.." + std::to_string(nv - 1));
  const int existing = find_edge(cell, op.from, op.to, op.offset);
  switch (op.kind) {
    case EdgeOperator::Kind::Remove:
      if (existing < 0) throw InputError(name + ": no such edge in the unit cell");
      cell.edges.erase(cell.edges.begin() + existing);
      return;
    case EdgeOperator::Kind::Add: {
      if (existing >= 0) throw InputError(name + ": the edge is already there");
      CellEdge e{op.from, op.to, op.offset, 0, op.is_virtual};
      e.rest_length = glm::length(cell.edge_vector(e));
      if (e.rest_length < 1e-9 * cell.spacing) throw InputError(name + ": joins a vertex to itself");
      cell.edges.push_back(e);
      return;
    }
    case EdgeOperator::Kind::Flip: {
      if (existing < 0) throw InputError(name + ": no such edge in the unit cell");
      if (cell.edges[existing].is_virtual) throw InputError(name + ": virtual edges cannot be flipped");
      const CellEdge e = cell.edges[existing];
      const auto out = outgoing(cell);
      const HalfEdge forward{e.to, e.offset, 0}, backward{e.from, -e.offset, 0};
      const CellFace left = face_left_of(out, e.from, {0, 0}, forward);
      const CellFace right = face_left_of(out, e.to, e.offset, backward);
      if (left.size() < 3 || right.size() < 3)
        throw InputError(name + ": the edge needs a face on both sides to be flipped");
      // In each face, the corner after the edge's end: for two triangles, the opposite corners.
      const CellFaceCorner a = left[2 % left.size()], b = right[2 % right.size()];
      CellEdge flipped{a.vertex, b.vertex, b.cell - a.cell, 0, false};
      flipped.rest_length = glm::length(cell.edge_vector(flipped));
      // Normalise so the edge leaves cell (0,0).
      if (find_edge(cell, flipped.from, flipped.to, flipped.offset) >= 0)
        throw InputError(name + ": the flipped edge " + describe_edge(flipped) + " already exists");
      cell.edges[existing] = flipped;
      return;
    }
  }
}

void add_bracing_edges(UnitCell& cell) {
  for (const CellFace& face : cell_faces(cell)) {
    const int n = static_cast<int>(face.size());
    if (n <= 3) continue;
    // Join each corner to the opposite one (both diagonals of a quad, long diagonals of a hexagon).
    for (int i = 0; i < (n + 1) / 2; ++i) {
      const auto& a = face[i];
      const auto& b = face[(i + n / 2) % n];
      const glm::ivec2 offset = b.cell - a.cell;
      if (find_edge(cell, a.vertex, b.vertex, offset) >= 0) continue;
      CellEdge e{a.vertex, b.vertex, offset, 0, true};
      e.rest_length = glm::length(cell.edge_vector(e));
      cell.edges.push_back(e);
    }
  }
}

}  // namespace paver
