#include "comminute/breakage/criteria/fracture_energy.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>

#include "comminute/core/error.hpp"
#include "comminute/core/math_policy.hpp"

namespace comminute::breakage {

FractureEnergyDistribution::FractureEnergyDistribution(double e50, double sigma, double emax_ratio)
    : e50_(e50), sigma_(sigma), emax_(e50 * emax_ratio) {
  if (!(e50 > 0) || !(sigma > 0) || !(emax_ratio > 1))
    throw Error("fracture-energy distribution needs E50 > 0, sigma > 0, Emax/E50 > 1");
}

double FractureEnergyDistribution::cdf(double e) const {
  if (e <= 0) return 0.0;
  if (e >= emax_) return 1.0;
  const double e_star = std::isinf(emax_) ? e : e * emax_ / (emax_ - e);  // seed 002 eq. 11
  return 0.5 * (1.0 + std::erf((std::log(e_star) - std::log(e50_)) / (std::sqrt(2.0) * sigma_)));
}

double FractureEnergyDistribution::quantile(double u) const {
  // Inversion (MODELS.md): ln E* = ln E50 + sqrt2 sigma erf^-1(2u - 1); E = E* Emax/(Emax + E*).
  const double e_star = e50_ * std::exp(std::sqrt(2.0) * sigma_ *
                                        boost::math::erf_inv(2.0 * u - 1.0, DoublePrecision()));
  return std::isinf(emax_) ? e_star : e_star * emax_ / (emax_ + e_star);
}

double SizeEffect::e50(double d) const {
  return e_inf * partition * (1.0 + std::pow(d0 / d, phi));  // seed 002 eq. 12
}

double plane_strain_modulus(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);
}

double energy_share(double k_p, double k_o) {
  return 1.0 / (1.0 + k_p / k_o);
}

}  // namespace comminute::breakage
