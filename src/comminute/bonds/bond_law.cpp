#include "comminute/bonds/bond_law.hpp"

namespace comminute::bonds {

Vec3 rotate_with(const Vec3& v, const Vec3& a, const Vec3& b) {
  // Rodrigues' formula with k = a x b (|k| = sin θ), c = a·b = cos θ:
  // R v = c v + k x v + k (k·v) / (1 + c)
  const Vec3 k = cross(a, b);
  const double c = dot(a, b);
  if (c <= -1.0 + 1e-12) return v;  // a half turn in one step: no rotation is defined
  return c * v + cross(k, v) + k * (dot(k, v) / (1.0 + c));
}

}  // namespace comminute::bonds
