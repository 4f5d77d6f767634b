#include "comminute/pbm/batch_grinding.hpp"

#include "comminute/core/error.hpp"

namespace comminute::pbm {

BatchGrinding::BatchGrinding(std::vector<double> rates, Eigen::MatrixXd b)
    : s_(std::move(rates)), b_(std::move(b)) {
  const auto n = static_cast<Eigen::Index>(s_.size());
  if (b_.rows() != n || b_.cols() != n) throw Error("BatchGrinding: b must be n × n");
  for (double s : s_)
    if (!(s >= 0)) throw Error("BatchGrinding: negative or non-finite rate");
}

BatchGrinding BatchGrinding::from_models(const SizeGrid& grid, const SelectionFunction& rate,
                                         const BreakageFunction& function) {
  const std::size_t n = grid.classes();
  std::vector<double> s(n);
  Eigen::MatrixXd b =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) {
    s[j] = rate.rate(grid.size_edge(j + 1), grid.volume_edge(j + 1));
    const double parent = grid.volume_edge(j);  // D_j, the parent class's lower size
    for (std::size_t i = 0; i < j; ++i) {
      const double lo = i == 0 ? 0.0 : grid.volume_edge(i);
      b(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          function.cumulative_mass(grid.volume_edge(i + 1), parent) -
          function.cumulative_mass(lo, parent);
    }
  }
  s[0] = 0;  // the sink
  return BatchGrinding(std::move(s), std::move(b));
}

// Austin, Klimpel & Luckie (1984), docs/models.md eq. G1: dw_i/dt = −S_i w_i + Σ_j b_ij S_j w_j.
LinearOde BatchGrinding::system() const {
  const auto n = static_cast<Eigen::Index>(s_.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < j; ++i) a(i, j) = b_(i, j) * s_[static_cast<std::size_t>(j)];
    a(j, j) = -s_[static_cast<std::size_t>(j)];
  }
  return LinearOde(std::move(a));
}

}  // namespace comminute::pbm
