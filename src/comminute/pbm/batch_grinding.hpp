#pragma once
// Austin's size–mass balance of batch grinding (Austin, Klimpel & Luckie 1984):
//   dw_i/dt = −S_i w_i + Σ_{j>i} b_ij S_j w_j
// w_i mass fraction in class i; classes fine (0) to coarse (n−1), unlike Austin's numbering from
// the top; the finest class is the sink. Austin's sieve conventions are kept when built from
// models: S_i at the class's upper size, and b_ij = B(top_i, D_j) − B(bottom_i, D_j) with D_j the
// parent class's lower size, so that everything broken leaves its class (B_{j+1,j} = 1) and
// Σ_i b_ij = 1; the finest class takes every fragment below the grid.
#include <Eigen/Dense>
#include <vector>

#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/ode.hpp"
#include "comminute/pbm/selection_function.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

class BatchGrinding {
 public:
  // rates S_i (1/s, ≥ 0) and b (b(i, j) for i < j; columns j ≥ 1 sum to 1).
  BatchGrinding(std::vector<double> rates, Eigen::MatrixXd b);
  static BatchGrinding from_models(const SizeGrid& grid, const SelectionFunction& rate,
                                   const BreakageFunction& function);

  // y = mass (or mass fraction) per class.
  LinearOde system() const;
  const std::vector<double>& rates() const { return s_; }
  const Eigen::MatrixXd& breakage() const { return b_; }

 private:
  std::vector<double> s_;
  Eigen::MatrixXd b_;
};

}  // namespace comminute::pbm
