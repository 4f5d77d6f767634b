#include "comminute/geometry/mesh_pieces.hpp"

#include <algorithm>
#include <cmath>

namespace comminute {

void add_grid(IndexedMesh& m, const Vec3& o, const Vec3& u, const Vec3& v, int nu, int nv,
              const Vec3& facing) {
  const auto b = static_cast<std::uint32_t>(m.vertices.size());
  const auto cu = static_cast<std::uint32_t>(nu), cv = static_cast<std::uint32_t>(nv);
  for (std::uint32_t j = 0; j <= cv; ++j)
    for (std::uint32_t i = 0; i <= cu; ++i)
      m.vertices.push_back(o + u * (static_cast<double>(i) / nu) +
                           v * (static_cast<double>(j) / nv));
  const bool along = dot(cross(u, v), facing) >= 0;
  auto at = [&](std::uint32_t i, std::uint32_t j) { return b + j * (cu + 1) + i; };
  for (std::uint32_t j = 0; j < cv; ++j)
    for (std::uint32_t i = 0; i < cu; ++i) {
      const std::uint32_t a = at(i, j), p = at(i + 1, j), q = at(i + 1, j + 1), r = at(i, j + 1);
      if (along) {
        m.triangles.push_back({a, p, q});
        m.triangles.push_back({a, q, r});
      } else {
        m.triangles.push_back({a, q, p});
        m.triangles.push_back({a, r, q});
      }
    }
}

AxialTiling axial_tiling(double width, double overhang, double target) {
  const int m = std::max(1, static_cast<int>(std::ceil(width / target - 1e-9)));
  const double tile = width / m;
  const int over = overhang > 0 ? static_cast<int>(std::ceil(overhang / tile - 1e-9)) : 0;
  return {width / 2 + over * tile, m + 2 * over};
}

void append(IndexedMesh& m, const IndexedMesh& part) {
  const auto b = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const auto& t : part.triangles) m.triangles.push_back({t[0] + b, t[1] + b, t[2] + b});
}

Vec3 triangle_normal(const IndexedMesh& m, std::size_t t) {
  const auto& tri = m.triangles[t];
  const Vec3 n =
      cross(m.vertices[tri[1]] - m.vertices[tri[0]], m.vertices[tri[2]] - m.vertices[tri[0]]);
  return n / norm(n);
}

}  // namespace comminute
