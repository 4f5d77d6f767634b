// Parallel bond of Potyondy & Cundall (Int. J. Rock Mech. Min. Sci. 41 (2004) 1329): a cemented
// disc of radius R̄ = λ̄ min(R_i, R_j) with normal and shear stiffness per area k̄n, k̄s (Pa/m).
// The normal force follows the total change of centre distance (as MUSEN does); shear force,
// twist and bending moments are incremental and turn with the bond. It fails in tension when
// σ = F_n,tension/A + |M_s| R̄/I reaches σ̄_c and in shear when τ = |F_s|/A + |M_n| R̄/J reaches τ̄_c.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/bonds/bond_law.hpp"

namespace comminute::bonds {
namespace {

class ParallelBond final : public BondLaw {
 public:
  explicit ParallelBond(const CaseTable& t)
      : kn_(t.number("normal_stiffness", Limits::positive())),
        ks_(t.number("shear_stiffness", Limits::positive())),
        sigma_(t.number("tensile_strength", Limits::positive())),
        tau_(t.number("shear_strength", Limits::positive())),
        sigma_sd_(t.number("tensile_strength_sd", Limits::non_negative(), 0.0)),
        tau_sd_(t.number("shear_strength_sd", Limits::non_negative(), 0.0)),
        lambda_(t.number("radius_multiplier", Limits::positive(), 1.0)) {}

  std::string name() const override { return "parallel_bond"; }

  BondState create(double ri, double rj, double length, const Vec3& normal,
                   Rng& rng) const override {
    BondState s;
    s.normal = normal;
    s.length0 = length;
    s.radius = lambda_ * std::min(ri, rj);
    // strengths scatter normally (mean, standard deviation) per bond, redrawn when not positive
    s.tensile_strength = draw(rng, sigma_, sigma_sd_);
    s.shear_strength = draw(rng, tau_, tau_sd_);
    return s;
  }

  BondLoad update(BondState& s, const BondMotion& m) const override {
    if (s.failed != FailureMode::none) return {};
    const double r = s.radius;
    const double area = std::numbers::pi * r * r;
    const double inertia = std::numbers::pi * r * r * r * r / 4;  // I = πR̄⁴/4
    const double polar = 2 * inertia;                             // J = πR̄⁴/2
    // stored shear force and moment turn with the bond into the new frame
    const BondTurn turn(s.normal, m.normal);
    s.shear_force = turn(s.shear_force);
    s.moment = turn(s.moment);
    s.normal = m.normal;
    const Vec3& n = m.normal;
    const Vec3 twist = dot(m.rotation_increment, n) * n;
    const Vec3 bend = m.rotation_increment - twist;
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: ΔF̄s = -k̄s A ΔUs, ΔM̄n = -k̄s J
    // Δθn, ΔM̄s = -k̄n I Δθs
    s.shear_force -= ks_ * area * m.slip_increment;
    s.shear_force -= dot(s.shear_force, n) * n;
    s.moment -= ks_ * polar * twist + kn_ * inertia * bend;
    // normal force on j from the total elongation (tension pulls j towards i)
    const double tension = kn_ * area * (m.length - s.length0);
    const double mn = dot(s.moment, n);
    const Vec3 ms = s.moment - mn * n;
    s.strain_energy =
        0.5 * (tension * tension / (kn_ * area) + norm2(s.shear_force) / (ks_ * area) +
               mn * mn / (ks_ * polar) + norm2(ms) / (kn_ * inertia));
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: σ = -F̄n/A + |M̄s| R̄/I, τ =
    // |F̄s|/A + |M̄n| R̄/J
    const double sigma = tension / area + norm(ms) * r / inertia;
    const double tau = norm(s.shear_force) / area + std::abs(mn) * r / polar;
    const double load_t = sigma / s.tensile_strength, load_s = tau / s.shear_strength;
    if (load_t >= 1.0 || load_s >= 1.0) {
      s.failed = load_t >= load_s ? FailureMode::tensile : FailureMode::shear;
      s.damage = 1.0;
      s.dissipated += s.strain_energy;  // the strain energy is released when the bond fails
      s.strain_energy = 0;
      s.shear_force = {};
      s.moment = {};
      return {};
    }
    return {-tension * n + s.shear_force, s.moment};
  }

  double stiffness(const BondState& s) const override {
    return std::max(kn_, ks_) * std::numbers::pi * s.radius * s.radius;
  }

 private:
  static double draw(Rng& rng, double mean, double sd) {
    if (sd <= 0) return mean;
    for (;;) {
      const double v = rng.normal(mean, sd);
      if (v > 0) return v;
    }
  }

  double kn_, ks_, sigma_, tau_, sigma_sd_, tau_sd_, lambda_;
};

std::unique_ptr<BondLaw> make(const CaseTable& t) {
  return std::make_unique<ParallelBond>(t);
}
const bool registered = BondLawRegistry::add("parallel_bond", &make);

}  // namespace
}  // namespace comminute::bonds
