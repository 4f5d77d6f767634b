#include "comminute/geometry/wall_keys.hpp"

namespace comminute {

Vec3 read_unit_vector(const CaseTable& t, std::string_view key, const Vec3& fallback) {
  const Vec3 v = t.vec3(key, Limits::any(), fallback);
  if (norm(v) == 0) t.fail(key, "must not be the zero vector");
  return v / norm(v);
}

}  // namespace comminute
