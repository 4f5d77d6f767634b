#include "comminute/geometry/roll_pair.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/geometry/mesh_pieces.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

// The rolls' rings along y: tiles of at most four facet chords (or width / axial_divisions).
AxialTiling roll_tiling(const RollPairGeometry& g) {
  const double chord = g.diameter * std::sin(std::numbers::pi / g.segments);
  const double target = g.axial_divisions > 0 ? g.width / g.axial_divisions : 4 * chord;
  return axial_tiling(g.width, g.side_plates ? 0.0 : g.overhang, target);
}

// The chute plates' tiles along y, about as long as a plate's slant height.
AxialTiling chute_tiling(const RollPairGeometry& g) {
  const double slant = g.chute_height / std::cos(g.chute_angle);
  if (!g.side_plates) return axial_tiling(g.width, g.overhang, slant);
  const double half = g.width / 2 + g.side_plate_clearance;
  return {half, std::max(1, static_cast<int>(std::ceil(2 * half / slant)))};
}

}  // namespace

void check_roll_pair(const RollPairGeometry& g) {
  if (!(g.diameter > 0)) throw GeometryError("diameter", "the roll diameter must be > 0");
  if (!(g.width > 0)) throw GeometryError("width", "the roll width must be > 0");
  if (!(g.gap > 0)) throw GeometryError("gap", "the gap must be > 0 (the rolls must not touch)");
  if (!(g.gap < g.diameter))
    throw GeometryError("gap", fmt::format("the gap {:.6g} m must be smaller than the roll "
                                           "diameter {:.6g} m",
                                           g.gap, g.diameter));
  if (g.segments < 12) throw GeometryError("segments", "a roll needs at least 12 segments");
  if (g.axial_divisions < 0) throw GeometryError("axial_divisions", "must be >= 0 (0: automatic)");
  if (g.chute) {
    if (!(g.chute_opening > g.gap) || !(g.chute_opening < g.diameter + g.gap))
      throw GeometryError(
          "chute_opening",
          fmt::format("the chute opening {:.6g} m must lie between the gap {:.6g} m and diameter "
                      "+ gap {:.6g} m, so that the plates' lower edges stand over the rolls",
                      g.chute_opening, g.gap, g.diameter + g.gap));
    if (!(g.chute_height > 0)) throw GeometryError("chute_height", "must be > 0");
    if (!(g.chute_angle >= 0 && g.chute_angle < 80 * std::numbers::pi / 180))
      throw GeometryError("chute_angle", "must lie in [0, 80) degrees");
    if (!(g.chute_clearance > 0)) throw GeometryError("chute_clearance", "must be > 0");
  }
  if (g.side_plates && !(g.side_plate_clearance > 0))
    throw GeometryError("side_plate_clearance",
                        "must be > 0: a side plate flush with a roll's end disc would double "
                        "every contact there");
  if (!g.side_plates && !(g.overhang > 0))
    throw GeometryError("overhang", "must be > 0 without side plates");
}

double roll_offset(const RollPairGeometry& g) {
  return g.diameter / 2 + g.gap / 2;
}

int roll_rings(const RollPairGeometry& g) {
  return roll_tiling(g).count;
}

IndexedMesh roll_mesh(const RollPairGeometry& g, int k) {
  check_roll_pair(g);
  const double R = g.diameter / 2, c = roll_offset(g), y = roll_tiling(g).half;
  const auto n = static_cast<std::uint32_t>(g.segments);
  const auto rings = static_cast<std::uint32_t>(roll_rings(g));
  IndexedMesh m;
  // roll 0 at -x, vertex 0 of each ring on the line of centres facing the pinch; counter-clockwise
  // in (x, z); rings from -y to +y
  for (std::uint32_t q = 0; q <= rings; ++q) {
    const double yy = q == rings ? y : -y + 2 * y * q / rings;
    for (std::uint32_t j = 0; j < n; ++j) {
      const double theta = 2 * std::numbers::pi * j / n;
      m.vertices.push_back({-c + R * std::cos(theta), yy, j == 0 ? 0.0 : R * std::sin(theta)});
    }
  }
  const std::uint32_t c0 = (rings + 1) * n, c1 = c0 + 1;
  m.vertices.push_back({-c, -y, 0});
  m.vertices.push_back({-c, y, 0});
  for (std::uint32_t q = 0; q < rings; ++q)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a0 = q * n + i, b0 = q * n + (i + 1) % n, a1 = a0 + n, b1 = b0 + n;
      m.triangles.push_back({a0, b1, b0});  // mantle, normal away from the axis
      m.triangles.push_back({a0, a1, b1});
    }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t a0 = i, b0 = (i + 1) % n, a1 = rings * n + i, b1 = rings * n + (i + 1) % n;
    m.triangles.push_back({c0, a0, b0});  // end at -y: counter-clockwise in (x, z) is -y
    m.triangles.push_back({c1, b1, a1});  // end at +y
  }
  if (k == 1) {  // the mirror image in x = 0, orientation restored
    for (Vec3& v : m.vertices) v.x = -v.x;
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
  }
  return m;
}

double chute_bottom(const RollPairGeometry& g) {
  const double R = g.diameter / 2, s = roll_offset(g) - g.chute_opening / 2;
  return std::sqrt(std::max(0.0, R * R - s * s)) + g.chute_clearance;
}

IndexedMesh chute_mesh(const RollPairGeometry& g) {
  check_roll_pair(g);
  IndexedMesh m;
  if (!g.chute) return m;
  const AxialTiling tiles = chute_tiling(g);
  const double y = tiles.half, z0 = chute_bottom(g), z1 = z0 + g.chute_height;
  const double x0 = g.chute_opening / 2, x1 = x0 + g.chute_height * std::tan(g.chute_angle);
  for (double s : {-1.0, 1.0})
    add_grid(m, {s * x0, -y, z0}, {0, 2 * y, 0}, {s * (x1 - x0), 0, z1 - z0}, tiles.count, 1,
             {-s, 0, 0});
  return m;
}

IndexedMesh side_plates_mesh(const RollPairGeometry& g) {
  check_roll_pair(g);
  IndexedMesh m;
  if (!g.side_plates) return m;
  const double R = g.diameter / 2, y = g.width / 2 + g.side_plate_clearance;
  double x = roll_offset(g) + R, top = R;
  if (g.chute) {
    x = std::max(x, g.chute_opening / 2 + g.chute_height * std::tan(g.chute_angle));
    top = std::max(top, chute_bottom(g) + g.chute_height);
  }
  for (double s : {-1.0, 1.0})
    add_grid(m, {-x, s * y, -R}, {2 * x, 0, 0}, {0, 0, top + R}, 1, 1, {0, -s, 0});
  return m;
}

}  // namespace comminute
