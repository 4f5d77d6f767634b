#include <cmath>
#include <memory>

#include "comminute/pbm/critical_stress.hpp"

namespace comminute::pbm {

// docs/models.md eq. S3: sigma_crit = sigma0 (d/d_ref)^(-1/m).
double PowerLawStrength::of_size(double d) const {
  return sigma0_ * std::pow(d / ref_, -1.0 / m_);
}

namespace {
std::unique_ptr<CriticalStress> make(const CaseTable& t) {
  return std::make_unique<PowerLawStrength>(t.number("sigma0", Limits::positive()),
                                            t.number("m", Limits::positive()),
                                            t.number("reference_size", Limits::positive(), 1.0));
}
const bool registered = CriticalStressRegistry::add("power_law", &make);
}  // namespace

}  // namespace comminute::pbm
