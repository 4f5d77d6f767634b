// Bilinear cohesive bond: Camanho & Dávila (NASA/TM-2002-211737, 2002) mixed-mode softening with
// the Benzeggagh–Kenane criterion (mixed_mode.hpp). Traction t = F/A on the bond area
// A = π R̄², separation = change of the centre distance (normal) and accumulated slip at the
// contact point (shear). Compression is never damaged; the bond fails at d = 1.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_step.hpp"
#include "comminute/bonds/mixed_mode.hpp"

namespace comminute::bonds {
namespace {

class BilinearCohesive final : public BondLaw {
 public:
  explicit BilinearCohesive(const CaseTable& t) {
    p_.penalty = t.number("penalty_stiffness", Limits::positive());
    p_.normal_strength = t.number("normal_strength", Limits::positive());
    p_.shear_strength = t.number("shear_strength", Limits::positive());
    p_.toughness_I = t.number("mode_I_toughness", Limits::positive());
    p_.toughness_II = t.number("mode_II_toughness", Limits::positive());
    p_.bk_exponent = t.number("bk_exponent", Limits::positive());
    lambda_ = t.number("radius_multiplier", Limits::positive(), 1.0);
    // softening needs δ_mf > δ_m0 in every mode, 2 G_c / K > δ_m0²; δ_m0² is largest,
    // (N² + S²) / K², where both strengths are reached together (β = S/N)
    const double reach =
        p_.normal_strength * p_.normal_strength + p_.shear_strength * p_.shear_strength;
    if (2 * std::min(p_.toughness_I, p_.toughness_II) * p_.penalty <= reach)
      t.fail("mode_I_toughness",
             "mode_I_toughness and mode_II_toughness (J/m2) must both exceed (normal_strength^2 + "
             "shear_strength^2) / (2 penalty_stiffness), or the law cannot soften");
  }

  std::string name() const override { return "bilinear_cohesive"; }

  BondState create(double ri, double rj, double length, const Vec3& normal, Rng&) const override {
    BondState s;
    s.normal = normal;
    s.length0 = length;
    s.radius = lambda_ * std::min(ri, rj);
    s.tensile_strength = p_.normal_strength;
    s.shear_strength = p_.shear_strength;
    return s;
  }

  BondLoad update(BondState& s, const BondMotion& m) const override { return advance(s, m); }

  // update(), inlined into the loop of update_range (bond_step.hpp)
  [[gnu::always_inline]] BondLoad advance(BondState& s, const BondMotion& m) const {
    if (s.failed != FailureMode::none) return {};
    const double area = std::numbers::pi * s.radius * s.radius;
    // the accumulated slip turns with the bond and stays perpendicular to it
    s.slip = rotate_with(s.slip, s.normal, m.normal) + m.slip_increment;
    s.slip -= dot(s.slip, m.normal) * m.normal;
    s.normal = m.normal;
    const double dn = m.length - s.length0;
    const double ds = norm(s.slip);
    const MixedMode mode = mixed_mode(p_, dn, ds);
    const double d_new = std::max(s.damage, bilinear_damage(mode));
    if (d_new > s.damage) {
      // dissipation of this step along the current mode (exact for a fixed mode ratio)
      s.dissipated +=
          area * (dissipated_per_area(p_, mode, d_new) - dissipated_per_area(p_, mode, s.damage));
      s.damage = d_new;
    }
    const double open = std::max(dn, 0.0), closed = std::min(dn, 0.0);
    const double k_soft = (1.0 - s.damage) * p_.penalty;
    s.strain_energy =
        0.5 * area * (k_soft * (open * open + ds * ds) + p_.penalty * closed * closed);
    if (s.damage >= 1.0) {
      s.damage = 1.0;
      s.failed = mode.shear_ratio < 0.5 ? FailureMode::tensile : FailureMode::shear;
      s.dissipated += s.strain_energy;  // what compression still held is released
      s.strain_energy = 0;
      return {};
    }
    // traction on j: t = (1-d) K δ_active + K δ_inactive (pulls j back towards i)
    const double tn = k_soft * open + p_.penalty * closed;
    BondLoad load;
    load.force = -area * (tn * m.normal + k_soft * s.slip);
    return load;
  }

  BondStepSums update_range(const BondStep& step, std::size_t begin,
                            std::size_t end) const override {
    return update_bonds(*this, step, begin, end);
  }

  double stiffness(const BondState& s) const override {
    return p_.penalty * std::numbers::pi * s.radius * s.radius;
  }

 private:
  CohesiveParameters p_;
  double lambda_ = 1;
};

std::unique_ptr<BondLaw> make(const CaseTable& t) {
  return std::make_unique<BilinearCohesive>(t);
}
const bool registered = BondLawRegistry::add("bilinear_cohesive", &make);

}  // namespace
}  // namespace comminute::bonds
