#pragma once
// The linear breakage equation ∂f/∂t = ∫_v^∞ p(v,y) S(y) f(y) dy − S(v) f(v) discretised by the
// method of classes with the number- and mass-preserving weights of Kumar et al. (weighted finite
// volume scheme; J. Kumar, Saha & Tsotsas, SIAM J. Numer. Anal. 53 (2015) 1672; as used in
// Skorych et al., Processes 7 (2019) 535 / Dyssol's Crusher PBM TM):
//   dN_i/dt = Σ_{k≥i} ω^b_k S_k B_{i,k} N_k − ω^d_i S_i N_i
//   B_{i,k} = fragments of a parent at pivot x_k born in class i below min(x_{i+½}, x_k)
//   ω^b_k = x_k (ν_k − 1) / Σ_{i<k} (x_k − x_i) B_{i,k},   ω^d_k = (ω^b_k/x_k) Σ_{i≤k} x_i B_{i,k}
// Fragments below the grid are counted in the finest class; the finest class never breaks
// (ω = 0 there). Without the correction ω = 1. Functions defined by mass only are discretised by
// lumping each class's fragment mass at its pivot (B_{i,k} = x_k ΔB / x_i), for which the weights
// are exactly 1.
#include <Eigen/Dense>
#include <vector>

#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/ode.hpp"
#include "comminute/pbm/selection_function.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

class MethodOfClasses {
 public:
  MethodOfClasses(const SizeGrid& grid, const SelectionFunction& rate,
                  const BreakageFunction& function, bool kumar_correction = true);

  // y = number of particles per class N_i.
  LinearOde system() const { return LinearOde(a_); }
  const std::vector<double>& rates() const { return s_; }
  const std::vector<double>& fragments() const { return nu_; }  // ν_k
  const std::vector<double>& birth_weights() const { return wb_; }
  const std::vector<double>& death_weights() const { return wd_; }
  const Eigen::MatrixXd& birth_matrix() const { return b_; }  // B_{i,k}
  const Eigen::MatrixXd& matrix() const { return a_; }        // dN/dt = A N

 private:
  std::vector<double> s_, nu_, wb_, wd_;
  Eigen::MatrixXd b_, a_;
};

}  // namespace comminute::pbm
