#pragma once
// Rigid-body rotation of points and directions (Rodrigues' formula).
#include <cmath>

#include "comminute/core/vec3.hpp"

namespace comminute {

// Rotates v by |rotation| radians about the unit axis rotation/|rotation|.
inline Vec3 rotate(const Vec3& v, const Vec3& rotation) {
  const double angle = norm(rotation);
  if (angle == 0.0) return v;
  const Vec3 k = rotation / angle;
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

// Any unit vector perpendicular to unit n.
inline Vec3 perpendicular(const Vec3& n) {
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 p = cross(n, a);
  return p / norm(p);
}

}  // namespace comminute
