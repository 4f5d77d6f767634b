#include "comminute/breakage/criteria/tavares.hpp"

#include <cmath>
#include <limits>

#include "comminute/breakage/criteria/damage.hpp"

namespace comminute::breakage {

void Tavares::attach(ParticleStore& p) {
  energy_ = p.add_field("tavares.fracture_energy", 0.0);  // J/kg, current (after damage)
  damage_ = p.add_field("tavares.damage", 0.0);           // accumulated D = 1 - E/E_initial
}

FractureEnergyDistribution Tavares::distribution(double d) const {
  return {p_.size_effect.e50(d), p_.sigma, p_.emax_ratio};
}

void Tavares::initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const {
  p.field(energy_)[i] = distribution(d).quantile(rng.uniform());
  p.field(damage_)[i] = 0.0;
}

bool Tavares::breaks(const ParticleStore& p, std::size_t i, double, const StressingEvent& e) const {
  return e.specific_energy >= p.field(energy_)[i];
}

void Tavares::survive(ParticleStore& p, std::size_t i, double, const StressingEvent& e) const {
  if (e.specific_energy < p_.min_damage_energy) return;
  double& energy = p.field(energy_)[i];
  const double d = tavares_king_damage(p_.gamma, e.specific_energy / energy);
  energy *= 1.0 - d;  // E <- E(1 - D), seed 002 eq. 15
  double& total = p.field(damage_)[i];
  total = 1.0 - (1.0 - total) * (1.0 - d);
}

double Tavares::strength(const ParticleStore& p, std::size_t i, double) const {
  return p.field(energy_)[i];
}

double Tavares::damage(const ParticleStore& p, std::size_t i) const {
  return p.field(damage_)[i];
}

double Tavares::probability(double d, const StressingEvent& e) const {
  return distribution(d).cdf(e.specific_energy);
}

namespace {
std::unique_ptr<BreakageCriterion> make(const ParameterSource& s, const Material& m) {
  const double inf = std::numeric_limits<double>::infinity();
  TavaresParameters p;
  p.size_effect.e_inf = s.number("e_inf", 0, inf, true, ParameterSource::required);
  p.size_effect.d0 = s.number("d0", 0, inf, false, 0.0);
  p.size_effect.phi = s.number("phi", 0, inf, false, 1.0);
  p.sigma = s.number("sigma", 0, inf, true, ParameterSource::required);
  p.emax_ratio = s.number("emax_ratio", 1, inf, true, inf);
  p.gamma = s.number("gamma", 0, inf, true, 5.0);
  p.min_damage_energy = s.number("min_damage_energy", 0, inf, false, 0.0);
  // E_inf measured as applied energy against a device (steel by default) or as absorbed energy.
  const std::string basis = s.choice("e_inf_basis", {"applied", "absorbed"}, "applied");
  if (basis == "applied") {
    const double ks = plane_strain_modulus(s.number("device_youngs_modulus", 0, inf, true, 210e9),
                                           s.number("device_poisson_ratio", 0, 0.5, false, 0.3));
    p.size_effect.partition =
        energy_share(plane_strain_modulus(m.youngs_modulus, m.poisson_ratio), ks);
  }
  return std::make_unique<Tavares>(p);
}
const bool registered = CriterionRegistry::add("tavares", &make);
}  // namespace

}  // namespace comminute::breakage
