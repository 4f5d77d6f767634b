#include "comminute/analysis/stress_measures.hpp"

#include <Eigen/Eigenvalues>

namespace comminute::analysis {

StressMeasures stress_measures(const SymTensor& s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d ev = eig.eigenvalues();  // increasing
  StressMeasures r;
  r.principal = {ev[2], ev[1], ev[0]};
  r.mean = (s[0] + s[1] + s[2]) / 3;
  r.tau_max = 0.5 * (ev[2] - ev[0]);
  return r;
}

}  // namespace comminute::analysis
