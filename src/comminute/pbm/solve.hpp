#pragma once
// Integrates an OdeSystem from t = 0 and returns the state at each requested time.
#include <Eigen/Dense>
#include <vector>

#include "comminute/pbm/integrator.hpp"
#include "comminute/pbm/ode.hpp"

namespace comminute::pbm {

// times: non-decreasing, ≥ 0.
std::vector<Eigen::VectorXd> solve(const OdeSystem& system, Integrator& integrator,
                                   Eigen::VectorXd y0, const std::vector<double>& times);

}  // namespace comminute::pbm
