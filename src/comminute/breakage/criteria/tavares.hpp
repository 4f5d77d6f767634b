#pragma once
// Tavares (UFRJ) energy criterion with Tavares-King damage (docs/models.md eq. F1-F5, D1-D2).
// Each particle draws a specific fracture energy E from the upper-truncated lognormal distribution
// of its size (fracture::FractureEnergyModel); it breaks when the energy absorbed in one stressing
// event reaches E; otherwise the event damages it, E <- E (1 - D) (fracture::DamageLaw).
// Option relative_strength (this project's extension, not a published model; docs/models.md eq.
// C2b): the particle's fracture energy is weighted by its composition, E_eff = w E with
// w = sum_k C_k f_rel,k; that is, its distribution has E50 and E_max scaled by w.
#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/breakage/criteria/phase_weights.hpp"
#include "comminute/fracture/damage.hpp"
#include "comminute/fracture/fracture_energy_model.hpp"

namespace comminute::breakage {

// The fracture energies (size_effect, sigma, emax_ratio) plus the damage settings.
struct TavaresParameters : fracture::FractureEnergyModel {
  fracture::DamageLaw damage;      // damage_gamma, damage_form
  double min_damage_energy = 0.0;  // J/kg, events absorbing less do not damage (Rocky's e_min)
  PhaseWeights phases;             // relative_strength (empty: no phase weighting)
};

class Tavares final : public BreakageCriterion {
 public:
  explicit Tavares(const TavaresParameters& p) : p_(p) {}
  std::string name() const override { return "tavares"; }
  void attach(ParticleStore& p) override;
  void initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const override;
  bool breaks(const ParticleStore& p, std::size_t i, double d,
              const StressingEvent& e) const override;
  void survive(ParticleStore& p, std::size_t i, double d, const StressingEvent& e) const override;
  double strength(const ParticleStore& p, std::size_t i, double d) const override;
  std::string strength_unit() const override { return "J/kg"; }
  double damage(const ParticleStore& p, std::size_t i) const override;
  double probability(double d, const StressingEvent& e) const override;
  bool energy_based() const override { return true; }
  // Of a fresh particle of the default composition (all phase 0): E50(d) f_rel,0.
  double median_fracture_energy(double d) const override { return distribution(d).e50(); }
  double t10_median_energy(double d, double specific_energy,
                           fracture::E50bRule rule) const override {
    return fracture::t10_median_energy(distribution(d), specific_energy, rule);  // eq. P1b
  }
  const std::vector<double>* relative_strength() const override {
    return p_.phases.empty() ? nullptr : &p_.phases.relative_strength();
  }
  // Fracture-energy distribution of size d at the default composition (E50 and E_max times
  // f_rel,0; unscaled without relative_strength).
  fracture::FractureEnergyDistribution distribution(double d) const {
    return scaled(d, p_.phases.nominal());
  }
  // Fracture-energy distribution of particle i (size d) by its composition (eq. C2b).
  fracture::FractureEnergyDistribution distribution(const ParticleStore& p, std::size_t i,
                                                    double d) const {
    return scaled(d, p_.phases.weight(p, i));
  }
  const TavaresParameters& parameters() const { return p_; }

 private:
  fracture::FractureEnergyDistribution scaled(double d, double w) const;
  // E_eff / E of particle i: the phase weight w (1 without relative_strength).
  double weight(const ParticleStore& p, std::size_t i) const { return p_.phases.weight(p, i); }

  TavaresParameters p_;
  std::size_t energy_ = 0, damage_ = 0;  // field indices
};

}  // namespace comminute::breakage
