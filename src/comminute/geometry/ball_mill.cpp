#include "comminute/geometry/ball_mill.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>

namespace comminute {

namespace {

constexpr double kPi = std::numbers::pi;

// Cross-section point (radius rho, angle theta from +x towards +z), as (x, z).
struct P2 {
  double x = 0, z = 0;
};

double cross2(const P2& o, const P2& a, const P2& b) {
  return (a.x - o.x) * (b.z - o.z) - (a.z - o.z) * (b.x - o.x);
}

P2 at(double rho, double theta) {
  return {rho * std::cos(theta), rho * std::sin(theta)};
}

// Lifter dimensions derived from the geometry: base half-angle beta, radial coordinates of the
// base chord (b) and of the top face (t), top half-width, half-angle gamma of the top corners.
struct Lifter {
  double beta, b, t, top_half, gamma;
};

Lifter lifter_of(const BallMillGeometry& g) {
  const double R = g.diameter / 2, w = g.lifter_width;
  Lifter l{};
  l.beta = std::asin(std::min(1.0, w / (2 * R)));
  l.b = std::sqrt(std::max(0.0, R * R - w * w / 4));
  l.t = R - g.lifter_height;
  l.top_half = w / 2 - (l.b - l.t) * std::tan(g.lifter_face_angle);
  l.gamma = std::atan2(l.top_half, l.t);
  return l;
}

// The shell vertices' angles that stay (evenly spaced, those near or under a lifter's base
// dropped), and each lifter's centre angle.
bool under_lifter(const BallMillGeometry& g, const Lifter& l, double theta) {
  const double step = 2 * kPi / g.segments;
  for (int k = 0; k < g.lifters; ++k) {
    double d = std::remainder(theta - 2 * kPi * k / g.lifters, 2 * kPi);
    if (std::abs(d) < l.beta + 0.25 * step) return true;
  }
  return false;
}

// Profile of the cross-section in order of increasing angle (counter-clockwise in (x, z)).
std::vector<P2> profile(const BallMillGeometry& g) {
  const double R = g.diameter / 2;
  const Lifter l = lifter_of(g);
  std::multimap<double, std::vector<P2>> items;  // keyed by angle
  for (int j = 0; j < g.segments; ++j) {
    const double theta = 2 * kPi * j / g.segments;
    if (g.lifters == 0 || !under_lifter(g, l, theta))
      items.emplace(theta, std::vector{at(R, theta)});
  }
  for (int k = 0; k < g.lifters; ++k) {
    const double phi = 2 * kPi * k / g.lifters;
    const P2 er{std::cos(phi), std::sin(phi)}, et{-std::sin(phi), std::cos(phi)};
    auto point = [&](double radial, double tangential) {
      return P2{radial * er.x + tangential * et.x, radial * er.z + tangential * et.z};
    };
    const double w2 = g.lifter_width / 2;
    items.emplace(phi, std::vector{point(l.b, -w2), point(l.t, -l.top_half), point(l.t, l.top_half),
                                   point(l.b, w2)});
  }
  std::vector<P2> out;
  for (const auto& [theta, pts] : items) out.insert(out.end(), pts.begin(), pts.end());
  return out;
}

bool inside_triangle(const P2& p, const P2& a, const P2& b, const P2& c) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Ear clipping of a simple counter-clockwise polygon: triangles as index triples, each
// counter-clockwise.
std::vector<std::array<std::uint32_t, 3>> triangulate(const std::vector<P2>& poly) {
  std::vector<std::uint32_t> ring(poly.size());
  for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = static_cast<std::uint32_t>(i);
  std::vector<std::array<std::uint32_t, 3>> out;
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const std::uint32_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                          c = ring[(i + 1) % ring.size()];
      if (cross2(poly[a], poly[b], poly[c]) <= 0) continue;  // reflex or straight: no ear
      bool empty = true;
      for (std::uint32_t q : ring)
        if (q != a && q != b && q != c && inside_triangle(poly[q], poly[a], poly[b], poly[c]))
          empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) throw Error("ball mill: the cross-section could not be triangulated");
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

}  // namespace

void check_ball_mill(const BallMillGeometry& g) {
  if (!(g.diameter > 0) || !(g.length > 0))
    throw Error("ball mill: diameter and length must be > 0");
  if (g.segments < 8) throw Error("ball mill: segments must be at least 8");
  if (g.lifters == 0) return;
  const Lifter l = lifter_of(g);
  const double R = g.diameter / 2;
  if (!(g.lifter_width > 0) || g.lifter_width >= g.diameter)
    throw Error("ball mill: lifter_width must be > 0 and below the diameter");
  if (!(l.t < l.b))
    throw Error(fmt::format(
        "ball mill: lifter_height must exceed the sagitta of the lifter base, {:.6g} m", R - l.b));
  if (!(l.t > 0.1 * R)) throw Error("ball mill: lifter_height must stay below 0.9 D/2");
  if (!(l.top_half > 0))
    throw Error("ball mill: lifter_face_angle leaves no top face (top width <= 0)");
  if (!(std::max(l.beta, l.gamma) + 0.5 * 2 * kPi / g.segments < kPi / g.lifters))
    throw Error("ball mill: the lifters overlap one another (too many or too wide)");
}

IndexedMesh ball_mill_mesh(const BallMillGeometry& g) {
  check_ball_mill(g);
  const std::vector<P2> poly = profile(g);
  const auto n = static_cast<std::uint32_t>(poly.size());
  IndexedMesh m;
  const double y0 = -g.length / 2, y1 = g.length / 2;
  for (const P2& p : poly) m.vertices.push_back({p.x, y0, p.z});
  for (const P2& p : poly) m.vertices.push_back({p.x, y1, p.z});
  // shell and lifter faces, normals away from the mill's inside
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t a0 = i, b0 = (i + 1) % n, a1 = a0 + n, b1 = b0 + n;
    m.triangles.push_back({a0, b1, b0});
    m.triangles.push_back({a0, a1, b1});
  }
  if (g.end_liners) {
    // counter-clockwise in (x, z) is a normal along -y: as is at y0, reversed at y1
    for (const auto& t : triangulate(poly)) {
      m.triangles.push_back(t);
      m.triangles.push_back({t[0] + n, t[2] + n, t[1] + n});
    }
  }
  return m;
}

double ball_mill_section_area(const BallMillGeometry& g) {
  check_ball_mill(g);
  const double R = g.diameter / 2;
  const Lifter l = lifter_of(g);
  // the shell polygon: its vertices (the kept shell vertices and the lifters' base corners) all
  // lie on the circle, so its area is the sum of R^2 sin(dtheta) / 2 over consecutive vertices
  std::vector<double> angles;
  for (int j = 0; j < g.segments; ++j) {
    const double theta = 2 * kPi * j / g.segments;
    if (g.lifters == 0 || !under_lifter(g, l, theta)) angles.push_back(theta);
  }
  for (int k = 0; k < g.lifters; ++k) {
    const double phi = 2 * kPi * k / g.lifters;
    angles.push_back(std::fmod(phi - l.beta + 2 * kPi, 2 * kPi));
    angles.push_back(phi + l.beta);
  }
  std::sort(angles.begin(), angles.end());
  double area = 0;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * kPi;
    area += 0.5 * R * R * std::sin(next - angles[i]);
  }
  // less each lifter: a trapezoid of height b - t between its base chord and top face
  area -= g.lifters * (l.b - l.t) * (g.lifter_width / 2 + l.top_half);
  return area;
}

double enclosed_volume(const IndexedMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6;
  return v;
}

void write_stl(const std::filesystem::path& file, const IndexedMesh& m) {
  std::string b(80, ' ');
  b.replace(0, 20, "comminute ball mill ");
  const auto count = static_cast<std::uint32_t>(m.triangles.size());
  b.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : m.triangles) {
    const Vec3 nrm =
        cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
    const Vec3 u = nrm * (1 / norm(nrm));
    float rec[12] = {static_cast<float>(u.x), static_cast<float>(u.y), static_cast<float>(u.z)};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        rec[3 + 3 * k + a] = static_cast<float>(m.vertices[t[static_cast<std::size_t>(k)]][a]);
    b.append(reinterpret_cast<const char*>(rec), 48);
    b.append(2, '\0');
  }
  std::ofstream f(file, std::ios::binary);
  f.write(b.data(), static_cast<std::streamsize>(b.size()));
  if (!f) throw Error(fmt::format("cannot write '{}'", file.string()));
}

// Critical speed: centrifugal force on a ball at the liner equals its weight,
// omega_c^2 (D - d) / 2 = g (Napier-Munn, Morrell, Morrison & Kojovic, Mineral Comminution
// Circuits, JKMRC 1996, Ch. 10; Austin, Klimpel & Luckie, Process Engineering of Size
// Reduction, 1984, Eq. 10.1: N_c = 42.3 / sqrt(D - d) rpm).
double critical_speed(double mill_diameter, double ball_diameter, double g) {
  if (!(mill_diameter > ball_diameter) || !(ball_diameter >= 0) || !(g > 0))
    throw Error("critical speed: need D > d >= 0 and g > 0");
  return std::sqrt(2 * g / (mill_diameter - ball_diameter));
}

// Ball charge of a fractional filling J (Austin, Klimpel & Luckie 1984, Eq. 10.2: J is the bed
// volume, voids included, over the mill volume; the bed porosity is taken as 0.4).
long balls_for_filling(double filling, double mill_volume, double ball_diameter, double voids) {
  if (!(filling > 0 && filling < 1) || !(mill_volume > 0) || !(ball_diameter > 0) ||
      !(voids >= 0 && voids < 1))
    throw Error("ball charge: need 0 < J < 1, V > 0, d > 0, 0 <= voids < 1");
  return std::lround((1 - voids) * filling * mill_volume / (kPi * std::pow(ball_diameter, 3) / 6));
}

}  // namespace comminute
