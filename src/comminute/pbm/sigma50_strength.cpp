#include <cmath>
#include <limits>
#include <memory>

#include "comminute/pbm/critical_stress.hpp"

namespace comminute::pbm {

// docs/models.md eq. S4: sigma50 = sigma_inf (1 + x0/(d - x_p))^phi, infinite for d <= x_p.
double Sigma50Strength::of_size(double d) const {
  if (d <= x_p_) return std::numeric_limits<double>::infinity();
  return sigma_inf_ * std::pow(1 + x0_ / (d - x_p_), phi_);
}

namespace {
std::unique_ptr<CriticalStress> make(const CaseTable& t) {
  return std::make_unique<Sigma50Strength>(
      t.number("sigma_inf", Limits::positive()), t.number("x0", Limits::non_negative()),
      t.number("phi", Limits::any()), t.number("x_p", Limits::non_negative(), 0.0));
}
const bool registered = CriticalStressRegistry::add("sigma50", &make);
}  // namespace

}  // namespace comminute::pbm
