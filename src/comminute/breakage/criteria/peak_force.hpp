#pragma once
// Peak-force criteria (Cleary & Sinnott 2015; seed 000 eq. 1-3, MODELS.md "Peak-force criteria").
// A particle breaks when the peak of the sum of elastic normal contact forces on it within one
// stressing event reaches F_crit(d) times its own random strength factor (lognormal with median
// 1 and log-standard-deviation `factor_sigma`; 0 = deterministic). The force is not time-filtered.
#include <vector>

#include "comminute/breakage/criteria/breakage_criterion.hpp"

namespace comminute::breakage {

// F_CS(x) = a x^b + c, x the diameter (m), F in N (seed 000 eq. 1).
struct CriticalForceLaw {
  double a = 0, b = 1.5, c = 0;
  double operator()(double x) const;
};

class PeakForce : public BreakageCriterion {
 public:
  PeakForce(const CriticalForceLaw& law, double factor_sigma)
      : law_(law), factor_sigma_(factor_sigma) {}
  std::string name() const override { return "peak_force"; }
  void attach(ParticleStore& p) override;
  void initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const override;
  bool breaks(const ParticleStore& p, std::size_t i, double d,
              const StressingEvent& e) const override;
  double strength(const ParticleStore& p, std::size_t i, double d) const override;
  std::string strength_unit() const override { return "N"; }
  double probability(double d, const StressingEvent& e) const override;

 protected:
  // Critical force of particle i before its random factor (N).
  virtual double critical_force(const ParticleStore& p, std::size_t i, double d) const;
  // Critical force of a fresh particle of diameter d (N), for the model curve.
  virtual double nominal_critical_force(double d) const { return law_(d); }
  CriticalForceLaw law_;

 private:
  double factor_sigma_;
  std::size_t factor_ = 0;
};

// Composition-dependent peak force (seed 000 eq. 2-3): F_crit(x, C) = sum_k F_CS(x) C_k f_rel,k,
// with the particle's composition vector in fields "composition.0", "composition.1", ... (phase 0
// defaults to 1, the others to 0; fragments inherit the parent's composition).
class CompositionPeakForce final : public PeakForce {
 public:
  CompositionPeakForce(const CriticalForceLaw& law, double factor_sigma,
                       std::vector<double> relative_strength)
      : PeakForce(law, factor_sigma), relative_strength_(std::move(relative_strength)) {}
  std::string name() const override { return "composition_peak_force"; }
  void attach(ParticleStore& p) override;

 protected:
  double critical_force(const ParticleStore& p, std::size_t i, double d) const override;
  double nominal_critical_force(double d) const override;

 private:
  std::vector<double> relative_strength_;  // f_rel,k = sigma_k / sigma_ref per phase
  std::vector<std::size_t> composition_;   // field indices
};

}  // namespace comminute::breakage
