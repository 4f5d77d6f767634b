#include "comminute/geometry/region.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/units.hpp"

namespace comminute {

double Region::volume() const {
  if (shape == Shape::box) return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  return units::pi * radius * radius * length;
}

bool Region::contains(const Vec3& x, double r) const {
  if (shape == Shape::box) {
    for (int a = 0; a < 3; ++a)
      if (x[a] - r < lo[a] || x[a] + r > hi[a]) return false;
    return true;
  }
  const Vec3 d = x - center;
  const double s = dot(d, axis);
  return std::abs(s) + r <= 0.5 * length && norm(d - s * axis) + r <= radius;
}

void Region::bounds(Vec3& lo_out, Vec3& hi_out) const {
  if (shape == Shape::box) {
    lo_out = lo;
    hi_out = hi;
    return;
  }
  for (int a = 0; a < 3; ++a) {
    // extent of a cylinder along axis a: half-length |axis_a| + radius sqrt(1 - axis_a^2)
    const double e =
        0.5 * length * std::abs(axis[a]) + radius * std::sqrt(std::max(0.0, 1 - axis[a] * axis[a]));
    lo_out[a] = center[a] - e;
    hi_out[a] = center[a] + e;
  }
}

Vec3 Region::sample(Rng& rng, double r) const {
  Vec3 a, b;
  bounds(a, b);
  for (int tries = 0; tries < 1000; ++tries) {
    Vec3 x{rng.uniform(a.x + r, b.x - r), rng.uniform(a.y + r, b.y - r),
           rng.uniform(a.z + r, b.z - r)};
    if (contains(x, r)) return x;
  }
  return 0.5 * (a + b);
}

}  // namespace comminute
