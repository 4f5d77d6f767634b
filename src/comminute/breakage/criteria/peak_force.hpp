#pragma once
// Peak-force criteria (Cleary & Sinnott, Minerals Eng. 74 (2015) 178; docs/models.md eq. C1-C2).
// A particle breaks when the peak force of one stressing event (by default the largest single
// elastic normal contact force, this project's reading of Cleary & Sinnott; the sum with
// force_measure = "contact_sum", docs/breakage.md) reaches F_crit(d) times its own random strength
// factor (lognormal with median 1 and log-standard-deviation `factor_sigma`; 0 = deterministic).
// The force is not time-filtered.
#include "comminute/breakage/criteria/breakage_criterion.hpp"

namespace comminute::breakage {

// F_CS(x) = a x^b + c, x the diameter (m), F in N (docs/models.md eq. C1).
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
  bool energy_based() const override { return false; }

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

// Case-file parameters shared by the peak-force family: a, b, c of F_CS and factor_sigma.
CriticalForceLaw read_critical_force_law(const CaseTable& t);
double read_factor_sigma(const CaseTable& t);

}  // namespace comminute::breakage
