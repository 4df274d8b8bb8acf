// Repairs, each reported in LoadedSurface::warnings: degenerate faces are dropped, polygons are
// triangulated, unreferenced vertices are dropped, faces are reoriented consistently; vertices at
// one position are joined where the file left faces apart, never where that would make a bowtie or
// an edge of more than two faces (a good scan with two vertices at one point stays as it is), and
// a bowtie vertex of the file's own is split, one copy per fan.
// Several connected components: we KEEP THE LARGEST (by face count) and drop the others with a
// warning. Stray specks and leftover fragments are common in scans and exports, and refusing the
// whole file for them would be unhelpful; the warning says how much was dropped, so a user with
// two real pieces notices. Pieces that touched at a single vertex are two once it is split. The
// manifold, orientation and boundary checks look at the kept component only.
// Everything else (non-manifold edges, non-orientable, handles) is an InputError
// that names the file, the place and the fix.
#include "mesh/mesh_repair.h"
#include "core/edge_key.h"

#include "mesh/mesh_messages.h"
#include "mesh/polygon_triangulation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <tuple>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace paver {
namespace {

using namespace mesh_detail;

class DisjointSets {
public:
  explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<int> parent_;
};

// One side of a triangle: corner c runs from t[c] to t[(c + 1) % 3].
struct Side {
  std::uint64_t key;  // the undirected edge: (min vertex << 32) | max vertex
  int triangle;
  int corner;
};

int corner_of(const glm::ivec3& t, int vertex) { return t.x == vertex ? 0 : t.y == vertex ? 1 : 2; }

std::string edge_between(int a, int b, const std::vector<glm::dvec3>& positions) {
  return "the edge between vertices " + std::to_string(a) + " and " + std::to_string(b) + " (counting from 0) at " +
         format_point(positions[a]) + " - " + format_point(positions[b]);
}

// The triangles' sides grouped by undirected edge (sorting, not hashing: faster at this size).
struct Edges {
  std::vector<Side> sides;                        // sorted by key
  std::vector<std::pair<size_t, size_t>> ranges;  // per edge, its [begin, end) in `sides`
};

Edges collect_edges(const std::vector<glm::ivec3>& triangles) {
  Edges edges;
  edges.sides.reserve(triangles.size() * 3);
  for (int f = 0; f < int(triangles.size()); ++f)
    for (int c = 0; c < 3; ++c) edges.sides.push_back({edge_key(triangles[f][c], triangles[f][(c + 1) % 3]), f, c});
  std::sort(edges.sides.begin(), edges.sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.triangle != b.triangle ? a.triangle < b.triangle : a.corner < b.corner;
  });
  edges.ranges.reserve(edges.sides.size() / 2 + 1);
  for (size_t begin = 0; begin < edges.sides.size();) {
    size_t end = begin + 1;
    while (end < edges.sides.size() && edges.sides[end].key == edges.sides[begin].key) ++end;
    edges.ranges.emplace_back(begin, end);
    begin = end;
  }
  return edges;
}

// Where each face's sides lead: the face across side c of face f, and whether that face runs the
// shared edge in the same direction (an orientation conflict).
struct Adjacency {
  std::vector<int> neighbour;         // #F*3, -1 on the boundary
  std::vector<char> same_direction;   // #F*3
};

Adjacency face_adjacency(const std::vector<glm::ivec3>& triangles, const Edges& edges) {
  Adjacency adjacency{std::vector<int>(triangles.size() * 3, -1), std::vector<char>(triangles.size() * 3, 0)};
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 2) continue;
    const Side& s = edges.sides[begin];
    const Side& r = edges.sides[begin + 1];
    const bool same = triangles[r.triangle][r.corner] == triangles[s.triangle][s.corner];
    adjacency.neighbour[s.triangle * 3 + s.corner] = r.triangle;
    adjacency.neighbour[r.triangle * 3 + r.corner] = s.triangle;
    adjacency.same_direction[s.triangle * 3 + s.corner] = adjacency.same_direction[r.triangle * 3 + r.corner] = same;
  }
  return adjacency;
}

// `polygons` must index `positions`, and every position be finite: otherwise nothing else is
// meaningful.
void check_indices_and_coordinates(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::vector<int>>& polygons, const std::string& source) {
  const long long vertex_count = static_cast<long long>(positions.size());
  for (size_t f = 0; f < polygons.size(); ++f)
    for (int index : polygons[f])
      if (index < 0 || index >= vertex_count)
        fail(source, "face " + std::to_string(f) + " (counting from 0) refers to vertex " + std::to_string(index) +
                         " but there are only " + count_of(vertex_count, "vertex", "vertices") +
                         "; the file is corrupt: export it again");
  int nonfinite = 0, first_nonfinite = -1;
  for (size_t v = 0; v < positions.size(); ++v) {
    const glm::dvec3& p = positions[v];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
    if (nonfinite++ == 0) first_nonfinite = int(v);
  }
  if (nonfinite > 0)
    fail(source, "vertex " + std::to_string(first_nonfinite) + " (counting from 0) has a non-finite coordinate " +
                     format_point(positions[first_nonfinite]) + "; " +
                     count_of(nonfinite, "vertex has", "vertices have") +
                     " NaN or infinite coordinates: fix them in the modelling tool and export again");
}

struct Components {
  int count = 0;
  long long dropped_faces = 0;
};

// For every vertex a face uses, the first such vertex with exactly its position (0 and -0 alike, as
// the STL reader's Welder joins corners): the vertex itself when it is the first. A vertex no face
// uses is its own, and never another's: it must not become a fan's vertex unannounced.
std::vector<int> first_at_same_position(const std::vector<glm::dvec3>& positions, const std::vector<char>& used) {
  std::vector<int> order;
  for (int v = 0; v < int(positions.size()); ++v)
    if (used[std::size_t(v)]) order.push_back(v);
  const auto key = [&](int i) { return std::tie(positions[i].x, positions[i].y, positions[i].z); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  std::vector<int> first(positions.size());
  std::iota(first.begin(), first.end(), 0);
  for (std::size_t k = 0; k < order.size(); ++k)
    first[order[k]] = k > 0 && key(order[k]) == key(order[k - 1]) ? first[order[k - 1]] : order[k];
  return first;
}

// How the file's own vertices became the surface's: joined where the file left faces apart at one
// position, kept apart where joining them would make an edge of more than two faces or a vertex
// where fans of faces meet at a point, and split (one copy per fan) where the file's own vertex is
// such a point (a bowtie).
struct Welding {
  long long joined = 0;     // file vertices that became another's
  long long split = 0;      // file vertices that needed copies, one per fan but the first
  int collapsed_faces = 0;  // faces whose corners all lay at one point (left out of the triangles)
};

// The vertex of every triangle corner: `file_triangles` (the file's own vertex numbers) joined by
// position, then parted again where joining broke the surface (see Welding). Split copies are
// appended to `positions`; faces whose corners join are removed from `file_triangles`.
Welding weld(std::vector<glm::dvec3>& positions, std::vector<glm::ivec3>& file_triangles,
             std::vector<glm::ivec3>& triangles) {
  std::vector<char> file_used(positions.size(), 0);
  for (const glm::ivec3& t : file_triangles) file_used[t.x] = file_used[t.y] = file_used[t.z] = 1;
  const std::vector<int> first = first_at_same_position(positions, file_used);
  Welding welding;
  // Two corners at one position give a face of no area, which the triangulation left out; three
  // at one point pass its relative test (no edge to measure by), so they are left out here.
  welding.collapsed_faces = int(std::erase_if(file_triangles, [&](const glm::ivec3& t) {
    return first[t.x] == first[t.y] || first[t.y] == first[t.z] || first[t.x] == first[t.z];
  }));
  triangles = file_triangles;
  for (glm::ivec3& t : triangles)
    for (int c = 0; c < 3; ++c) t[c] = first[t[c]];
  // An edge of more than two faces made by joining is undone at both ends, repeatedly (each round
  // parts at least one join, so this ends).
  std::vector<char> parted(positions.size(), 0);
  for (bool changed = true; changed;) {
    changed = false;
    const Edges edges = collect_edges(triangles);
    for (const auto& [begin, end] : edges.ranges) {
      if (end - begin <= 2) continue;
      for (std::size_t k = begin; k < end; ++k) {
        const Side& side = edges.sides[k];
        for (int c : {side.corner, (side.corner + 1) % 3}) {
          const int file_vertex = file_triangles[side.triangle][c];
          if (triangles[side.triangle][c] == file_vertex) continue;
          parted[first[file_vertex]] = 1;
        }
      }
    }
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (int c = 0; c < 3; ++c)
        if (parted[triangles[f][c]] && triangles[f][c] != file_triangles[f][c]) {
          triangles[f][c] = file_triangles[f][c];
          changed = true;
        }
  }

  // Fans: corners of one vertex joined across the edges of exactly two faces. A vertex on an edge of
  // more than two faces is left alone: that edge is refused later, by name.
  const Edges edges = collect_edges(triangles);
  DisjointSets corners(triangles.size() * 3);
  std::vector<char> on_bad_edge(positions.size(), 0);
  for (const auto& [begin, end] : edges.ranges) {
    const Side& s = edges.sides[begin];
    if (end - begin > 2) {
      on_bad_edge[triangles[s.triangle][s.corner]] = on_bad_edge[triangles[s.triangle][(s.corner + 1) % 3]] = 1;
      continue;
    }
    if (end - begin != 2) continue;
    const Side& r = edges.sides[begin + 1];
    const glm::ivec3& ts = triangles[s.triangle];
    const glm::ivec3& tr = triangles[r.triangle];
    for (int vertex : {ts[s.corner], ts[(s.corner + 1) % 3]})
      corners.unite(s.triangle * 3 + corner_of(ts, vertex), r.triangle * 3 + corner_of(tr, vertex));
  }
  // Each fan after a vertex's first takes a file vertex of its own where one of its corners had
  // one that no fan took yet (a join undone), else a copy (a bowtie of the file's, split).
  const std::size_t file_vertex_count = positions.size();
  std::vector<int> fan_vertex(triangles.size() * 3, -1);  // per fan root
  std::vector<char> taken(file_vertex_count, 0);
  std::vector<char> copied(file_vertex_count, 0);
  std::vector<int> fan_roots;
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner)
    if (corners.find(corner) == corner) fan_roots.push_back(corner);
  // First pass: the fan of a corner that kept its vertex number holds that vertex.
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner) {
    const int vertex = triangles[corner / 3][corner % 3];
    const int root = corners.find(corner);
    if (fan_vertex[root] < 0 && !taken[vertex] && vertex == file_triangles[corner / 3][corner % 3]) {
      fan_vertex[root] = vertex;
      taken[vertex] = 1;
    }
  }
  // Second: a fan of joined corners takes one of their own file vertices still free, else (in the
  // order of the fans) the joined vertex when free, else a copy.
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner) {
    const int root = corners.find(corner);
    if (fan_vertex[root] >= 0) continue;
    const int own = file_triangles[corner / 3][corner % 3];
    if (!taken[own] && !on_bad_edge[triangles[corner / 3][corner % 3]]) {
      fan_vertex[root] = own;
      taken[own] = 1;
    }
  }
  for (int root : fan_roots) {
    if (fan_vertex[root] >= 0) continue;
    const int vertex = triangles[root / 3][root % 3];
    if ((!taken[vertex] && file_used[std::size_t(vertex)]) || on_bad_edge[vertex]) {
      fan_vertex[root] = vertex;
      taken[vertex] = 1;
      continue;
    }
    fan_vertex[root] = int(positions.size());
    positions.push_back(positions[vertex]);
    if (!copied[vertex]) ++welding.split;
    copied[vertex] = 1;
  }
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner)
    triangles[corner / 3][corner % 3] = fan_vertex[corners.find(corner)];
  // Joins: the file's vertices its kept faces use that no corner has any more.
  std::fill(file_used.begin(), file_used.end(), 0);
  for (const glm::ivec3& t : file_triangles) file_used[t.x] = file_used[t.y] = file_used[t.z] = 1;
  std::vector<char> used(positions.size(), 0);
  for (const glm::ivec3& t : triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  for (std::size_t v = 0; v < file_vertex_count; ++v) welding.joined += file_used[v] && !used[v];
  return welding;
}

// Keeps the triangles of the largest component (through shared vertices; see the top comment).
Components keep_largest_component(std::vector<glm::ivec3>& triangles, size_t vertex_count) {
  DisjointSets sets(vertex_count);
  for (const glm::ivec3& t : triangles) {
    sets.unite(t.x, t.y);
    sets.unite(t.x, t.z);
  }
  std::vector<int> faces(vertex_count, 0);  // per root
  for (const glm::ivec3& t : triangles) ++faces[sets.find(t.x)];
  Components components;
  int largest = -1;
  for (size_t root = 0; root < vertex_count; ++root) {
    if (faces[root] == 0) continue;
    ++components.count;
    if (largest < 0 || faces[root] > faces[largest]) largest = int(root);
  }
  if (components.count > 1) {
    const size_t before = triangles.size();
    std::erase_if(triangles, [&](const glm::ivec3& t) { return sets.find(t.x) != largest; });
    components.dropped_faces = static_cast<long long>(before - triangles.size());
  }
  return components;
}

// Every edge on at most 2 faces, and the faces around every vertex one fan.
void check_manifold(const std::vector<glm::ivec3>& triangles, const Edges& edges,
                    const std::vector<glm::dvec3>& positions, const std::string& source, const std::string& note) {
  int bad_edges = 0;
  size_t example_edge = 0;
  for (size_t e = 0; e < edges.ranges.size(); ++e) {
    if (edges.ranges[e].second - edges.ranges[e].first <= 2) continue;
    if (bad_edges++ == 0) example_edge = e;
  }
  if (bad_edges > 0) {
    const auto [begin, end] = edges.ranges[example_edge];
    const Side& side = edges.sides[begin];
    const glm::ivec3& t = triangles[side.triangle];
    fail(source, "has " + count_of(bad_edges, "non-manifold edge", "non-manifold edges") +
                     " (shared by more than 2 faces), e.g. " +
                     edge_between(t[side.corner], t[(side.corner + 1) % 3], positions) + ", shared by " +
                     std::to_string(end - begin) +
                     " faces; Paver needs a manifold surface: remove the extra (duplicated or fin) faces" + note);
  }

  // Corners of the same vertex joined across shared edges form that vertex's fans.
  DisjointSets corners(triangles.size() * 3);
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 2) continue;
    const Side& s = edges.sides[begin];
    const Side& r = edges.sides[begin + 1];
    const glm::ivec3& ts = triangles[s.triangle];
    const glm::ivec3& tr = triangles[r.triangle];
    for (int vertex : {ts[s.corner], ts[(s.corner + 1) % 3]})
      corners.unite(s.triangle * 3 + corner_of(ts, vertex), r.triangle * 3 + corner_of(tr, vertex));
  }
  std::vector<int> fans(positions.size(), 0);
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner)
    if (corners.find(corner) == corner) ++fans[triangles[corner / 3][corner % 3]];
  int bad_vertices = 0, example_vertex = -1;
  for (size_t v = 0; v < fans.size(); ++v) {
    if (fans[v] <= 1) continue;
    if (bad_vertices++ == 0) example_vertex = int(v);
  }
  if (bad_vertices > 0)
    fail(source, "has " + count_of(bad_vertices, "non-manifold vertex", "non-manifold vertices") + ", e.g. vertex " +
                     std::to_string(example_vertex) + " (counting from 0) at " +
                     format_point(positions[example_vertex]) + ", where " + std::to_string(fans[example_vertex]) +
                     " separate fans of faces meet at a single point (like two cones touching at their tips, or a "
                     "bowtie); Paver needs a manifold surface: pull the pieces apart or split the vertex" +
                     note);
}

// Flips faces so that neighbours run their shared edge in opposite directions, keeping the
// orientation most faces already have. Returns how many faces were flipped.
long long orient_consistently(std::vector<glm::ivec3>& triangles, const Edges& edges,
                              const std::vector<glm::dvec3>& positions, const std::string& source,
                              const std::string& note) {
  const Adjacency adjacency = face_adjacency(triangles, edges);
  const int face_count = int(triangles.size());
  std::vector<signed char> flip(size_t(face_count), -1);  // -1: not reached yet
  std::vector<int> queue;
  queue.reserve(size_t(face_count));
  for (int seed = 0; seed < face_count; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    queue.assign(1, seed);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int c = 0; c < 3; ++c) {
        const int g = adjacency.neighbour[f * 3 + c];
        if (g < 0) continue;
        const signed char wanted = static_cast<signed char>(flip[f] ^ adjacency.same_direction[f * 3 + c]);
        if (flip[g] < 0) {
          flip[g] = wanted;
          queue.push_back(g);
        } else if (flip[g] != wanted) {
          fail(source, "is not orientable (like a Moebius strip): its faces cannot be oriented consistently, as "
                       "seen at " +
                           edge_between(triangles[f][c], triangles[f][(c + 1) % 3], positions) +
                           "; Paver needs a two-sided surface" + note);
        }
      }
    }
  }
  long long flipped = std::count(flip.begin(), flip.end(), 1);
  const bool invert = 2 * flipped > face_count;
  if (invert) flipped = face_count - flipped;
  for (int f = 0; f < face_count; ++f)
    if ((flip[f] == 1) != invert) std::swap(triangles[f].y, triangles[f].z);
  return flipped;
}

// The boundary loops of consistently oriented, manifold triangles, each following the direction
// of its sides and starting at its lowest vertex; the longest (in 3D) first, then by first vertex.
std::vector<std::vector<int>> boundary_loops(const std::vector<glm::ivec3>& triangles, const Edges& edges,
                                             const std::vector<glm::dvec3>& positions) {
  const size_t vertex_count = positions.size();
  std::vector<int> next(vertex_count, -1);
  bool any = false;
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 1) continue;
    // The face may have been flipped since `edges` was collected: read the direction off the face.
    const glm::ivec3& t = triangles[edges.sides[begin].triangle];
    int c = 0;
    while (edge_key(t[c], t[(c + 1) % 3]) != edges.sides[begin].key) ++c;
    next[t[c]] = t[(c + 1) % 3];
    any = true;
  }
  if (!any) return {};  // a closed surface: the map stage cuts it into charts
  std::vector<char> visited(vertex_count, 0);
  std::vector<std::vector<int>> loops;
  for (int start = 0; start < int(vertex_count); ++start) {
    if (next[start] < 0 || visited[start]) continue;
    std::vector<int>& loop = loops.emplace_back();
    for (int v = start; v >= 0 && !visited[v]; v = next[v]) {
      visited[v] = 1;
      loop.push_back(v);
    }
  }
  std::vector<double> length(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) length[l] = loop_length(positions, loops[l]);
  std::vector<size_t> order(loops.size());
  for (size_t l = 0; l < order.size(); ++l) order[l] = l;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return length[a] > length[b]; });
  std::vector<std::vector<int>> sorted;
  for (size_t l : order) sorted.push_back(std::move(loops[l]));
  return sorted;
}

}  // namespace

LoadedSurface check_and_repair(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& given_polygons,
                               const std::string& source, int collapsed_faces, VertexRepair repair) {
  LoadedSurface loaded;
  if (given_polygons.empty() && collapsed_faces == 0)
    fail(source, "contains no faces (" + count_of(static_cast<long long>(positions.size()), "vertex", "vertices") +
                     "); Paver needs a surface, not a point cloud: export the faces too");
  check_indices_and_coordinates(positions, given_polygons, source);
  // Corners at exactly the same position are one vertex, whatever the format (STL's reader did
  // this alone): an OBJ or PLY exported with every face's corners apart paved one triangle of 800,
  // the "largest component", with the verdict ok. But only where joining mends the surface: a good
  // scan with two vertices at one position must not become a bowtie of our making.
  Triangulation triangulation = triangulate(positions, given_polygons, degenerate_area(positions, given_polygons));
  const std::size_t file_vertex_count = positions.size();
  std::vector<glm::ivec3> triangles;
  Welding welding;
  if (repair == VertexRepair::JoinAndSplit) welding = weld(positions, triangulation.triangles, triangles);
  else triangles = triangulation.triangles;
  loaded.dropped_degenerate_faces = triangulation.degenerate + welding.collapsed_faces + collapsed_faces;
  const std::string degenerate = count_of(loaded.dropped_degenerate_faces, "degenerate face", "degenerate faces");
  if (triangles.empty())
    fail(source,
         "contains no faces after dropping " + degenerate + " (zero area or repeated vertices); check the export");
  if (welding.joined > 0)
    loaded.warnings.push_back(source + ": joined " + count_of(welding.joined, "vertex", "vertices") +
                              " at exactly the position of another (faces exported apart)");
  if (welding.split > 0)
    loaded.warnings.push_back(source + ": split " + count_of(welding.split, "vertex", "vertices") +
                              " where separate fans of faces met at one point (a bowtie), one copy per fan");
  if (loaded.dropped_degenerate_faces > 0)
    loaded.warnings.push_back(source + ": dropped " + degenerate + " (zero area or repeated vertices)");

  std::vector<char> file_used(file_vertex_count, 0);
  for (const glm::ivec3& t : triangulation.triangles) file_used[t.x] = file_used[t.y] = file_used[t.z] = 1;
  const long long unreferenced = std::count(file_used.begin(), file_used.end(), 0);
  if (unreferenced > 0)
    loaded.warnings.push_back(source + ": dropped " +
                              count_of(unreferenced, "unreferenced vertex", "unreferenced vertices") +
                              " (not used by any face)");

  const Components components = keep_largest_component(triangles, positions.size());
  std::string note;  // appended to topology errors when other components were dropped
  if (components.count > 1) {
    loaded.dropped_components = components.count - 1;
    loaded.warnings.push_back(source + ": the surface has " + std::to_string(components.count) +
                              " connected components; kept the largest (" +
                              count_of(static_cast<long long>(triangles.size()), "face", "faces") +
                              ") and dropped the other " + std::to_string(components.count - 1) + " (" +
                              count_of(components.dropped_faces, "face", "faces") + ")");
    note = " (in its largest connected component, the one Paver keeps; the file has " +
           std::to_string(components.count) + ")";
  }
  // A topology error after faces were dropped may be caused by the dropping: say so.
  if (loaded.dropped_degenerate_faces > 0)
    note += " (after dropping " + degenerate + " of zero area or with repeated vertices, which may have opened it)";

  const Edges edges = collect_edges(triangles);
  check_manifold(triangles, edges, positions, source, note);
  const long long flipped = orient_consistently(triangles, edges, positions, source, note);
  if (flipped > 0)
    loaded.warnings.push_back(source + ": reoriented " + count_of(flipped, "face", "faces") +
                              " to match their neighbours");
  const std::vector<std::vector<int>> loops = boundary_loops(triangles, edges, positions);

  // Compact the vertices to those the kept faces use.
  std::vector<char> used(positions.size(), 0);
  for (const glm::ivec3& t : triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  std::vector<int> new_index(positions.size(), -1);
  SurfaceMesh& mesh = loaded.mesh;
  for (size_t v = 0; v < positions.size(); ++v)
    if (used[v]) {
      new_index[v] = int(mesh.positions.size());
      mesh.positions.push_back(positions[v]);
    }

  // A connected, orientable surface of genus g with L boundary loops has V - E + F = 2 - 2g - L.
  const long long euler = static_cast<long long>(mesh.positions.size()) -
                          static_cast<long long>(edges.ranges.size()) + static_cast<long long>(triangles.size());
  const long long loop_count = static_cast<long long>(loops.size());
  const long long handles = (2 - loop_count - euler) / 2;
  // A closed surface with handles (a solid ring) is cut into charts without them by the map stage.
  if (handles != 0 && loop_count > 0)
    fail(source, "has " + count_of(handles, "handle", "handles") + " (V - E + F = " + std::to_string(euler) + " with " +
                     count_of(loop_count, "boundary loop", "boundary loops") + "; a surface without handles has " +
                     std::to_string(2 - loop_count) +
                     "); Paver paves an open surface without handles (a disk, a band, a surface with holes) or a "
                     "closed one (a bead, a solid ring): cut through the handles or fill them" +
                     note);

  mesh.triangles.reserve(triangles.size());
  for (const glm::ivec3& t : triangles) mesh.triangles.emplace_back(new_index[t.x], new_index[t.y], new_index[t.z]);
  for (const std::vector<int>& loop : loops) {
    std::vector<int>& kept = mesh.boundary_loops.emplace_back();
    kept.reserve(loop.size());
    for (int v : loop) kept.push_back(new_index[v]);
  }
  return loaded;
}


}  // namespace paver
