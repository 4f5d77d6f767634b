#pragma once
// Composition-dependent peak force (Cleary & Sinnott, Minerals Eng. 74 (2015) 178;
// docs/models.md eq. C2): the peak-force criterion with a critical force weighted by the
// particle's composition.
#include <vector>

#include "comminute/breakage/criteria/peak_force.hpp"
#include "comminute/breakage/criteria/phase_weights.hpp"

namespace comminute::breakage {

// Composition-dependent peak force (docs/models.md eq. C2): F_crit(x, C) = sum_k F_CS(x) C_k
// f_rel,k, with the particle's composition vector in fields "composition.0", "composition.1", ...
// (phase 0 defaults to 1, the others to 0; fragments inherit the parent's composition).
class CompositionPeakForce final : public PeakForce {
 public:
  CompositionPeakForce(const CriticalForceLaw& law, double factor_sigma,
                       std::vector<double> relative_strength)
      : PeakForce(law, factor_sigma), weights_(std::move(relative_strength)) {}
  std::string name() const override { return "composition_peak_force"; }
  void attach(ParticleStore& p) override;
  const std::vector<double>* relative_strength() const override {
    return &weights_.relative_strength();
  }

 protected:
  double critical_force(const ParticleStore& p, std::size_t i, double d) const override;
  double nominal_critical_force(double d) const override;

 private:
  PhaseWeights weights_;  // f_rel,k = sigma_k / sigma_ref per phase
};

}  // namespace comminute::breakage
