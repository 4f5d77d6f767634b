#include "comminute/contact/jkr_curve.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/units.hpp"

namespace comminute {

namespace {

// c = sqrt(2 pi Gamma / E*): delta(a) = a^2 / R* - c sqrt(a).
double adhesion_length(double modulus, double work) {
  return std::sqrt(2.0 * units::pi * work / modulus);
}

// Johnson, Kendall & Roberts, Proc. R. Soc. Lond. A 324 (1971) 301: F(a) on the JKR curve.
double jkr_force(double a, double r, double modulus, double work) {
  const double a3 = a * a * a;
  return 4.0 * modulus * a3 / (3.0 * r) - std::sqrt(8.0 * units::pi * work * modulus * a3);
}

}  // namespace

JkrPoint jkr_point(double delta, double r, double modulus, double work) {
  const double c = adhesion_length(modulus, work);
  const double ac = std::cbrt(units::pi * work * r * r / (8.0 * modulus));  // d delta/d a = 0
  if (delta < -3.0 * ac * ac / r) return {};                                // separated
  // u^4 - c R u - R delta = 0 on u >= sqrt(a_c): convex, Newton from above the root.
  const double lo = std::sqrt(ac);
  double u = std::max({std::cbrt(2.0 * c * r), std::pow(std::max(2.0 * r * delta, 0.0), 0.25), lo});
  for (int it = 0; it < 100; ++it) {
    const double g = u * u * u * u - c * r * u - r * delta;
    const double step = g / (4.0 * u * u * u - c * r);
    u = std::max(u - step, lo);
    if (std::abs(step) <= 1e-15 * u) break;
  }
  const double a = u * u;
  return {a, jkr_force(a, r, modulus, work)};
}

// Integral of F(a) delta'(a) da from a(0) to a(delta), in closed form:
//   2 K a^5 / (5 R) - (K c / 7 + 4 W / (7 R)) a^(7/2) + W c a^2 / 4,
// K = 4 E* / (3 R*), W = sqrt(8 pi Gamma E*).
double jkr_energy(double delta, double r, double modulus, double work) {
  const double c = adhesion_length(modulus, work);
  const double k = 4.0 * modulus / (3.0 * r), w = std::sqrt(8.0 * units::pi * work * modulus);
  auto primitive = [&](double a) {
    return 2.0 * k * std::pow(a, 5) / (5.0 * r) -
           (k * c / 7.0 + 4.0 * w / (7.0 * r)) * std::pow(a, 3.5) + w * c * a * a / 4.0;
  };
  const double a0 = std::cbrt(c * c * r * r);  // delta(a0) = 0: a0^(3/2) = c R*
  const double a = jkr_point(delta, r, modulus, work).contact_radius;
  return a > 0 ? primitive(a) - primitive(a0) : 0.0;
}

}  // namespace comminute
