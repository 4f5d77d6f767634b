#pragma once
// Tavares (UFRJ) energy criterion with Tavares-King damage (MODELS.md; seed 002 eq. 10-15).
// Each particle draws a specific fracture energy E from the upper-truncated lognormal distribution
// of its size; it breaks when the energy absorbed in one stressing event reaches E; otherwise the
// event damages it, E <- E (1 - D).
#include <limits>

#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/breakage/criteria/fracture_energy.hpp"

namespace comminute::breakage {

struct TavaresParameters {
  SizeEffect size_effect;                                       // E50(d)
  double sigma = 0.8;                                           // standard deviation of ln E*
  double emax_ratio = std::numeric_limits<double>::infinity();  // Emax/E50 (infinity: untruncated)
  double gamma = 5.0;                                           // damage exponent
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
  double median_fracture_energy(double d) const override { return p_.size_effect.e50(d); }
  FractureEnergyDistribution distribution(double d) const;
  const TavaresParameters& parameters() const { return p_; }

 private:
  TavaresParameters p_;
  std::size_t energy_ = 0, damage_ = 0;  // field indices
};

}  // namespace comminute::breakage
