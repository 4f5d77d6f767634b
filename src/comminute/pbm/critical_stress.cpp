#include "comminute/pbm/critical_stress.hpp"

#include <cmath>
#include <limits>

namespace comminute::pbm {

// seed 003: σ_crit = σ0 x^(−1/m).
double PowerLawStrength::of_size(double d) const {
  return sigma0_ * std::pow(d / ref_, -1.0 / m_);
}

// seed 003: σ50 = σ∞ (1 + x0/(x − x_p))^φ.
double Sigma50Strength::of_size(double d) const {
  if (d <= x_p_) return std::numeric_limits<double>::infinity();
  return sigma_inf_ * std::pow(1 + x0_ / (d - x_p_), phi_);
}

}  // namespace comminute::pbm
