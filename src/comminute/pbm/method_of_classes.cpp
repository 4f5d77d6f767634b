#include "comminute/pbm/method_of_classes.hpp"

namespace comminute::pbm {

MethodOfClasses::MethodOfClasses(const SizeGrid& grid, const SelectionFunction& rate,
                                 const BreakageFunction& function, bool kumar_correction) {
  const std::size_t n = grid.classes();
  const auto ni = static_cast<Eigen::Index>(n);
  s_.resize(n);
  nu_.assign(n, 0.0);
  wb_.assign(n, 1.0);
  wd_.assign(n, 1.0);
  b_ = Eigen::MatrixXd::Zero(ni, ni);
  a_ = Eigen::MatrixXd::Zero(ni, ni);
  for (std::size_t k = 0; k < n; ++k) {
    const double y = grid.pivot_volume(k);
    s_[k] = rate.rate(grid.pivot_size(k), y);
    const bool by_number = function.cumulative_number(y, y).has_value();
    for (std::size_t i = 0; i <= k; ++i) {
      const double lo = i == 0 ? 0.0 : grid.volume_edge(i);
      const double hi = i == k ? y : grid.volume_edge(i + 1);
      double bik = 0;
      if (by_number)
        bik = *function.cumulative_number(hi, y) - *function.cumulative_number(lo, y);
      else
        bik = y * (function.cumulative_mass(hi, y) - function.cumulative_mass(lo, y)) /
              grid.pivot_volume(i);
      b_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = bik;
      nu_[k] += bik;
    }
    if (kumar_correction) {
      double denom = 0, mass = 0;
      for (std::size_t i = 0; i <= k; ++i) {
        const double bik = b_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
        if (i < k) denom += (y - grid.pivot_volume(i)) * bik;
        mass += grid.pivot_volume(i) * bik;
      }
      // Finest class, or every fragment inside the parent's own class: nothing can be born
      // below, so the class cannot break on this grid without violating mass or number.
      wb_[k] = denom > 0 ? y * (nu_[k] - 1) / denom : 0.0;
      wd_[k] = wb_[k] / y * mass;
    }
    for (std::size_t i = 0; i <= k; ++i)
      a_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) +=
          wb_[k] * s_[k] * b_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
    a_(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)) -= wd_[k] * s_[k];
  }
}

}  // namespace comminute::pbm
