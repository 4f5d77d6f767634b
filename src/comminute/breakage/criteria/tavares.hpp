#pragma once
// Tavares (UFRJ) energy criterion with Tavares-King damage (docs/models.md eq. F1-F5, D1-D2).
// Each particle draws a specific fracture energy E from the upper-truncated lognormal distribution
// of its size (fracture::FractureEnergyModel); it breaks when the energy absorbed in one stressing
// event reaches E; otherwise the event damages it, E <- E (1 - D) (fracture::DamageLaw).
#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/fracture/damage.hpp"
#include "comminute/fracture/fracture_energy_model.hpp"

namespace comminute::breakage {

// The fracture energies (size_effect, sigma, emax_ratio) plus the damage settings.
struct TavaresParameters : fracture::FractureEnergyModel {
  fracture::DamageLaw damage;      // damage_gamma, damage_form
  double min_damage_energy = 0.0;  // J/kg, events absorbing less do not damage (Rocky's e_min)
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
  double median_fracture_energy(double d) const override { return p_.e50(d); }
  double t10_median_energy(double d, double specific_energy,
                           fracture::E50bRule rule) const override {
    return fracture::t10_median_energy(distribution(d), specific_energy, rule);  // eq. P1b
  }
  fracture::FractureEnergyDistribution distribution(double d) const { return p_.distribution(d); }
  const TavaresParameters& parameters() const { return p_; }

 private:
  TavaresParameters p_;
  std::size_t energy_ = 0, damage_ = 0;  // field indices
};

}  // namespace comminute::breakage
