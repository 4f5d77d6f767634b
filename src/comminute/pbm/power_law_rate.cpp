#include "comminute/pbm/power_law_rate.hpp"

#include <cmath>

namespace comminute::pbm {

// Austin et al. (1984): S_i = A (x_i/x_0)^α Q_i, Q_i = 1/(1 + (x_i/μ)^Λ).
double PowerLawRate::rate(double size, double volume) const {
  const double x = p_.variable == GridCoordinate::size ? size : volume;
  double s = p_.k * std::pow(x / p_.reference, p_.alpha);
  if (p_.mu) s /= 1 + std::pow(size / *p_.mu, p_.lambda);
  return s;
}

}  // namespace comminute::pbm
