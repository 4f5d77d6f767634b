#include "comminute/particles/restitution.hpp"

#include <cmath>

#include "comminute/core/units.hpp"

namespace comminute {

// β = ln e / sqrt(ln² e + π²): the linear oscillator's damping ratio for restitution e (Tsuji,
// Tanaka & Ishida, Powder Technol. 71 (1992) 239; docs/models.md "Contact laws").
double damping_beta(double restitution) {
  if (restitution >= 1.0) return 0.0;
  const double l = std::log(restitution);
  return l / std::sqrt(l * l + units::pi * units::pi);
}

// Non-dimensional Hertz impact with Tsuji-type damping (Tsuji, Tanaka & Ishida, Powder Technol.
// 71 (1992) 239), integrated by RK4; verifies beta(e) (see the header).
double hertz_restitution(double beta) {
  const double c = std::sqrt(5.0) * std::abs(beta);
  auto acc = [c](double x, double v) {
    const double xp = x > 0 ? x : 0.0;
    return -xp * std::sqrt(xp) - c * std::sqrt(std::sqrt(xp)) * v;
  };
  // classical RK4 on (x, v) from x = 0, v = 1 until the overlap closes (contact time ~3.2)
  const double h = 2e-4;
  double x = 0, v = 1;
  for (int n = 0; n < 200000; ++n) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0.0 && n > 0) {
      // the force vanishes at x = 0, so v is constant through the crossing: interpolate
      const double s = x / (x - xn);
      return -(v + s * (vn - v));
    }
    x = xn;
    v = vn;
  }
  return 0.0;
}

}  // namespace comminute
