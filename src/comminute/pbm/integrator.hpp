#pragma once
// Time integrators for OdeSystem: classical RK4 with a fixed step and the adaptive embedded
// Dormand–Prince 5(4) pair with error control. The case file picks one by name.
#include <Eigen/Dense>
#include <cstddef>

#include "comminute/pbm/ode.hpp"

namespace comminute::pbm {

struct IntegratorStats {
  std::size_t steps = 0, rejected = 0, evaluations = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances y from t to t_end (t is updated to t_end).
  virtual void advance(const OdeSystem& sys, double& t, double t_end, Eigen::VectorXd& y) = 0;
  const IntegratorStats& stats() const { return stats_; }

 protected:
  IntegratorStats stats_;
};

// Classical Runge–Kutta 4 with step ≤ time_step (each interval split into equal steps).
class Rk4 : public Integrator {
 public:
  explicit Rk4(double time_step) : h_(time_step) {}
  void advance(const OdeSystem& sys, double& t, double t_end, Eigen::VectorXd& y) override;

 private:
  double h_;
  Eigen::VectorXd k1_, k2_, k3_, k4_, tmp_;
};

// Dormand & Prince (J. Comput. Appl. Math. 6 (1980) 19) 5(4) with FSAL and the usual
// controller h ← h·clamp(0.9·err^(−1/5), 0.2, 5); err is the RMS of e_i/(atol + rtol·|y_i|)
// with atol = absolute_tolerance × max|y| at the start of each advance (scale-free).
class DormandPrince : public Integrator {
 public:
  struct Options {
    double relative_tolerance = 1e-6;
    double absolute_tolerance = 1e-12;
    std::size_t max_steps = 1000000;
  };
  explicit DormandPrince(Options o) : o_(o) {}
  void advance(const OdeSystem& sys, double& t, double t_end, Eigen::VectorXd& y) override;

 private:
  Options o_;
  double h_ = 0;  // last accepted step size, kept between calls
  Eigen::VectorXd k_[7], y_new_, tmp_;
  bool have_fsal_ = false;
};

}  // namespace comminute::pbm
