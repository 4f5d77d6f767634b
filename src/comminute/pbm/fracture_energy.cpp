#include "comminute/pbm/fracture_energy.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>

namespace comminute::pbm {

// Tavares (seed 002 eq. 12): E50(d) = E∞ [1 + (d0/d)^φ].
double FractureEnergyModel::e50(double d) const {
  return e50_inf * (1 + std::pow(d0 / d, phi));
}

// Tavares (seed 002 eq. 10–11): upper-truncated lognormal.
double FractureEnergyModel::cdf(double energy, double d) const {
  if (energy <= 0) return 0.0;
  const double median = e50(d), emax = max_ratio * median;
  if (energy >= emax) return 1.0;
  const double estar = energy * emax / (emax - energy);
  return 0.5 * boost::math::erfc(-(std::log(estar) - std::log(median)) / (std::sqrt(2.0) * sigma));
}

}  // namespace comminute::pbm
