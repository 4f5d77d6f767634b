#include "comminute/geometry/triangle_bins.hpp"

#include <algorithm>
#include <cmath>

namespace comminute {

std::array<std::int64_t, 3> TriangleBins::cell_of(const Vec3& p) const {
  std::array<std::int64_t, 3> c{};
  for (int a = 0; a < 3; ++a) {
    double f = std::floor((p[a] - origin_[a]) / h_);
    if (!(f > 0)) f = 0;  // also NaN: a non-finite particle is reported after the step
    if (!(f < static_cast<double>(n_[a] - 1))) f = static_cast<double>(n_[a] - 1);
    c[a] = static_cast<std::int64_t>(f);
  }
  return c;
}

void TriangleBins::build(const std::vector<Vec3>& v,
                         const std::vector<std::array<std::uint32_t, 3>>& tris) {
  Vec3 lo = v.at(0), hi = v.at(0);
  for (const Vec3& p : v)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  double mean = 0;
  for (const auto& t : tris) {
    const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
    mean += std::sqrt(std::max({norm2(b - a), norm2(c - b), norm2(a - c)}));
  }
  mean /= static_cast<double>(tris.size());
  const Vec3 span = hi - lo;
  const double largest = std::max({span.x, span.y, span.z});
  h_ = std::max(mean, 1e-9 * largest);
  if (!(h_ > 0)) h_ = 1;
  const double limit = 4.0 * static_cast<double>(tris.size()) + 64;
  for (int grow = 0; grow < 4000; ++grow) {  // (a finite span needs far fewer)
    double cells = 1;
    for (int a = 0; a < 3; ++a) cells *= std::floor(span[a] / h_) + 1;
    if (cells <= limit) break;
    h_ *= 1.25;
  }
  origin_ = lo;
  for (int a = 0; a < 3; ++a) n_[a] = static_cast<std::int64_t>(std::floor(span[a] / h_)) + 1;
  const std::size_t ncell = static_cast<std::size_t>(n_[0] * n_[1] * n_[2]);
  std::vector<std::array<std::int64_t, 6>> box(tris.size());
  start_.assign(ncell + 1, 0);
  auto each_cell = [&](const std::array<std::int64_t, 6>& b, auto&& f) {
    for (std::int64_t z = b[2]; z <= b[5]; ++z)
      for (std::int64_t y = b[1]; y <= b[4]; ++y)
        for (std::int64_t x = b[0]; x <= b[3]; ++x)
          f(static_cast<std::size_t>((z * n_[1] + y) * n_[0] + x));
  };
  for (std::size_t t = 0; t < tris.size(); ++t) {
    Vec3 tlo = v[tris[t][0]], thi = tlo;
    for (int k = 1; k < 3; ++k)
      for (int a = 0; a < 3; ++a) {
        tlo[a] = std::min(tlo[a], v[tris[t][k]][a]);
        thi[a] = std::max(thi[a], v[tris[t][k]][a]);
      }
    const auto c0 = cell_of(tlo), c1 = cell_of(thi);
    box[t] = {c0[0], c0[1], c0[2], c1[0], c1[1], c1[2]};
    each_cell(box[t], [&](std::size_t c) { ++start_[c + 1]; });
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  items_.assign(start_.back(), 0);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < tris.size(); ++t)
    each_cell(box[t], [&](std::size_t c) { items_[fill[c]++] = static_cast<std::uint32_t>(t); });
}

void TriangleBins::query(const Vec3& lo, const Vec3& hi, std::vector<std::uint32_t>& out) const {
  for (int a = 0; a < 3; ++a)  // the box misses the grid (the mesh) entirely
    if (hi[a] < origin_[a] || lo[a] > origin_[a] + static_cast<double>(n_[a]) * h_) return;
  const auto c0 = cell_of(lo), c1 = cell_of(hi);
  for (std::int64_t z = c0[2]; z <= c1[2]; ++z)
    for (std::int64_t y = c0[1]; y <= c1[1]; ++y)
      for (std::int64_t x = c0[0]; x <= c1[0]; ++x) {
        const std::size_t c = static_cast<std::size_t>((z * n_[1] + y) * n_[0] + x);
        out.insert(out.end(), items_.begin() + start_[c], items_.begin() + start_[c + 1]);
      }
}

std::size_t TriangleBins::bytes() const {
  return (start_.capacity() + items_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace comminute
