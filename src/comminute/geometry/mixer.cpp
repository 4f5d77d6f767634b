#include "comminute/geometry/mixer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace comminute {

namespace {

constexpr double kPi = std::numbers::pi;

// Appends the closed box centre c, half-extents h along the orthonormal right-handed axes e.
void add_box(IndexedMesh& m, const Vec3& c, const std::array<Vec3, 3>& e, const Vec3& h) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (int k = 0; k < 8; ++k) {
    const double s0 = (k & 1) ? 1 : -1, s1 = (k & 2) ? 1 : -1, s2 = (k & 4) ? 1 : -1;
    m.vertices.push_back(c + s0 * h.x * e[0] + s1 * h.y * e[1] + s2 * h.z * e[2]);
  }
  // faces as quads (counter-clockwise seen from outside), two triangles each
  const std::uint32_t q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : q) {
    m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    m.triangles.push_back({base + f[0], base + f[2], base + f[3]});
  }
}

// A closed prism of n sides, radius r, from z0 to z1 about the z axis.
void add_prism(IndexedMesh& m, double r, double z0, double z1, int n) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  const auto un = static_cast<std::uint32_t>(n);
  for (int j = 0; j < n; ++j) {  // half a segment off +x, as the vessel's
    const double a = 2 * kPi * (j + 0.5) / n;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), z0});
  }
  for (int j = 0; j < n; ++j) {
    const double a = 2 * kPi * (j + 0.5) / n;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), z1});
  }
  m.vertices.push_back({0, 0, z0});
  m.vertices.push_back({0, 0, z1});
  const std::uint32_t bottom = base + 2 * un, top = bottom + 1;
  for (std::uint32_t j = 0; j < un; ++j) {
    const std::uint32_t a0 = base + j, b0 = base + (j + 1) % un, a1 = a0 + un, b1 = b0 + un;
    m.triangles.push_back({a0, b0, b1});
    m.triangles.push_back({a0, b1, a1});
    m.triangles.push_back({bottom, b0, a0});
    m.triangles.push_back({top, a1, b1});
  }
}

// Lowest point of a blade above its centre: half the chord's and the thickness's vertical parts.
double blade_half_rise(const MixerGeometry& g) {
  return 0.5 * (g.blade_height * std::sin(g.pitch) + g.blade_thickness * std::cos(g.pitch));
}

}  // namespace

void check_mixer(const MixerGeometry& g) {
  if (!(g.vessel_diameter > 0) || !(g.vessel_height > 0))
    throw Error("mixer: vessel_diameter and vessel_height must be > 0");
  if (g.blades < 1) throw Error("mixer: blades must be at least 1");
  if (g.blades_built < 1 || g.blades_built > g.blades)
    throw Error("mixer: blades_built must lie in [1, blades]");
  if (!(g.shaft_diameter > 0) || !(g.shaft_diameter < g.vessel_diameter))
    throw Error("mixer: shaft_diameter must be > 0 and below vessel_diameter");
  if (!(g.blade_length > 0) || !(g.wall_clearance() > 0))
    throw Error(fmt::format(
        "mixer: the blade tip (radius {:.6g} m) must stay inside the vessel (radius {:.6g} m)",
        g.tip_radius(), 0.5 * g.vessel_diameter));
  if (!(g.blade_height > 0) || !(g.blade_thickness > 0))
    throw Error("mixer: blade_height and blade_thickness must be > 0");
  if (!(g.pitch > 0) || g.pitch > 0.5 * kPi)
    throw Error("mixer: pitch must lie in (0, 90] degrees");
  if (!(g.bottom_clearance > 0)) throw Error("mixer: bottom_clearance must be > 0");
  if (g.segments < 6) throw Error("mixer: segments must be at least 6");
  if (!(g.shaft_top > g.bottom_clearance + 2 * blade_half_rise(g)))
    throw Error("mixer: shaft_top must be above the blades");
  // neighbouring blades must not touch at the shaft surface: their half widths across the
  // radial direction there (chord and thickness projected on the horizontal) within the gap
  const double rs = 0.5 * g.shaft_diameter;
  const double half_across =
      0.5 * (g.blade_height * std::cos(g.pitch) + g.blade_thickness * std::sin(g.pitch));
  if (g.blades > 1 && !(2 * half_across < 2 * rs * std::sin(kPi / g.blades)))
    throw Error("mixer: the blades overlap one another at the shaft (too many or too wide)");
}

IndexedMesh mixer_shaft_mesh(const MixerGeometry& g) {
  check_mixer(g);
  IndexedMesh m;
  const double rs = 0.5 * g.shaft_diameter, r0 = 0.5 * rs, r1 = g.tip_radius();
  const double zc = g.bottom_clearance + blade_half_rise(g);
  for (int k = 0; k < g.blades_built; ++k) {
    const double phi = 2 * kPi * k / g.blades;
    const Vec3 er{std::cos(phi), std::sin(phi), 0}, et{-std::sin(phi), std::cos(phi), 0};
    const Vec3 ez{0, 0, 1};
    // chord tilted from the horizontal (+et) up towards +z by the pitch; normal completes the
    // right-handed triple (er, ec, en)
    const Vec3 ec = std::cos(g.pitch) * et + std::sin(g.pitch) * ez;
    const Vec3 en = cross(er, ec);
    add_box(m, 0.5 * (r0 + r1) * er + Vec3{0, 0, zc}, {er, ec, en},
            {0.5 * (r1 - r0), 0.5 * g.blade_height, 0.5 * g.blade_thickness});
  }
  if (g.shaft) add_prism(m, rs, g.bottom_clearance, g.shaft_top, g.segments);
  return m;
}

IndexedMesh mixer_vessel_mesh(double diameter, double height, int segments) {
  if (!(diameter > 0) || !(height > 0) || segments < 8)
    throw Error("mixer vessel: need diameter > 0, height > 0, segments >= 8");
  IndexedMesh m;
  const double r = 0.5 * diameter;
  const auto n = static_cast<std::uint32_t>(segments);
  // vertices half a segment off +x: the faces of a sector of n | segments then cut facets in
  // their middle, never along an edge (a probe there would see a face on one side and an edge on
  // the other, by round-off)
  for (std::uint32_t j = 0; j < n; ++j) {
    const double a = 2 * kPi * (j + 0.5) / segments;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  for (std::uint32_t j = 0; j < n; ++j) {
    const double a = 2 * kPi * (j + 0.5) / segments;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), height});
  }
  m.vertices.push_back({0, 0, 0});
  const std::uint32_t centre = 2 * n;
  for (std::uint32_t j = 0; j < n; ++j) {
    const std::uint32_t a0 = j, b0 = (j + 1) % n, a1 = a0 + n, b1 = b0 + n;
    m.triangles.push_back({a0, b0, b1});  // shell, normal outwards
    m.triangles.push_back({a0, b1, a1});
    m.triangles.push_back({centre, b0, a0});  // floor, normal along -z
  }
  return m;
}

}  // namespace comminute
