// Elastic–plastic spring–dashpot rolling resistance (Ai, Chen, Rotter & Ooi, Powder Technol. 206
// (2011) 269, model C; Iwashita & Oda, J. Eng. Mech. 124 (1998) 285):
// k_r = 2.25 k_n mu_r^2 R*^2, dM = -k_r w_rel dt, |M| <= mu_r R* |F_n| (full mobilisation, no
// damping), viscous part -C_r w_rel with C_r = eta_r 2 sqrt(I_r k_r), I_r = m* R*^2 (eta_r from
// [pair] rolling_damping). The spring torque is kept in the contact's slot "rolling_spring" (N m).
#include <cmath>

#include "comminute/contact/rolling_resistance.hpp"

namespace comminute {
namespace {

class EpsdRolling final : public RollingResistance {
 public:
  std::string name() const override { return "epsd"; }
  void declare(ContactStateStore& layout) override {
    spring_ = layout.declare_vec3("rolling_spring", SwapRule::negate);
  }
  void compute(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
               ContactForces& out) const override {
    Vec3& spring = s.vec3(spring_);
    const double r = k.effective_radius;
    const Vec3 wr =
        k.relative_angular_velocity - dot(k.relative_angular_velocity, k.normal) * k.normal;
    // k_n from the secant stiffness of the normal force
    const double kn = k.overlap > 0 ? std::abs(out.elastic_normal_force) / k.overlap : 0.0;
    const double kr = 2.25 * kn * p.rolling_friction * p.rolling_friction * r * r;
    Vec3 m = spring;
    m -= dot(m, k.normal) * k.normal;  // keep it in the tangent plane
    m -= kr * k.dt * wr;
    const double limit = p.rolling_friction * r * std::abs(out.normal_force);
    const double mm = norm(m);
    if (mm > limit) {
      // full mobilisation: the torque does work |M| |rolling slip|, slip = (M_trial - M) / k_r
      const Vec3 trial = m;
      m *= limit / mm;
      if (kr > 0) out.friction_dissipation += limit * norm(trial - m) / kr;
      spring = m;
      out.rolling_torque += m;
      return;
    }
    spring = m;
    const double cr = p.rolling_damping * 2.0 * std::sqrt(k.effective_mass * r * r * kr);
    out.rolling_torque += m - cr * wr;
    out.damping_dissipation += cr * norm2(wr) * k.dt;
    if (kr > 0) out.stored_energy += 0.5 * norm2(m) / kr;
  }

 private:
  SlotId spring_ = 0;
};

const bool registered = RollingResistanceRegistry::add(
    "epsd", [](const CaseTable&) { return std::make_unique<EpsdRolling>(); });

}  // namespace
}  // namespace comminute
