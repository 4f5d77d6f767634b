#include "comminute/breakage/criteria/composition_peak_force.hpp"

#include <string>

namespace comminute::breakage {

void CompositionPeakForce::attach(ParticleStore& p) {
  PeakForce::attach(p);
  composition_.clear();
  for (std::size_t k = 0; k < relative_strength_.size(); ++k)
    composition_.push_back(p.add_field("composition." + std::to_string(k), k == 0 ? 1.0 : 0.0));
}

double CompositionPeakForce::critical_force(const ParticleStore& p, std::size_t i, double d) const {
  double s = 0;  // Cleary & Sinnott (2015), docs/models.md eq. C2: sum_k C_k f_rel,k
  for (std::size_t k = 0; k < composition_.size(); ++k)
    s += p.field(composition_[k])[i] * relative_strength_[k];
  return law_(d) * s;
}

double CompositionPeakForce::nominal_critical_force(double d) const {
  return law_(d) * relative_strength_[0];  // default composition: all phase 0
}

namespace {
std::unique_ptr<BreakageCriterion> make_composition(const CaseTable& t, const Material&) {
  auto law = read_critical_force_law(t);
  auto sigma = read_factor_sigma(t);
  auto f_rel = t.numbers("relative_strength", Limits::non_negative());
  if (f_rel.empty()) t.fail("relative_strength", "needs one value per phase");
  return std::make_unique<CompositionPeakForce>(law, sigma, f_rel);
}
const bool registered_composition =
    CriterionRegistry::add("composition_peak_force", &make_composition);
}  // namespace

}  // namespace comminute::breakage
