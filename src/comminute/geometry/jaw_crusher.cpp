#include "comminute/geometry/jaw_crusher.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/geometry/mesh_pieces.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

// The jaws' tiles along y, about as wide as a strip is high.
AxialTiling jaw_tiling(const JawCrusherGeometry& g) {
  return axial_tiling(g.width, g.side_plates ? 0.0 : g.overhang, g.height / g.divisions);
}

}  // namespace

void check_jaw_crusher(const JawCrusherGeometry& g) {
  if (!(g.height > 0)) throw GeometryError("height", "the jaw height must be > 0");
  if (!(g.width > 0)) throw GeometryError("width", "the jaw width must be > 0");
  if (!(g.closed_side_setting > 0))
    throw GeometryError("closed_side_setting", "must be > 0 (the jaws must not touch)");
  if (!(g.jaw_throw > 0)) throw GeometryError("throw", "must be > 0");
  if (!(g.gape > g.closed_side_setting + g.jaw_throw))
    throw GeometryError(
        "gape", fmt::format("the gape {:.6g} m must exceed closed_side_setting + throw = {:.6g} m "
                            "(the jaws converge downwards at the open side too)",
                            g.gape, g.closed_side_setting + g.jaw_throw));
  if (g.divisions < 1) throw GeometryError("divisions", "must be at least 1");
  if (!g.side_plates && !(g.overhang > 0))
    throw GeometryError("overhang", "must be > 0 without side plates");
}

IndexedMesh fixed_jaw_mesh(const JawCrusherGeometry& g) {
  check_jaw_crusher(g);
  const AxialTiling tiles = jaw_tiling(g);
  const double y = tiles.half;
  IndexedMesh m;
  add_grid(m, {0, -y, 0}, {0, 2 * y, 0}, {0, 0, g.height}, tiles.count, g.divisions, {1, 0, 0});
  return m;
}

IndexedMesh swing_jaw_mesh(const JawCrusherGeometry& g) {
  check_jaw_crusher(g);
  const AxialTiling tiles = jaw_tiling(g);
  const double y = tiles.half;
  IndexedMesh m;
  add_grid(m, {g.closed_side_setting, -y, 0}, {0, 2 * y, 0},
           {g.gape - g.closed_side_setting, 0, g.height}, tiles.count, g.divisions, {-1, 0, 0});
  return m;
}

IndexedMesh cheek_plates_mesh(const JawCrusherGeometry& g) {
  check_jaw_crusher(g);
  IndexedMesh m;
  if (!g.side_plates) return m;
  for (double s : {-1.0, 1.0})
    add_grid(m, {0, s * g.width / 2, 0}, {g.gape, 0, 0}, {0, 0, g.height}, 1, 1, {0, -s, 0});
  return m;
}

Vec3 jaw_pivot(const JawCrusherGeometry& g) {
  return {g.gape, 0, g.height};
}

double jaw_opening_angle(const JawCrusherGeometry& g) {
  check_jaw_crusher(g);
  // docs/models.md eq. J2 (geometry of the swing, ours):
  // bottom edge relative to the pivot: (-dx, -H) = -L (sin beta, cos beta); turned by a about +y
  // its x is -L sin(beta + a), which is css + throw - gape at a = alpha_open
  const double dx = g.gape - g.closed_side_setting, L = std::hypot(dx, g.height);
  const double beta = std::atan2(dx, g.height);
  return std::asin((dx - g.jaw_throw) / L) - beta;
}

}  // namespace comminute
