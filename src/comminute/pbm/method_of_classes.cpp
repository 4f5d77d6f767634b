#include "comminute/pbm/method_of_classes.hpp"

#include <map>

namespace comminute::pbm {

// Method of classes with the number- and mass-preserving weights of Kumar et al.
// (docs/models.md eq. B1).
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
  std::map<const BreakageFunction*, std::vector<double>> tables;  // see below
  for (std::size_t k = 0; k < n; ++k) {
    const double y = grid.pivot_volume(k);
    s_[k] = rate.rate(grid.pivot_size(k), y);
    const BreakageFunction& fk = function.of_parent(y);
    const bool by_number = fk.cumulative_number(y, y).has_value();
    auto cumulative = [&](double v, double parent) {
      return by_number ? *fk.cumulative_number(v, parent) : fk.cumulative_mass(v, parent);
    };
    // Cumulative at the edges below the pivot and at the pivot. On a grid geometric in volume a
    // homogeneous function has edge_i/x_k = edge_{i+n−1−k}/x_{n−1}, so one table per function
    // (relative to the coarsest pivot) serves every parent.
    std::vector<double> upper(k + 1);
    if (grid.geometric_in_volume() && fk.homogeneous()) {
      auto [it, fresh] = tables.try_emplace(&fk);
      if (fresh) {
        const double top = grid.pivot_volume(n - 1);
        for (std::size_t j = 1; j < n; ++j)
          it->second.push_back(cumulative(grid.volume_edge(j), top));
        it->second.push_back(cumulative(top, top));
      }
      for (std::size_t i = 0; i < k; ++i) upper[i] = it->second[i + n - 1 - k];
      upper[k] = it->second.back();
    } else {
      for (std::size_t i = 0; i <= k; ++i)
        upper[i] = cumulative(i == k ? y : grid.volume_edge(i + 1), y);
    }
    double below = 0;  // everything under the grid falls into the finest class
    for (std::size_t i = 0; i <= k; ++i) {
      double bik = upper[i] - below;
      below = upper[i];
      if (!by_number) bik *= y / grid.pivot_volume(i);
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
