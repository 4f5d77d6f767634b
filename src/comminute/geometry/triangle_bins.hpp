#pragma once
// A uniform cell grid over the triangles of a mesh, in the mesh's own (body) frame so that a rigid
// motion never re-bins: each triangle is listed in every cell its bounding box overlaps (CSR
// layout). The cell edge is the mean longest-edge of the triangles, enlarged until the grid has at
// most 4 cells per triangle (plus 64), so memory stays linear in the triangle count from 10^4 to
// 10^6 triangles and a sphere query visits a few cells.
#include <array>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

class TriangleBins {
 public:
  void build(const std::vector<Vec3>& vertices,
             const std::vector<std::array<std::uint32_t, 3>>& triangles);
  // Appends (unsorted, possibly repeated) the triangles listed in the cells the box [lo, hi]
  // overlaps.
  void query(const Vec3& lo, const Vec3& hi, std::vector<std::uint32_t>& out) const;
  double cell_size() const { return h_; }
  std::size_t bytes() const;

 private:
  Vec3 origin_;
  double h_ = 1;
  std::array<std::int64_t, 3> n_{1, 1, 1};
  std::vector<std::uint32_t> start_;  // per cell, + 1
  std::vector<std::uint32_t> items_;
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const;
};

}  // namespace comminute
