#include "comminute/pbm/integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

void Rk4::advance(const OdeSystem& sys, double& t, double t_end, Eigen::VectorXd& y) {
  if (!(t_end > t)) return;
  const double steps = std::ceil((t_end - t) / h_ * (1 - 1e-12));
  if (!(steps >= 1 && steps <= 1e12))  // checked before the conversion (NaN, inf, overflow)
    throw Error(fmt::format("RK4: {} steps of {} s from t = {} s to {} s", steps, h_, t, t_end));
  const auto n = static_cast<std::size_t>(steps);
  const double h = (t_end - t) / static_cast<double>(n);
  const double t0 = t;
  for (std::size_t s = 0; s < n; ++s) {
    const double ts = t0 + h * static_cast<double>(s);
    sys.derivative(ts, y, k1_);
    tmp_ = y + 0.5 * h * k1_;
    sys.derivative(ts + 0.5 * h, tmp_, k2_);
    tmp_ = y + 0.5 * h * k2_;
    sys.derivative(ts + 0.5 * h, tmp_, k3_);
    tmp_ = y + h * k3_;
    sys.derivative(ts + h, tmp_, k4_);
    y += (h / 6.0) * (k1_ + 2.0 * k2_ + 2.0 * k3_ + k4_);
    stats_.evaluations += 4;
    ++stats_.steps;
  }
  t = t_end;
}

namespace {
// Dormand–Prince 5(4) tableau.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                 b6 = 11.0 / 84;
// error coefficients b − b̂
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
}  // namespace

void DormandPrince::advance(const OdeSystem& sys, double& t, double t_end, Eigen::VectorXd& y) {
  if (!(t_end > t)) return;
  const double atol = o_.absolute_tolerance * std::max(y.cwiseAbs().maxCoeff(), 1e-300);
  const double rtol = o_.relative_tolerance;
  auto& k1 = k_[0];
  if (!have_fsal_ || k1.size() != y.size()) {
    sys.derivative(t, y, k1);
    ++stats_.evaluations;
    have_fsal_ = true;
  }
  if (h_ <= 0) {  // Hairer's simple guess: h = 0.01 ‖y‖/‖y'‖ in the error norm
    const Eigen::ArrayXd sc = atol + rtol * y.array().abs();
    const double d0 = std::sqrt((y.array() / sc).square().mean());
    const double d1 = std::sqrt((k1.array() / sc).square().mean());
    h_ = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  }
  auto &k2 = k_[1], &k3 = k_[2], &k4 = k_[3], &k5 = k_[4], &k6 = k_[5], &k7 = k_[6];
  while (t < t_end) {
    if (stats_.steps + stats_.rejected >= o_.max_steps)
      throw SimulationError(
          fmt::format("adaptive integrator: more than {} steps at t = {} s", o_.max_steps, t));
    double h = h_;
    const bool last = t + h >= t_end * (1 - 1e-14);
    if (last) h = t_end - t;
    tmp_ = y + h * a21 * k1;
    sys.derivative(t + c2 * h, tmp_, k2);
    tmp_ = y + h * (a31 * k1 + a32 * k2);
    sys.derivative(t + c3 * h, tmp_, k3);
    tmp_ = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
    sys.derivative(t + c4 * h, tmp_, k4);
    tmp_ = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
    sys.derivative(t + c5 * h, tmp_, k5);
    tmp_ = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
    sys.derivative(t + h, tmp_, k6);
    y_new_ = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    sys.derivative(t + h, y_new_, k7);
    stats_.evaluations += 6;
    tmp_ = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    const Eigen::ArrayXd sc = atol + rtol * y.array().abs().max(y_new_.array().abs());
    const double err = std::sqrt((tmp_.array() / sc).square().mean());
    if (!std::isfinite(err))
      throw SimulationError(fmt::format("adaptive integrator: non-finite state at t = {} s", t));
    const double factor = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
    if (err <= 1.0) {
      t = last ? t_end : t + h;
      y.swap(y_new_);
      k1.swap(k7);
      ++stats_.steps;
      // keep the controller's step, not the one shortened to land on t_end
      if (!last || h >= h_) h_ = h * factor;
    } else {
      h_ = h * std::min(1.0, factor);
      ++stats_.rejected;
    }
  }
}

}  // namespace comminute::pbm
