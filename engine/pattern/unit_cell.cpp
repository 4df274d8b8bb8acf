#include "pattern/unit_cell.h"

#include "core/input_error.h"
#include "core/number_text.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <limits>
#include <sstream>
#include <stdexcept>
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

// Twice the signed area of a face (positive counter-clockwise).
double twice_face_area(const UnitCell& cell, const CellFace& face) {
  double twice = 0;
  for (size_t i = 0; i < face.size(); ++i) {
    const glm::dvec2 a = cell.position(face[i].vertex, face[i].cell);
    const glm::dvec2 b = cell.position(face[(i + 1) % face.size()].vertex, face[(i + 1) % face.size()].cell);
    twice += a.x * b.y - a.y * b.x;
  }
  return twice;
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

// The two vertices of the periodic graph nearest each other that no edge joins (virtual edges
// join too: their springs hold): the pair and its distance, within two cells.
struct UnjoinedPair {
  int from = -1, to = -1;
  glm::ivec2 offset{0};
  double distance = std::numeric_limits<double>::infinity();
};

UnjoinedPair nearest_unjoined(const UnitCell& cell) {
  UnjoinedPair nearest;
  const int n = int(cell.vertices.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy) {
          const glm::ivec2 offset(dx, dy);
          if (i == j && offset == glm::ivec2(0)) continue;
          const double d = glm::length(cell.position(j, offset) - cell.position(i, {0, 0}));
          if (d < nearest.distance && find_edge(cell, i, j, offset) < 0) nearest = {i, j, offset, d};
        }
  return nearest;
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
    case Tessellation::Cairo: {
      // The 4-valent vertices make a square grid of side L; in each square a pair of 3-valent
      // vertices D apart, each joined to the two corners on its side, the pairs lying across and
      // along in a checkerboard. Every edge is D when (L - D)^2 + L^2 = 4 D^2: L = (1 + sqrt 7) D / 2.
      const double l = (1 + std::sqrt(7.0)) / 2 * d;
      c.a1 = {2 * l, 0}, c.a2 = {l, l};
      c.vertices = {{0, 0}, {l, 0}, {l / 2 - d / 2, l / 2}, {l / 2 + d / 2, l / 2},
                    {1.5 * l, l / 2 - d / 2}, {1.5 * l, l / 2 + d / 2}};
      c.edges = {{2, 0, {0, 0}}, {2, 1, {-1, 1}}, {3, 1, {0, 0}}, {3, 0, {0, 1}}, {2, 3, {0, 0}},
                 {4, 1, {0, 0}}, {4, 0, {1, 0}}, {5, 0, {0, 1}}, {5, 1, {0, 1}}, {4, 5, {0, 0}}};
      break;
    }
    case Tessellation::Prismatic: {
      // Houses: walls and roof edges D, the base kPrismaticBase D wide (so that eaves and ridges of
      // neighbouring houses, joined by no edge, stay that far apart); the next row upside down, its
      // roofs between them.
      const double b = kPrismaticBase * d, roof = std::sqrt(d * d - b * b / 4);
      c.a1 = {b, 0}, c.a2 = {b / 2, 2 * d + roof};
      c.vertices = {{0, 0}, {0, d}, {b / 2, d + roof}};
      c.edges = {{0, 0, {1, 0}}, {0, 1, {0, 0}}, {1, 2, {0, 0}}, {2, 1, {1, 0}}, {2, 0, {0, 1}}};
      break;
    }
    case Tessellation::Custom:
      throw std::logic_error("make_unit_cell: a drawn cell is made by make_drawn_cell");
  }
  for (auto& e : c.edges) e.rest_length = glm::length(c.edge_vector(e));
  return c;
}

namespace {

// Whether segments p0-p1 and q0-q1 meet anywhere but at an end they share.
bool segments_meet(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 q0, glm::dvec2 q1, double tolerance) {
  const auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
  const auto near = [&](glm::dvec2 a, glm::dvec2 b) { return glm::length(a - b) <= tolerance; };
  // Distance from x to segment a-b.
  const auto distance = [](glm::dvec2 x, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double t = std::clamp(glm::dot(x - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(x - (a + t * ab));
  };
  const int shared = (near(p0, q0) || near(p0, q1)) + (near(p1, q0) || near(p1, q1));
  if (shared == 2) return true;  // the same edge twice
  // An end of one on the other (other than at a shared end): through a vertex, or overlapping.
  for (const auto& [x, a, b] : {std::tuple{p0, q0, q1}, {p1, q0, q1}, {q0, p0, p1}, {q1, p0, p1}})
    if (!near(x, a) && !near(x, b) && distance(x, a, b) <= tolerance) return true;
  if (shared == 1) return false;
  const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
  const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Planar: no two real edges of the cell (of any two cells within `reach`) meet but at a shared end;
// `unit` is the cell at D = 1, `c` the one named in messages.
void refuse_crossing_edges(const UnitCell& unit, const UnitCell& c, int reach, double tolerance) {
  const auto fail = [](const std::string& what) { throw InputError(what); };
  const std::size_t ne = c.edges.size();
  for (std::size_t k = 0; k < ne; ++k) {
    const CellEdge& e = c.edges[k];
    if (e.is_virtual) continue;
    const glm::dvec2 p0 = unit.vertices[std::size_t(e.from)], p1 = unit.position(e.to, e.offset);
    for (std::size_t m = k; m < ne; ++m) {
      const CellEdge& f = c.edges[m];
      if (f.is_virtual) continue;
      for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j) {
          if (m == k && i == 0 && j == 0) continue;
          const glm::dvec2 q0 = unit.position(f.from, {i, j}), q1 = unit.position(f.to, f.offset + glm::ivec2(i, j));
          if (segments_meet(p0, p1, q0, q1, tolerance))
            fail("edges[" + std::to_string(k) + "] " + describe_edge(e) + " and edges[" + std::to_string(m) + "] " +
                 describe_edge(f) + (i || j ? " of the cell (" + std::to_string(i) + "," + std::to_string(j) + ")" : "") +
                 " cross or overlap: a tessellation's edges meet only at their ends");
        }
    }
  }
}

// Connected over the plane: every vertex reached from vertex 0, and the loops' lattice steps reach
// every cell (else the pattern is strips, or copies lying between each other).
void refuse_disconnected(const UnitCell& c) {
  const auto fail = [](const std::string& what) { throw InputError(what); };
  const std::size_t nv = c.vertices.size();
  std::vector<glm::ivec2> step(nv);
  std::vector<std::uint8_t> reached(nv, 0);
  std::vector<int> stack{0};
  reached[0] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (const CellEdge& e : c.edges) {
      if (e.is_virtual) continue;
      if (e.from == v && !reached[std::size_t(e.to)]) step[std::size_t(e.to)] = step[std::size_t(v)] + e.offset;
      else if (e.to == v && !reached[std::size_t(e.from)]) step[std::size_t(e.from)] = step[std::size_t(v)] - e.offset;
      else continue;
      const int w = e.from == v ? e.to : e.from;
      reached[std::size_t(w)] = 1;
      stack.push_back(w);
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (!reached[v]) fail("vertices[" + std::to_string(v) + "] is not joined to vertices[0] by edges: the pattern falls apart");
  std::vector<glm::ivec2> loops;
  for (const CellEdge& e : c.edges)
    if (!e.is_virtual) loops.push_back(step[std::size_t(e.from)] + e.offset - step[std::size_t(e.to)]);
  long index = 0;
  for (std::size_t a = 0; a < loops.size(); ++a)
    for (std::size_t b = a + 1; b < loops.size(); ++b)
      index = std::gcd(index, long(loops[a].x) * loops[b].y - long(loops[a].y) * loops[b].x);
  if (index == 0) fail("the edges do not join the cells both ways: the pattern is strips (add an edge along the other lattice vector)");
  if (index != 1)
    fail("the edges join only one cell in " + std::to_string(index) +
         ": the pattern is copies lying between each other (join them, or use a smaller cell)");
}

}  // namespace

UnitCell make_drawn_cell(const CellDesign& design, double spacing) {
  const auto fail = [](const std::string& what) { throw InputError(what); };
  UnitCell c;
  c.tessellation = Tessellation::Custom;
  c.spacing = spacing;
  c.a1 = design.a1 * spacing, c.a2 = design.a2 * spacing;
  const double area = design.a1.x * design.a2.y - design.a1.y * design.a2.x;
  if (!(std::abs(area) > 1e-6 * glm::length(design.a1) * glm::length(design.a2)))
    fail("a1 and a2 must span the plane (they are parallel or zero)");
  if (area < 0) fail("a1 and a2 must turn counter-clockwise (a2 to the left of a1): swap them");
  const std::size_t nv = design.vertices.size(), ne = design.edges.size();
  if (nv == 0) fail("the cell has no vertex: give vertices as [{\"at\": [x, y]}, ...] in units of D");
  if (nv > kMaxDrawnCellVertices) fail("the cell has " + std::to_string(nv) + " vertices; the most is " +
                                       std::to_string(kMaxDrawnCellVertices));
  if (ne > kMaxDrawnCellEdges)
    fail("the cell has " + std::to_string(ne) + " edges; the most is " + std::to_string(kMaxDrawnCellEdges));
  const double tolerance = 1e-6 * std::sqrt(area);
  // Each vertex is taken into the cell the lattice vectors span (its edges' offsets follow), so that
  // the lattice laid over a map covers it wherever the designer drew it.
  std::vector<glm::ivec2> shift(nv);
  std::vector<glm::dvec2> inside(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const glm::dvec2 at = design.vertices[v].at;
    const std::string name = "vertices[" + std::to_string(v) + "]";
    if (!std::isfinite(at.x) || !std::isfinite(at.y)) fail(name + " is not finite");
    const glm::dvec2 l((at.x * design.a2.y - at.y * design.a2.x) / area, (design.a1.x * at.y - design.a1.y * at.x) / area);
    if (!(std::abs(l.x) < kMaxDrawnCellReach && std::abs(l.y) < kMaxDrawnCellReach))
      fail(name + " is about " + significant_text(std::max(std::abs(l.x), std::abs(l.y))) +
           " cells from the cell's origin: place it within a cell or two of it (the lattice repeats every cell)");
    shift[v] = glm::ivec2(int(std::floor(l.x + 1e-9)), int(std::floor(l.y + 1e-9)));
    inside[v] = at - double(shift[v].x) * design.a1 - double(shift[v].y) * design.a2;
    c.vertices.push_back(inside[v] * spacing);
  }
  // Two vertices at one place, in this cell or a neighbour's.
  const UnitCell unit = [&] {
    UnitCell u = c;
    u.a1 = design.a1, u.a2 = design.a2, u.spacing = 1;
    for (std::size_t v = 0; v < nv; ++v) u.vertices[v] = inside[v];
    return u;
  }();
  constexpr int kReach = kMaxDrawnCellOffset + 3;
  for (std::size_t v = 0; v < nv; ++v)
    for (std::size_t w = v; w < nv; ++w)
      for (int i = -kReach; i <= kReach; ++i)
        for (int j = -kReach; j <= kReach; ++j)
          if ((v != w || i != 0 || j != 0) &&
              glm::length(unit.position(int(w), {i, j}) - unit.vertices[v]) <= tolerance)
            fail("vertices[" + std::to_string(v) + "] and vertices[" + std::to_string(w) + "]" +
                 (i || j ? " of the cell (" + std::to_string(i) + "," + std::to_string(j) + ")" : "") +
                 " are at one place");
  std::vector<int> degree(nv, 0);
  for (std::size_t k = 0; k < ne; ++k) {
    const CellEdgeDesign& e = design.edges[k];
    const std::string name = "edges[" + std::to_string(k) + "] " + describe(e.from, e.to, e.offset);
    if (e.from < 0 || e.from >= int(nv) || e.to < 0 || e.to >= int(nv))
      fail(name + ": the cell has vertices 0.." + std::to_string(nv - 1));
    if (std::abs(e.offset.x) > kMaxDrawnCellOffset || std::abs(e.offset.y) > kMaxDrawnCellOffset)
      fail(name + ": an edge reaches at most " + std::to_string(kMaxDrawnCellOffset) + " cells away");
    const glm::ivec2 offset = e.offset + shift[std::size_t(e.to)] - shift[std::size_t(e.from)];
    if (std::abs(offset.x) > kReach - 1 || std::abs(offset.y) > kReach - 1)
      fail(name + ": its ends lie " + std::to_string(std::max(std::abs(offset.x), std::abs(offset.y))) +
           " cells apart; an edge joins vertices at most " + std::to_string(kReach - 1) + " cells apart");
    if (find_edge(c, e.from, e.to, offset) >= 0) fail(name + ": the edge is given twice");
    CellEdge edge{e.from, e.to, offset, 0, e.is_virtual};
    edge.rest_length = glm::length(c.edge_vector(edge));
    if (!(edge.rest_length > tolerance * spacing)) fail(name + ": joins a vertex to itself");
    c.edges.push_back(edge);
    if (!e.is_virtual) ++degree[std::size_t(e.from)], ++degree[std::size_t(e.to)];
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (degree[v] < 2)
      fail("vertices[" + std::to_string(v) + "] is on " + std::to_string(degree[v]) +
           " edge(s); every vertex of a tessellation is on two or more (add edges, or remove the vertex)");
  refuse_crossing_edges(unit, c, 2 * kReach, tolerance);
  refuse_disconnected(c);
  double faces_area = 0;
  for (const CellFace& face : cell_faces(c)) faces_area += 0.5 * twice_face_area(c, face);
  if (!(std::abs(faces_area - c.cell_area()) <= 1e-6 * c.cell_area()))
    fail("the edges do not close into faces that tile the cell (a face of more than 64 corners, or edges "
         "that leave a face open): add edges");
  return c;
}

double smallest_edge_angle(const UnitCell& cell) {
  double smallest = std::numbers::pi;
  for (const auto& list : outgoing(cell))
    for (std::size_t i = 0; i < list.size(); ++i) {
      double turn = list[(i + 1) % list.size()].angle - list[i].angle;
      if (list.size() == 1) turn = 2 * std::numbers::pi;
      if (turn <= 0) turn += 2 * std::numbers::pi;
      smallest = std::min(smallest, turn);
    }
  return smallest;
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
      if (twice_face_area(cell, face) <= 0) continue;
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

glm::dvec2 face_centre(const UnitCell& cell, const CellFace& face, glm::ivec2 offset) {
  glm::dvec2 sum(0);
  for (const CellFaceCorner& corner : face) sum += cell.position(corner.vertex, corner.cell + offset);
  return sum / double(face.size());
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
      // A flip turns every translate of the edge at once. Where that leaves two vertices nearer
      // than the new edge and joined by nothing, the lattice is sheared, not re-connected: its
      // springs press those stones together (a flipped square grid lost 154 stones of 500 on the
      // dome). Said here, with the way that works, instead of a degenerate pattern.
      UnitCell flipped_cell = cell;
      flipped_cell.edges[existing] = flipped;
      const UnjoinedPair near = nearest_unjoined(flipped_cell);
      if (near.distance < flipped.rest_length * (1 - 1e-9)) {
        std::ostringstream why;
        why.precision(3);
        why << name << ": a flip here shears the whole lattice: the new edge " << describe_edge(flipped) << " is "
            << flipped.rest_length / cell.spacing << " D long, while vertices " << describe(near.from, near.to, near.offset)
            << " are " << near.distance / cell.spacing
            << " D apart with no edge between them, so the springs would press their stones together. A flip turns "
               "the shared edge of two triangles into the other diagonal (add a square's diagonal, then flip it); "
               "to change the pattern otherwise, remove and add edges";
        throw InputError(why.str());
      }
      cell.edges[existing] = flipped;
      return;
    }
  }
}

void add_bracing_edges(UnitCell& cell) {
  for (const CellFace& face : cell_faces(cell)) {
    const int n = static_cast<int>(face.size());
    if (n <= 3) continue;
    // Join each corner to the opposite one (both diagonals of a quad, long diagonals of a hexagon);
    // a pentagon gets all five, so that no two corners come nearer than the design has them (a
    // prismatic house's eaves are joined by nothing else).
    for (int i = 0; i < (n == 5 ? 5 : (n + 1) / 2); ++i) {
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
