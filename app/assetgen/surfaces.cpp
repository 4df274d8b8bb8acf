#include "surfaces.h"

#include "sampling.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <utility>
#include <vector>

namespace paver::assetgen {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr double kPi = glm::pi<double>();

int rounded(double x) { return static_cast<int>(std::lround(x)); }

// Spherical cap: sphere radius 100, half-angle 60 degrees, base circle (radius 86.6) at z = 0,
// apex at z = 50. Ring k of n has 6k vertices at polar angle proportional to k, i.e. equal
// geodesic steps, so triangles stay close to even (the outer rings shrink by sin(a)/a >= 0.83).
Mesh dome(int rings) {
  constexpr double R = 100.0;
  const double half_angle = kPi / 3.0;
  const double z0 = R * std::cos(half_angle);
  Mesh m;
  const int centre = m.add({0.0, 0.0, R - z0});
  std::vector<Row> rs;
  for (int k = 1; k <= rings; ++k) {
    const double a = half_angle * k / rings;
    rs.push_back(make_ring(m, 6 * k, [&](double t) {
      const double th = 2.0 * kPi * t;
      return dvec3(R * std::sin(a) * std::cos(th), R * std::sin(a) * std::sin(th), R * std::cos(a) - z0);
    }));
  }
  stitch_rings(m, centre, rs);
  orient(m, [&](dvec3 p) { return p - dvec3(0.0, 0.0, -z0); });
  return m;
}

// Height field z(x, y) over a rectangle. Grid lines are placed at equal steps of arc length
// (averaged across the other axis), and each cell is split along its shorter 3D diagonal, or
// in a checkerboard where the diagonals are within 5% (flat regions stay regular).
struct HeightField {
  std::function<double(double, double)> z;
  dvec2 lo, hi;
};

Mesh height_field(const HeightField& hf, double h) {
  constexpr int kAcross = 64;  // samples of the other axis when averaging the slope
  const auto slope_density = [&](bool along_x) {
    return [&hf, along_x](double s) {
      const double lo = along_x ? hf.lo.y : hf.lo.x;
      const double hi = along_x ? hf.hi.y : hf.hi.x;
      const double eps = 1e-5 * ((along_x ? hf.hi.x - hf.lo.x : hf.hi.y - hf.lo.y));
      double sum = 0.0;
      for (int i = 0; i < kAcross; ++i) {
        const double o = lo + (hi - lo) * (i + 0.5) / kAcross;
        const double d = along_x ? (hf.z(s + eps, o) - hf.z(s - eps, o)) / (2.0 * eps)
                                 : (hf.z(o, s + eps) - hf.z(o, s - eps)) / (2.0 * eps);
        sum += std::sqrt(1.0 + d * d);
      }
      return sum / kAcross;
    };
  };
  const EvenSpacing ex(hf.lo.x, hf.hi.x, slope_density(true));
  const EvenSpacing ey(hf.lo.y, hf.hi.y, slope_density(false));
  const int nx = std::max(1, rounded(ex.length() / h));
  const int ny = std::max(1, rounded(ey.length() / h));
  const std::vector<double> xs = ex.nodes(nx);
  const std::vector<double> ys = ey.nodes(ny);

  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.add({xs[i], ys[j], hf.z(xs[i], ys[j])});
  const auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int v00 = id(i, j), v10 = id(i + 1, j), v01 = id(i, j + 1), v11 = id(i + 1, j + 1);
      const double d1 = glm::distance(m.v[v00], m.v[v11]);
      const double d2 = glm::distance(m.v[v10], m.v[v01]);
      const bool main_diagonal = d1 < 0.95 * d2 ? true : d2 < 0.95 * d1 ? false : (i + j) % 2 == 0;
      if (main_diagonal) {
        m.f.push_back({v00, v10, v11});
        m.f.push_back({v00, v11, v01});
      } else {
        m.f.push_back({v00, v10, v01});
        m.f.push_back({v10, v11, v01});
      }
    }
  }
  orient(m, [](dvec3) { return dvec3(0.0, 0.0, 1.0); });
  return m;
}

Mesh saddle(int target) {
  const HeightField hf{[](double x, double y) { return (x * x - y * y) / 120.0; },
                       {-90.0, -90.0}, {90.0, 90.0}};
  return fit_faces([&](double h) { return height_field(hf, h); }, 8.0, target);
}

Mesh wave(int target) {
  const HeightField hf{[](double x, double y) {
                         return 8.0 * std::sin(2.0 * kPi * x / 60.0) * std::cos(2.0 * kPi * y / 90.0);
                       },
                       {-90.0, -60.0}, {90.0, 60.0}};
  return fit_faces([&](double h) { return height_field(hf, h); }, 8.0, target);
}

// Facade panel, 400 wide (x) by 200 high (y), bulging towards +z by up to 25, less at the top.
HeightField facade_field() {
  return {[](double x, double y) {
            const double v = y / 200.0;
            return 25.0 * std::sin(kPi * x / 400.0) * (1.0 - 0.3 * v * v);
          },
          {0.0, 0.0},
          {400.0, 200.0}};
}

Mesh facade(int target) {
  const HeightField hf = facade_field();
  return fit_faces([&](double h) { return height_field(hf, h); }, 10.0, target);
}

// Vase, 120 high: the wall of a surface of revolution (belly r = 42 near z = 39, neck r = 24
// near z = 100, lip r = 32) over 270 degrees, open along a vertical seam like an architectural
// vase facade. A full cup with a bottom would be a disk too, but flattening it bends the map so
// much (singular-value ratios above 10) that no regular lattice survives the lift. Rows of
// constant height each get as many segments as their length needs. Normals point outward.
Mesh vase(int target) {
  const auto radius = [](double z) {
    return 30.0 + 12.0 * std::sin(z / 25.0) + 14.0 * std::pow(z / 120.0, 8.0);
  };
  constexpr double kHeight = 120.0;
  const double sweep = 1.5 * kPi;
  // Arc length along the profile, so rows are evenly spaced on the wall.
  std::vector<dvec2> pts;
  for (double z = 0.0; z < kHeight; z += 0.05) pts.emplace_back(radius(z), z);
  pts.emplace_back(radius(kHeight), kHeight);
  const Polyline profile(std::move(pts));
  return fit_faces(
      [&](double h) {
        const int rows = std::max(1, rounded(profile.length() / (h * std::sqrt(3.0) / 2.0)));
        Mesh m;
        std::vector<Row> rs;
        for (int i = 0; i <= rows; ++i) {
          const dvec2 p = profile.at(static_cast<double>(i) / rows);
          const int segments = std::max(1, rounded(p.x * sweep / h));
          rs.push_back(make_row(m, segments, [&](double t) {
            const double th = sweep * t;
            return dvec3(p.x * std::cos(th), p.x * std::sin(th), p.y);
          }));
        }
        for (std::size_t i = 1; i < rs.size(); ++i) stitch(m, rs[i - 1], rs[i], false);
        orient(m, [](dvec3 q) { return dvec3(q.x, q.y, 0.0); });
        return m;
      },
      5.0, target);
}

// Part of a torus (major radius 80, minor 30): toroidal angle 0..120 degrees, poloidal angle
// -90..150 degrees (bottom, outer equator, top and a little of the inner side). Rows of
// constant poloidal angle each get as many segments as their length needs, so the short inner
// rows are not crowded (row lengths differ by 2:1).
Mesh torus_section(int target) {
  constexpr double R = 80.0;
  constexpr double r = 30.0;
  const double phi_max = 2.0 * kPi / 3.0;
  const double th0 = -kPi / 2.0;
  const double th1 = 5.0 * kPi / 6.0;
  const auto point = [&](double phi, double th) {
    const double rho = R + r * std::cos(th);
    return dvec3(rho * std::cos(phi), rho * std::sin(phi), r * std::sin(th));
  };
  return fit_faces(
      [&](double h) {
        // Rows sqrt(3)/2 h apart with h along them: near-equilateral where rows are offset.
        const int rows = std::max(1, rounded(r * (th1 - th0) / (h * std::sqrt(3.0) / 2.0)));
        Mesh m;
        std::vector<Row> rs;
        for (int i = 0; i <= rows; ++i) {
          const double th = th0 + (th1 - th0) * i / rows;
          const int segments = std::max(1, rounded((R + r * std::cos(th)) * phi_max / h));
          rs.push_back(make_row(m, segments, [&](double t) { return point(phi_max * t, th); }));
        }
        for (std::size_t i = 1; i < rs.size(); ++i) stitch(m, rs[i - 1], rs[i], false);
        orient(m, [&](dvec3 p) {
          const double phi = std::atan2(p.y, p.x);
          return p - dvec3(R * std::cos(phi), R * std::sin(phi), 0.0);
        });
        return m;
      },
      8.0, target);
}

// Teardrop outline in XY: 28 wide, 40 long, round end down (y = -14), tip up (y = 26) rounded
// with radius 2.5 mm as a real pendant's would be. A circle of radius 14 at the origin and a
// tip circle, joined by their common tangents. Closed, counter-clockwise, starting at the bottom.
Polyline teardrop_outline() {
  constexpr double a = 14.0;    // half width, radius of the round end
  constexpr double tip = 26.0;  // y of the rounded tip's apex
  constexpr double rt = 2.5;    // tip rounding radius
  // Sharp apex at distance d from the origin with sin(half angle) = a / d; the rounding circle
  // sits rt / sin(half angle) = rt d / a below it, so its top is at d (1 - rt / a) + rt.
  const double d = (tip - rt) / (1.0 - rt / a);
  const double yc = d - rt * d / a;       // tip circle centre
  const double beta = std::acos(a / d);   // angle of the tangent points from +y
  constexpr int kPerArc = 2000;
  std::vector<dvec2> pts;
  const auto arc = [&](dvec2 c, double rad, double from, double to) {
    for (int i = 0; i <= kPerArc; ++i) {
      const double t = from + (to - from) * i / kPerArc;
      pts.push_back(c + rad * dvec2(std::cos(t), std::sin(t)));
    }
  };
  // Straight segments come for free between consecutive arcs' end points.
  arc({0.0, 0.0}, a, -kPi / 2.0, kPi / 2.0 - beta);
  arc({0.0, yc}, rt, kPi / 2.0 - beta, kPi / 2.0 + beta);
  arc({0.0, 0.0}, a, kPi / 2.0 + beta, 3.0 * kPi / 2.0);
  return Polyline(std::move(pts));
}

// Domed pendant over the teardrop, rings about h apart: rings are copies of the outline scaled about the middle of
// its length (0, 6), at scale rho in [0, 1]; height 6 at the centre, falling to 0 at the outline
// like an elliptic lens cap (finite slope at the rim so the rim is not vertical).
Mesh pendant_mesh(double h) {
  const Polyline outline = teardrop_outline();
  const dvec2 c(0.0, 6.0);
  constexpr double kHeight = 6.0;
  constexpr double kS = 0.85;  // lens shape: 1 would be a half-ellipse with a vertical rim
  const double base = std::sqrt(1.0 - kS);
  const auto height = [&](double rho) {
    return kHeight * (std::sqrt(1.0 - kS * rho * rho) - base) / (1.0 - base);
  };
  const auto point = [&](double rho, double t) {
    const dvec2 q = c + rho * (outline.at(t) - c);
    return dvec3(q.x, q.y, height(rho));
  };
  // Rings at equal steps of 3D arc length, averaged around the outline.
  constexpr int kAround = 256;
  const EvenSpacing radial(0.0, 1.0, [&](double rho) {
    const double eps = 1e-5;
    const double dz = (height(std::min(rho + eps, 1.0)) - height(std::max(rho - eps, 0.0))) /
                      (std::min(rho + eps, 1.0) - std::max(rho - eps, 0.0));
    double sum = 0.0;
    for (int i = 0; i < kAround; ++i) {
      const double dr = glm::distance(outline.at((i + 0.5) / kAround), c);
      sum += std::sqrt(dr * dr + dz * dz);
    }
    return sum / kAround;
  });
  const int n = std::max(1, rounded(radial.length() / h));
  const double step = radial.length() / n;
  Mesh m;
  const int centre = m.add(point(0.0, 0.0));
  std::vector<Row> rs;
  for (int k = 1; k <= n; ++k) {
    const double rho = radial.at(static_cast<double>(k) / n);
    // Ring perimeter; z is constant on a ring, so the planar one is the 3D one.
    const double perimeter = rho * outline.length();
    // Same rule as revolve(): tangential spacing ~1.05 step.
    const int count = std::max(6, rounded(perimeter * 3.0 / (kPi * step)));
    rs.push_back(make_ring(m, count, [&](double t) { return point(rho, t); }));
  }
  stitch_rings(m, centre, rs);
  orient(m, [](dvec3) { return dvec3(0.0, 0.0, 1.0); });
  return m;
}

Mesh pendant(int target) { return fit_faces(pendant_mesh, 1.0, target); }

// Ring i of `rows` on a profile (r, z) revolved about z, with as many vertices as its length
// needs; alternate rows are turned by half a step, so the triangles between them are
// near-equilateral.
Row revolved_ring(Mesh& m, const Polyline& profile, int i, int rows, double h) {
  const dvec2 p = profile.at(static_cast<double>(i) / rows);
  const double turn = (i % 2) * 0.5;
  const int count = std::max(6, rounded(2.0 * kPi * p.x / h));
  return make_ring(m, count, [&](double t) {
    const double th = 2.0 * kPi * (t + turn / count);
    return dvec3(p.x * std::cos(th), p.x * std::sin(th), p.y);
  });
}

// A band of revolution about z: rows of constant height on the profile (r(z), z), z0..z1, each a
// closed ring with as many vertices as its length needs. Both rims are open: two boundary loops.
Mesh band_of_revolution(const std::function<double(double)>& radius, double z0, double z1, double h) {
  std::vector<dvec2> pts;
  const int samples = 400;
  for (int i = 0; i <= samples; ++i) {
    const double z = z0 + (z1 - z0) * i / samples;
    pts.emplace_back(radius(z), z);
  }
  const Polyline profile(std::move(pts));
  const int rows = std::max(1, rounded(profile.length() / (h * std::sqrt(3.0) / 2.0)));
  Mesh m;
  std::vector<Row> rs;
  for (int i = 0; i <= rows; ++i) rs.push_back(revolved_ring(m, profile, i, rows, h));
  for (std::size_t i = 1; i < rs.size(); ++i) stitch(m, rs[i - 1], rs[i], true);
  orient(m, [](dvec3 q) { return dvec3(q.x, q.y, 0.0); });
  return m;
}

// A bangle's outer face: 64 mm inside diameter plus 1.5 mm of metal (radius 33.5), 12 mm wide,
// crowned 1.2 mm at the middle (a comfort profile). Normals outward.
Mesh bangle(int target) {
  const auto radius = [](double z) { return 33.5 + 1.2 * std::cos(kPi * z / 12.0); };
  return fit_faces([&](double h) { return band_of_revolution(radius, -6.0, 6.0, h); }, 1.0, target);
}

// A finger ring's outer face: size 57 (18.1 mm inside diameter) plus 1.6 mm of metal, 6 mm
// wide, crowned 0.6 mm. Normals outward.
Mesh ring_band(int target) {
  const auto radius = [](double z) { return 10.65 + 0.6 * std::cos(kPi * z / 6.0); };
  return fit_faces([&](double h) { return band_of_revolution(radius, -3.0, 3.0, h); }, 0.5, target);
}

// A value in [-1, 1] fixed by `key`: a scanner's noise, the same on every run (no randomness).
double scan_noise(std::uint32_t key) {
  key ^= key >> 16, key *= 0x7feb352dU, key ^= key >> 15, key *= 0x846ca68bU, key ^= key >> 16;
  return key / 2147483647.5 - 1.0;
}

// The ring band as a scanner writes it (issue 40's "scanned band"): the same crowned 6 mm band,
// out of round by 0.02 mm (three lobes, a hand-finished ring), every vertex moved by noise (0.012
// mm along the normal, a tenth of an edge along the surface: a quarter made angles under the asset
// check's 20 degrees) so the triangles are uneven, and the rims wavy by 0.03 mm. Normals outward.
Mesh ring_scan(int target) {
  const auto radius = [](double z) { return 10.65 + 0.6 * std::cos(kPi * z / 6.0); };
  return fit_faces(
      [&](double h) {
        Mesh m = band_of_revolution(radius, -3.0, 3.0, h);
        for (std::size_t i = 0; i < m.v.size(); ++i) {
          const dvec3 p = m.v[i];
          const bool rim = std::abs(std::abs(p.z) - 3.0) < 1e-9;
          const double theta = std::atan2(p.y, p.x) + 0.1 * h * scan_noise(3 * std::uint32_t(i)) / radius(p.z);
          const double z = rim ? p.z + 0.03 * scan_noise(3 * std::uint32_t(i) + 1)
                               : std::clamp(p.z + 0.1 * h * scan_noise(3 * std::uint32_t(i) + 1), -2.99, 2.99);
          const double r = radius(z) + 0.02 * std::sin(3 * theta + 0.4) + 0.012 * scan_noise(3 * std::uint32_t(i) + 2);
          m.v[i] = dvec3(r * std::cos(theta), r * std::sin(theta), z);
        }
        return m;
      },
      0.5, target);
}

// An open vase all the way round: the vase's profile (belly r = 42, neck 24, lip 32, 120 high)
// revolved a full turn with no bottom, so its foot and its lip are two rims: a band whose girth
// changes 1.75-fold, which no seamless lattice follows without tearing (docs/holes_and_bands.md).
Mesh vase_band(int target) {
  const auto radius = [](double z) { return 30.0 + 12.0 * std::sin(z / 25.0) + 14.0 * std::pow(z / 120.0, 8.0); };
  return fit_faces([&](double h) { return band_of_revolution(radius, 0.0, 120.0, h); }, 5.0, target);
}

// The facade panel with 4 x 3 windows: the grid's cells whose centres fall in a window are left
// out, so each window is a clean rectangle of cells with the panel's own triangles around it.
Mesh facade_windows(int target) {
  const HeightField hf = facade_field();
  const auto in_window = [](dvec3 c) {
    // Windows 50 wide and 34 high, on a 100 x 60 raster starting 25 in from the left and 20 up.
    const double fx = std::fmod(c.x - 25.0, 100.0), fy = std::fmod(c.y - 20.0, 60.0);
    return c.x > 25.0 && c.x < 375.0 && c.y > 20.0 && c.y < 180.0 && fx < 50.0 && fy < 34.0;
  };
  return fit_faces(
      [&](double h) {
        Mesh full = height_field(hf, h);
        // Whole cells go: a cell's two triangles have the same centre (the quad's), so both stay
        // or both go, and each window is a rectangle of cells.
        Mesh m;
        m.v = full.v;
        for (std::size_t f = 0; f < full.f.size(); f += 2) {
          const auto& a = full.f[f];
          const auto& b = full.f[f + 1];
          dvec3 centre(0.0);
          for (int k = 0; k < 3; ++k) centre += full.v[a[k]] + full.v[b[k]];
          if (in_window(centre / 6.0)) continue;
          m.f.push_back(a);
          m.f.push_back(b);
        }
        return drop_unused_vertices(m);
      },
      10.0, target);
}

// The pendant pierced three times: a bail hole 2.4 mm across near the tip and two 5 mm holes
// side by side in the round end. The faces whose centres fall in a hole are left out, so the
// holes' rims follow the pendant's rings (a scan-like, stepped rim).
Mesh pendant_pierced(int target) {
  struct Hole {
    dvec2 centre;
    double radius;
  };
  const Hole holes[] = {{{0.0, 20.5}, 1.2}, {{-5.5, -3.0}, 2.5}, {{5.5, -3.0}, 2.5}};
  const auto pierced = [&](double h) {
    const Mesh full = pendant_mesh(h);
    Mesh m;
    m.v = full.v;
    for (const auto& t : full.f) {
      const dvec3 c = centroid(full, t);
      bool inside = false;
      for (const Hole& hole : holes) inside = inside || glm::distance(dvec2(c), hole.centre) < hole.radius;
      if (!inside) m.f.push_back(t);
    }
    return drop_unused_vertices(m);
  };
  return fit_faces(pierced, 1.0, target);
}

// A bead: an olive (ellipsoid of revolution about z) 12 mm long and 8 mm across, closed, with
// no boundary loop. Rings at even steps of the profile's length between the two poles.
Mesh bead_mesh(double h) {
  constexpr double kHalfLength = 6.0, kRadius = 4.0;
  std::vector<dvec2> pts;
  const int samples = 400;
  for (int i = 0; i <= samples; ++i) {
    const double phi = kPi * i / samples;
    pts.emplace_back(kRadius * std::sin(phi), -kHalfLength * std::cos(phi));
  }
  const Polyline profile(std::move(pts));
  const int rows = std::max(2, rounded(profile.length() / (h * std::sqrt(3.0) / 2.0)));
  Mesh m;
  const int bottom = m.add(dvec3(0.0, 0.0, -kHalfLength));
  std::vector<Row> rs;
  for (int i = 1; i < rows; ++i) rs.push_back(revolved_ring(m, profile, i, rows, h));
  stitch_rings(m, bottom, rs);
  // The top cap runs against the bottom one: seen from outside, both turn the same way.
  const int top = m.add(dvec3(0.0, 0.0, kHalfLength));
  const std::vector<int>& last = rs.back().idx;
  for (std::size_t j = 0; j < last.size(); ++j) m.f.push_back({top, last[(j + 1) % last.size()], last[j]});
  orient(m, [](dvec3 q) { return q; });
  return m;
}

Mesh bead(int target) { return fit_faces(bead_mesh, 1.0, target); }

dvec3 up(dvec3) { return {0.0, 0.0, 1.0}; }

}  // namespace

std::vector<Surface> small_set() {
  return {
      {"dome", [] { return dome(20); }, [](dvec3 p) { return p - dvec3(0.0, 0.0, -50.0); }},
      {"saddle", [] { return saddle(2000); }, up},
      {"wave", [] { return wave(720); }, up},
      {"vase", [] { return vase(2100); }, [](dvec3 p) { return dvec3(p.x, p.y, 0.0); }},
      {"torus_section", [] { return torus_section(900); },
       [](dvec3 p) {
         const double phi = std::atan2(p.y, p.x);
         return p - dvec3(80.0 * std::cos(phi), 80.0 * std::sin(phi), 0.0);
       }},
      {"pendant", [] { return pendant(2000); }, up},
      {"facade", [] { return facade(1200); }, up},
      {"bangle", [] { return bangle(2400); }, [](dvec3 p) { return dvec3(p.x, p.y, 0.0); }, 2},
      {"ring_band", [] { return ring_band(1200); }, [](dvec3 p) { return dvec3(p.x, p.y, 0.0); }, 2},
      {"ring_scan", [] { return ring_scan(3000); }, [](dvec3 p) { return dvec3(p.x, p.y, 0.0); }, 2},
      {"vase_band", [] { return vase_band(2400); }, [](dvec3 p) { return dvec3(p.x, p.y, 0.0); }, 2},
      {"facade_windows", [] { return facade_windows(2400); }, up, 13},
      {"pendant_pierced", [] { return pendant_pierced(3000); }, up, 4},
      {"bead", [] { return bead(1600); }, [](dvec3 p) { return p; }, 0},
  };
}

// Targets sit a little above 50k where fit_faces() can land a few percent under its target.
std::vector<Surface> dense_set() {
  return {
      {"dome_dense", [] { return dome(100); }, [](dvec3 p) { return p - dvec3(0.0, 0.0, -50.0); }},
      {"wave_dense", [] { return wave(100000); }, up},
      {"facade_dense", [] { return facade(52000); }, up},
  };
}

}  // namespace paver::assetgen
