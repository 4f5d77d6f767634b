#include "comminute/breakage/criteria/phase_weights.hpp"

#include <string>

namespace comminute::breakage {

void PhaseWeights::attach(ParticleStore& p) {
  composition_.clear();
  for (std::size_t k = 0; k < relative_strength_.size(); ++k)
    composition_.push_back(p.add_field("composition." + std::to_string(k), k == 0 ? 1.0 : 0.0));
}

double PhaseWeights::weight(const ParticleStore& p, std::size_t i) const {
  if (composition_.empty()) return 1.0;
  double s = 0;  // Cleary & Sinnott (2015), docs/models.md eq. C2: sum_k C_k f_rel,k
  for (std::size_t k = 0; k < composition_.size(); ++k)
    s += p.field(composition_[k])[i] * relative_strength_[k];
  return s;
}

PhaseWeights read_phase_weights(const CaseTable& t, bool required) {
  if (!required && !t.has("relative_strength")) return {};
  auto f_rel = t.numbers("relative_strength", Limits::non_negative());
  if (f_rel.empty()) t.fail("relative_strength", "needs one value per phase");
  return PhaseWeights(std::move(f_rel));
}

}  // namespace comminute::breakage
