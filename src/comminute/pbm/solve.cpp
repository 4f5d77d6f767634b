#include "comminute/pbm/solve.hpp"

#include "comminute/core/error.hpp"

namespace comminute::pbm {

std::vector<Eigen::VectorXd> solve(const OdeSystem& system, Integrator& integrator,
                                   Eigen::VectorXd y0, const std::vector<double>& times) {
  std::vector<Eigen::VectorXd> out;
  double t = 0;
  for (double te : times) {
    if (te < t) throw Error("solve: output times must be non-decreasing and >= 0");
    integrator.advance(system, t, te, y0);
    out.push_back(y0);
  }
  return out;
}

}  // namespace comminute::pbm
