#include "comminute/neighbor/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace comminute {

namespace {
// floor(v) as a cell count: clamped in floating point before the conversion (a far-away or
// non-finite coordinate must not overflow the int).
int cells_along(double v) {
  if (!(v > 0)) return 0;  // also NaN
  return static_cast<int>(std::min(std::floor(v), 1e9));
}
}  // namespace

void CellGrid::build(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& subset,
                     double edge) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (auto s : subset)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[s][a]);
      hi[a] = std::max(hi[a], x[s][a]);
    }
  if (subset.empty()) lo = hi = Vec3{};
  lo_ = lo;
  // a zero, negative or non-finite edge would never give a finite grid
  edge_ = std::isfinite(edge) && edge > 0 ? edge : std::max(1.0, hi.x - lo.x);
  const double max_cells = 8.0 * static_cast<double>(subset.size()) + 27.0;
  while (true) {
    double cells = 1;
    for (int a = 0; a < 3; ++a) {
      dims_[a] = std::max(1, cells_along((hi[a] - lo[a]) / edge_) + 1);
      cells *= dims_[a];
    }
    if (cells <= max_cells) break;
    edge_ *= 1.26;  // doubles the cell volume
  }
  const std::size_t ncell = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  start_.assign(ncell + 1, 0);
  std::vector<std::uint32_t> cell(subset.size());
  for (std::size_t k = 0; k < subset.size(); ++k) {
    auto c = cell_of(x[subset[k]]);
    cell[k] = static_cast<std::uint32_t>(index(c[0], c[1], c[2]));
    ++start_[cell[k] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  items_.resize(subset.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < subset.size(); ++k) items_[fill[cell[k]]++] = subset[k];
}

std::array<int, 3> CellGrid::cell_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a)
    c[a] = std::clamp(cells_along((p[a] - lo_[a]) / edge_), 0, dims_[a] - 1);
  return c;
}

}  // namespace comminute
