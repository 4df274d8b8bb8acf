#include "elements/element_shape.h"
#include "design/design_keys.h"

#include "core/input_error.h"
#include "mesh/read_mesh_file.h"

#include <glm/geometric.hpp>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

namespace paver {
namespace {

constexpr double kRadius = 0.5;  // every built-in shape is 1 wide

class ShapeBuilder {
public:
  int vertex(double x, double y, double z) {
    mesh_.positions.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
    return static_cast<int>(mesh_.positions.size()) - 1;
  }
  int polar(double radius, double angle, double z) {
    return vertex(radius * std::cos(angle), radius * std::sin(angle), z);
  }
  // a, b, c counter-clockwise seen from outside.
  void triangle(int a, int b, int c) { mesh_.triangles.emplace_back(a, b, c); }

  ShapeMesh take() { return std::move(mesh_); }

private:
  ShapeMesh mesh_;
};

double segment_angle(int j, int segments) {
  return 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(segments);
}

// Surface of revolution about Z. `profile` is (radius, z) from the top to the bottom; its first and
// last radii are 0 (a pole, or the centre of a flat cap), the ones in between are rings of
// `segments` vertices, the first at angle 0 so that the shape reaches x = +-radius exactly.
ShapeMesh revolve(const std::vector<glm::dvec2>& profile, int segments) {
  ShapeBuilder b;
  const int top = b.vertex(0, 0, profile.front().y);
  const int ring_count = static_cast<int>(profile.size()) - 2;
  const int first_ring = top + 1;
  for (int i = 0; i < ring_count; ++i)
    for (int j = 0; j < segments; ++j)
      b.polar(profile[i + 1].x, segment_angle(j, segments), profile[i + 1].y);
  const int bottom = b.vertex(0, 0, profile.back().y);

  const auto ring = [&](int i, int j) { return first_ring + i * segments + j % segments; };
  for (int j = 0; j < segments; ++j) {
    b.triangle(top, ring(0, j), ring(0, j + 1));
    // Down the profile (i -> i + 1) then around (j -> j + 1) turns outwards.
    for (int i = 0; i + 1 < ring_count; ++i) {
      b.triangle(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      b.triangle(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
    b.triangle(bottom, ring(ring_count - 1, j + 1), ring(ring_count - 1, j));
  }
  return b.take();
}

// `rings` even, so that the equator (the widest circle) is a ring.
ShapeMesh make_sphere(int segments, int rings) {
  std::vector<glm::dvec2> profile;
  for (int i = 0; i <= rings; ++i) {
    const double polar_angle = std::numbers::pi * i / rings;
    const bool pole = i == 0 || i == rings;
    profile.emplace_back(pole ? 0.0 : kRadius * std::sin(polar_angle), kRadius * std::cos(polar_angle));
  }
  return revolve(profile, segments);
}

ShapeMesh make_prism(int segments, double height) {
  const double h = 0.5 * height;
  return revolve({{0, h}, {kRadius, h}, {kRadius, -h}, {0, -h}}, segments);
}

// The brilliant's outline for drawing tens of thousands: its table, its crown down to the girdle
// and its pavilion down to the culet, over 8 sides, at the brilliant's own heights.
ShapeMesh make_gem_outline() {
  return revolve({{0, kGemGirdleHalf + kGemCrownHeight},
                  {kGemTableRadius, kGemGirdleHalf + kGemCrownHeight},
                  {kRadius, 0},
                  {0, -kGemGirdleHalf - kGemPavilionDepth}},
                 8);
}

// Round brilliant with 8-fold symmetry: octagonal table, 8 star, 8 bezel (kite) and 16 upper
// girdle facets on the crown; a 16-sided girdle band; 16 lower girdle and 8 main facets on the
// pavilion down to a pointed culet. Proportions are those of a typical brilliant in units of the
// girdle diameter. Bezel and pavilion main facets are kept planar: their side vertices are put on
// the plane through the facet's top and bottom vertices and the girdle tangent there.
ShapeMesh make_gem() {
  constexpr double kTableRadius = kGemTableRadius;
  constexpr double kCrownHeight = kGemCrownHeight;
  constexpr double kPavilionDepth = kGemPavilionDepth;
  constexpr double kGirdleHalf = kGemGirdleHalf;
  constexpr double kStarLength = 0.5;        // star tips halfway from the table edge to the girdle
  constexpr double kLowerGirdleLength = 0.77;  // lower girdle facets reach 77% towards the culet
  constexpr int kMains = 8;
  constexpr int kGirdle = 2 * kMains;
  const double half_step = std::numbers::pi / kMains / 2;  // 22.5 degrees
  const double cos_half = std::cos(half_step);

  const double table_z = kGirdleHalf + kCrownHeight;
  const double culet_z = -kGirdleHalf - kPavilionDepth;
  // Height of the bezel plane at distance `along` from the axis in the direction of its main.
  const auto bezel_z = [&](double along) {
    return kGirdleHalf + kCrownHeight * (kRadius - along) / (kRadius - kTableRadius);
  };
  const auto pavilion_z = [&](double along) { return culet_z + kPavilionDepth * along / kRadius; };

  const double table_edge = kTableRadius * cos_half;  // distance of a table edge's middle
  const double star_radius = table_edge + kStarLength * (kRadius - table_edge);
  const double lower_along = kRadius * (1 - kLowerGirdleLength);

  ShapeBuilder b;
  const int table_centre = b.vertex(0, 0, table_z);
  std::array<int, kMains> table, star, lower;
  std::array<int, kGirdle> girdle_top, girdle_bottom;
  for (int k = 0; k < kMains; ++k) {
    table[k] = b.polar(kTableRadius, segment_angle(k, kMains), table_z);
    star[k] = b.polar(star_radius, segment_angle(2 * k + 1, kGirdle), bezel_z(star_radius * cos_half));
  }
  for (int j = 0; j < kGirdle; ++j) girdle_top[j] = b.polar(kRadius, segment_angle(j, kGirdle), kGirdleHalf);
  for (int j = 0; j < kGirdle; ++j)
    girdle_bottom[j] = b.polar(kRadius, segment_angle(j, kGirdle), -kGirdleHalf);
  for (int k = 0; k < kMains; ++k)
    lower[k] = b.polar(lower_along / cos_half, segment_angle(2 * k + 1, kGirdle), pavilion_z(lower_along));
  const int culet = b.vertex(0, 0, culet_z);

  const auto wrap = [](int k) { return (k + kMains) % kMains; };
  const auto rim = [](int j) { return (j + kGirdle) % kGirdle; };
  for (int k = 0; k < kMains; ++k) {
    const int t = table[k], t_next = table[wrap(k + 1)];
    const int g = girdle_top[2 * k], g_mid = girdle_top[2 * k + 1], g_next = girdle_top[rim(2 * k + 2)];
    const int s = star[k], s_prev = star[wrap(k - 1)];
    b.triangle(table_centre, t, t_next);
    b.triangle(t, s, t_next);  // star facet
    b.triangle(t, s_prev, g);  // bezel facet, split along its axis
    b.triangle(t, g, s);
    b.triangle(s, g, g_mid);  // upper girdle facets
    b.triangle(s, g_mid, g_next);
  }
  for (int j = 0; j < kGirdle; ++j) {
    b.triangle(girdle_top[j], girdle_bottom[j], girdle_bottom[rim(j + 1)]);
    b.triangle(girdle_top[j], girdle_bottom[rim(j + 1)], girdle_top[rim(j + 1)]);
  }
  // The pavilion faces downwards, so its triangles run clockwise seen from above.
  for (int k = 0; k < kMains; ++k) {
    const int g = girdle_bottom[2 * k], g_mid = girdle_bottom[2 * k + 1];
    const int g_next = girdle_bottom[rim(2 * k + 2)];
    const int l = lower[k], l_prev = lower[wrap(k - 1)];
    b.triangle(l, g_mid, g);  // lower girdle facets
    b.triangle(l, g_next, g_mid);
    b.triangle(culet, l, g);  // pavilion main facet, split along its axis
    b.triangle(culet, g, l_prev);
  }
  return b.take();
}

bool has_repeated_corner(const std::vector<int>& polygon) {
  for (size_t i = 0; i < polygon.size(); ++i)
    if (std::find(polygon.begin() + std::ptrdiff_t(i) + 1, polygon.end(), polygon[i]) != polygon.end()) return true;
  return false;
}

[[noreturn]] void shape_error(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

}  // namespace

ShapeMesh make_builtin_shape(ShapeKind kind, ShapeDetail detail) {
  const bool minimal = detail == ShapeDetail::Minimal, coarse = detail == ShapeDetail::Coarse;
  switch (kind) {
    case ShapeKind::Sphere: return minimal ? make_sphere(6, 2) : coarse ? make_sphere(8, 6) : make_sphere(16, 10);
    case ShapeKind::Gem: return minimal ? make_gem_outline() : make_gem();
    case ShapeKind::HexPrism: return make_prism(6, 0.5);
    case ShapeKind::Disc: return make_prism(minimal ? 6 : coarse ? 12 : 32, 0.2);
    case ShapeKind::Custom: break;
  }
  throw InputError("the custom element shape is not built in; load it from a file with load_custom_shape (design "
                   "key '" + key_path(Key::custom_shape) + "')");
}

ShapeMesh load_custom_shape(const std::filesystem::path& path) {
  // The surfaces' strict readers: a bad file is refused with the same message as a bad surface.
  const std::string source = "custom shape " + path.string();
  return custom_shape_from_soup(read_mesh_file(path, source), source);
}

ShapeMesh custom_shape_from_soup(const PolygonSoup& soup, const std::string& source) {

  // Polygons become fans from their first corner; faces repeating a vertex are skipped. Only the
  // vertices that faces use are kept, numbered in order of use, so that stray points do not move
  // the bounding box.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<int> new_index(soup.positions.size(), -1);
  std::vector<glm::dvec3> points;
  glm::dvec3 lo(inf), hi(-inf);
  ShapeMesh shape;
  shape.triangles.reserve(soup.polygons.size());
  auto use = [&](int v) {
    int& index = new_index[size_t(v)];
    if (index < 0) {
      index = static_cast<int>(points.size());
      points.push_back(soup.positions[size_t(v)]);
      lo = glm::min(lo, points.back());
      hi = glm::max(hi, points.back());
    }
    return index;
  };
  for (const std::vector<int>& polygon : soup.polygons) {
    if (has_repeated_corner(polygon)) continue;
    for (size_t i = 1; i + 1 < polygon.size(); ++i) {
      const int a = use(polygon[0]), b = use(polygon[i]), c = use(polygon[i + 1]);
      shape.triangles.emplace_back(a, b, c);
    }
  }
  if (shape.triangles.empty()) shape_error(source, "it has no faces");

  // The footprint the contact rule assumes is a disc of the element's diameter: the shape is
  // scaled so that its outline seen along +Z fits the unit disc around its bounding box's centre
  // (a square fits by its corners, not by its sides). Its height stays as modelled when z = 0
  // lies within it: that plane is the surface (a boss drawn standing on z = 0 stands on the
  // surface, not half sunk into it); a shape drawn away from z = 0 is centred on its box.
  glm::dvec3 centre = 0.5 * (lo + hi);
  if (lo.z <= 0 && 0 <= hi.z) centre.z = 0;
  double reach = 0;
  for (const glm::dvec3& p : points) reach = std::max(reach, glm::length(glm::dvec2(p - centre)));
  const double width = 2 * reach;
  if (!(width > 0))
    shape_error(source, "it has no horizontal extent (all vertices lie on one vertical line); "
                      "model it with +Z as the surface normal");
  shape.positions.reserve(points.size());
  for (const glm::dvec3& p : points) shape.positions.emplace_back((p - centre) / width);
  // A shape of flat slivers (every face a line or a point) makes elements of no size at all.
  double area = 0;
  for (const glm::ivec3& t : shape.triangles)
    area += glm::length(glm::cross(shape.positions[size_t(t.y)] - shape.positions[size_t(t.x)],
                                   shape.positions[size_t(t.z)] - shape.positions[size_t(t.x)])) / 2;
  if (!(area > 1e-9))
    shape_error(source, "its faces have no area (every triangle is degenerate: its corners are on one line); "
                      "model the element as a solid or a surface with area");
  return shape;
}

long open_edge_count(const ShapeMesh& shape) {
  std::map<std::pair<int, int>, int> faces_on;
  for (const glm::ivec3& t : shape.triangles)
    for (int k = 0; k < 3; ++k) ++faces_on[std::minmax(t[k], t[(k + 1) % 3])];
  return std::count_if(faces_on.begin(), faces_on.end(), [](const auto& edge) { return edge.second == 1; });
}

}  // namespace paver
