#include "comminute/breakage/criteria/composition_peak_force.hpp"

namespace comminute::breakage {

void CompositionPeakForce::attach(ParticleStore& p) {
  PeakForce::attach(p);
  weights_.attach(p);
}

double CompositionPeakForce::critical_force(const ParticleStore& p, std::size_t i, double d) const {
  return law_(d) * weights_.weight(p, i);  // Cleary & Sinnott (2015), docs/models.md eq. C2
}

double CompositionPeakForce::nominal_critical_force(double d) const {
  return law_(d) * weights_.nominal();  // default composition: all phase 0
}

namespace {
std::unique_ptr<BreakageCriterion> make_composition(const CaseTable& t, const Material&) {
  auto law = read_critical_force_law(t);
  auto sigma = read_factor_sigma(t);
  auto weights = read_phase_weights(t, true);
  return std::make_unique<CompositionPeakForce>(law, sigma, weights.relative_strength());
}
const bool registered_composition =
    CriterionRegistry::add("composition_peak_force", &make_composition);
}  // namespace

}  // namespace comminute::breakage
