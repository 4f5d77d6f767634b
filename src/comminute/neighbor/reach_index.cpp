#include "comminute/neighbor/reach_index.hpp"

#include <algorithm>

namespace comminute {

void ReachIndex::adopt(CellGrid small, CellGrid large, bool has_large, double r_small,
                       double r_large, std::size_t n) {
  small_ = std::move(small);
  large_ = std::move(large);
  has_large_ = has_large;
  r_small_ = r_small;
  r_large_ = r_large;
  r_extra_ = 0;
  slot_.resize(n);
  for (std::size_t s = 0; s < n; ++s) slot_[s] = static_cast<std::uint32_t>(s);
  n_build_ = n;
  extra_head_.clear();
  extra_next_.clear();
  valid_ = true;
}

void ReachIndex::build(const std::vector<Vec3>& x, const std::vector<double>& r, double skin) {
  std::vector<std::uint32_t> all(x.size());
  for (std::size_t s = 0; s < x.size(); ++s) all[s] = static_cast<std::uint32_t>(s);
  const double r_max = r.empty() ? 0.0 : *std::max_element(r.begin(), r.end());
  CellGrid g;
  g.build(x, all, 2 * r_max + skin);
  adopt(std::move(g), CellGrid{}, false, r_max, 0.0, x.size());
}

void ReachIndex::remap(const std::vector<std::uint32_t>& to_new) {
  const auto n = static_cast<std::ptrdiff_t>(slot_.size());
#pragma omp parallel for schedule(static) if (n >= 16384)
  for (std::ptrdiff_t e = 0; e < n; ++e) {
    auto& s = slot_[static_cast<std::size_t>(e)];
    if (s != none) s = s < to_new.size() ? to_new[s] : none;
  }
}

void ReachIndex::insert(std::uint32_t slot, const Vec3& x, double r) {
  if (extra_head_.empty()) {
    const auto& d = small_.dims();
    extra_head_.assign(static_cast<std::size_t>(d[0]) * d[1] * d[2], none);
  }
  const auto c = small_.cell_of(x);
  std::uint32_t& head = extra_head_[small_.index(c[0], c[1], c[2])];
  extra_next_.push_back(head);
  head = static_cast<std::uint32_t>(slot_.size());
  slot_.push_back(slot);
  r_extra_ = std::max(r_extra_, r);
}

}  // namespace comminute
