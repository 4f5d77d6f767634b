#include "comminute/breakage/criteria/tavares.hpp"

#include <cmath>

#include "comminute/fracture/energy_share.hpp"

namespace comminute::breakage {

void Tavares::attach(ParticleStore& p) {
  // J/kg, current (after damage), before the phase weight w: the particle's E_eff is w E
  energy_ = p.add_field("tavares.fracture_energy", 0.0);
  damage_ = p.add_field("tavares.damage", 0.0);  // accumulated D = 1 - E/E_initial
  p_.phases.attach(p);
}

fracture::FractureEnergyDistribution Tavares::scaled(double d, double w) const {
  // This project's extension (docs/models.md eq. C2b): E50 and E_max (E_max/E50 fixed) times w.
  return {p_.e50(d) * w, p_.sigma, p_.emax_ratio};
}

void Tavares::initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const {
  // drawn at the default composition's scale of 1; the phase weight applies when it is read
  p.field(energy_)[i] = p_.distribution(d).quantile(rng.uniform());
  p.field(damage_)[i] = 0.0;
}

bool Tavares::breaks(const ParticleStore& p, std::size_t i, double, const StressingEvent& e) const {
  return e.specific_energy >= p.field(energy_)[i] * weight(p, i);  // E_eff = w E, eq. C2b
}

void Tavares::survive(ParticleStore& p, std::size_t i, double, const StressingEvent& e) const {
  if (e.specific_energy < p_.min_damage_energy) return;
  double& energy = p.field(energy_)[i];
  const double d = p_.damage(e.specific_energy / (energy * weight(p, i)));
  energy *= 1.0 - d;  // E <- E(1 - D), Tavares & King (2002), docs/models.md eq. D2
  double& total = p.field(damage_)[i];
  total = 1.0 - (1.0 - total) * (1.0 - d);
}

double Tavares::strength(const ParticleStore& p, std::size_t i, double) const {
  return p.field(energy_)[i] * weight(p, i);
}

double Tavares::damage(const ParticleStore& p, std::size_t i) const {
  return p.field(damage_)[i];
}

double Tavares::probability(double d, const StressingEvent& e) const {
  return distribution(d).cdf(e.specific_energy);
}

namespace {
// Keys: the fracture energies (fracture::read_fracture_energy_model), damage_gamma, damage_form,
// min_damage_energy, and the basis of e_inf (docs/breakage.md).
std::unique_ptr<BreakageCriterion> make(const CaseTable& t, const Material& m) {
  TavaresParameters p;
  static_cast<fracture::FractureEnergyModel&>(p) = fracture::read_fracture_energy_model(t);
  p.damage = fracture::read_damage_law(t);
  p.min_damage_energy = t.number("min_damage_energy", Limits::non_negative(), 0.0);
  p.phases = read_phase_weights(t, false);  // optional: phase-weighted strength (eq. C2b)
  // E_inf measured as applied energy against a device (steel by default) or as absorbed energy.
  const std::string basis = t.choice("e_inf_basis", {"applied", "absorbed"}, "applied");
  if (basis == "applied") {
    const double ks = fracture::plane_strain_modulus(
        t.number("device_youngs_modulus", Limits::positive(), 210e9),
        t.number("device_poisson_ratio", Limits::between(0.0, 0.5), 0.3));
    p.size_effect.partition = fracture::energy_share(
        fracture::plane_strain_modulus(m.youngs_modulus, m.poisson_ratio), ks);  // eq. F5
  }
  return std::make_unique<Tavares>(p);
}
const bool registered = CriterionRegistry::add("tavares", &make);
}  // namespace

}  // namespace comminute::breakage
