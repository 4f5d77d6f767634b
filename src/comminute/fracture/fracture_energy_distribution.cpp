#include "comminute/fracture/fracture_energy_distribution.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/core/math_policy.hpp"

namespace comminute::fracture {

FractureEnergyDistribution::FractureEnergyDistribution(double e50, double sigma, double emax_ratio)
    : e50_(e50), sigma_(sigma), emax_(e50 * emax_ratio) {
  if (!(e50 > 0) || !(sigma > 0) || !(emax_ratio > 1))
    throw Error("fracture-energy distribution needs E50 > 0, sigma > 0, Emax/E50 > 1");
}

// Tavares & King (1998), upper-truncated lognormal: docs/models.md eq. F1.
double FractureEnergyDistribution::cdf(double e) const {
  if (e <= 0) return 0.0;
  if (e >= emax_) return 1.0;
  const double e_star = std::isinf(emax_) ? e : e * emax_ / (emax_ - e);
  return 0.5 * boost::math::erfc(-(std::log(e_star) - std::log(e50_)) / (std::sqrt(2.0) * sigma_));
}

// Inversion of eq. F1 (docs/models.md eq. F2).
double FractureEnergyDistribution::quantile(double u) const {
  const double e_star = e50_ * std::exp(std::sqrt(2.0) * sigma_ *
                                        boost::math::erf_inv(2.0 * u - 1.0, DoublePrecision()));
  return std::isinf(emax_) ? e_star : e_star * emax_ / (emax_ + e_star);
}

}  // namespace comminute::fracture
