// Parallel bond of Potyondy & Cundall (Int. J. Rock Mech. Min. Sci. 41 (2004) 1329): a cemented
// disc of radius R̄ = λ̄ min(R_i, R_j) with normal and shear stiffness per area k̄n, k̄s (Pa/m).
// The normal force follows the total change of centre distance (as MUSEN does); shear force,
// twist and bending moments are incremental and turn with the bond. It fails in tension when
// σ = F_n,tension/A + |M_s| R̄/I reaches σ̄_c and in shear when τ = |F_s|/A + |M_n| R̄/J reaches τ̄_c.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_step.hpp"

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
        lambda_(t.number("radius_multiplier", Limits::positive(), 1.0)),
        per_kn_(1.0 / kn_),
        per_ks_(1.0 / ks_) {}

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

  BondLoad update(BondState& s, const BondMotion& m) const override { return advance(s, m); }

  // update(), inlined into the loop of update_range (bond_step.hpp)
  [[gnu::always_inline]] BondLoad advance(BondState& s, const BondMotion& m) const {
    if (s.failed != FailureMode::none) return {};
    const double r = s.radius;
    const double area = std::numbers::pi * r * r;
    const double inertia = 0.25 * area * r * r;  // I = πR̄⁴/4
    const double polar = 2 * inertia;            // J = πR̄⁴/2
    // one division per bond: 1/A, then 1/I = 4π/A², 1/J = 2π/A²
    const double per_area = 1.0 / area;
    const double per_polar = 2 * std::numbers::pi * per_area * per_area;
    const double per_inertia = 2 * per_polar;
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
    const double elongation = m.length - s.length0;
    const double tension = kn_ * area * elongation;
    const double mn = dot(s.moment, n);
    const Vec3 ms = s.moment - mn * n;
    const double fs2 = norm2(s.shear_force), ms2 = norm2(ms);
    // ½ (F̄n²/(k̄n A) + |F̄s|²/(k̄s A) + M̄n²/(k̄s J) + |M̄s|²/(k̄n I)), F̄n²/(k̄n A) = F̄n δ
    s.strain_energy = 0.5 * (tension * elongation + fs2 * per_area * per_ks_ +
                             mn * mn * per_polar * per_ks_ + ms2 * per_inertia * per_kn_);
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: σ = -F̄n/A + |M̄s| R̄/I, τ =
    // |F̄s|/A + |M̄n| R̄/J
    const double sigma = tension * per_area + std::sqrt(ms2) * r * per_inertia;
    const double tau = std::sqrt(fs2) * per_area + std::abs(mn) * r * per_polar;
    if (sigma >= s.tensile_strength || tau >= s.shear_strength) {
      const double load_t = sigma / s.tensile_strength, load_s = tau / s.shear_strength;
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

  BondStepSums update_range(const BondStep& step, std::size_t begin,
                            std::size_t end) const override {
    return update_bonds(*this, step, begin, end);
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
  double per_kn_, per_ks_;  // 1/k̄n, 1/k̄s (m/Pa)
};

std::unique_ptr<BondLaw> make(const CaseTable& t) {
  return std::make_unique<ParallelBond>(t);
}
const bool registered = BondLawRegistry::add("parallel_bond", &make);

}  // namespace
}  // namespace comminute::bonds
