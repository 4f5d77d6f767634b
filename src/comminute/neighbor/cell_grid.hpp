#pragma once
// A uniform grid of cubic cells over the bounding box of a set of points, filled by counting sort
// (cell_start / items arrays: the particles of cell c are items[cell_start[c] .. cell_start[c+1])).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

class CellGrid {
 public:
  // Bins the points x[s] for s in `subset`; `edge` is the requested cell edge (m). The edge is
  // enlarged if the grid would have more than ~8 cells per point.
  void build(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& subset, double edge);

  double edge() const { return edge_; }
  std::array<int, 3> cell_of(const Vec3& p) const;  // clamped to the grid
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
  }
  const std::array<int, 3>& dims() const { return dims_; }
  const std::vector<std::uint32_t>& cell_start() const { return start_; }
  const std::vector<std::uint32_t>& items() const { return items_; }
  // Calls f(cell index) for the cells within `reach` cells of cell c (per axis).
  template <class F>
  void visit_cells_around(const std::array<int, 3>& c, int reach, F&& f) const {
    for (int k = std::max(0, c[2] - reach); k <= std::min(dims_[2] - 1, c[2] + reach); ++k)
      for (int j = std::max(0, c[1] - reach); j <= std::min(dims_[1] - 1, c[1] + reach); ++j)
        for (int i = std::max(0, c[0] - reach); i <= std::min(dims_[0] - 1, c[0] + reach); ++i)
          f(index(i, j, k));
  }
  // Visits the items of the cells within `reach` cells of cell c, in the order of
  // visit_cells_around. The cells of a row along x are consecutive in `items`, so each row is one
  // stretch of items (9 loops for the 27-cell stencil instead of 27).
  template <class F>
  void visit_around(const std::array<int, 3>& c, int reach, F&& f) const {
    const int i0 = std::max(0, c[0] - reach), i1 = std::min(dims_[0] - 1, c[0] + reach);
    if (i0 > i1) return;
    for (int k = std::max(0, c[2] - reach); k <= std::min(dims_[2] - 1, c[2] + reach); ++k)
      for (int j = std::max(0, c[1] - reach); j <= std::min(dims_[1] - 1, c[1] + reach); ++j) {
        const std::uint32_t q1 = start_[index(i1, j, k) + 1];
        for (std::uint32_t q = start_[index(i0, j, k)]; q < q1; ++q) f(items_[q]);
      }
  }

 private:
  Vec3 lo_;
  double edge_ = 1;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::uint32_t> start_, items_;
};

}  // namespace comminute
