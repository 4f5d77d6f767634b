// Constant directional torque rolling resistance (Ai et al. 2011, model A):
// M_r = -mu_r R* |F_n| w_rel/|w_rel|, with w_rel the relative rolling angular velocity.
#include <cmath>

#include "comminute/contact/rolling_resistance.hpp"

namespace comminute {
namespace {

class ConstantTorqueRolling final : public RollingResistance {
 public:
  std::string name() const override { return "constant_torque"; }
  void compute(const ContactKinematics& k, const PairParameters& p, ContactHistory&,
               ContactForces& out) const override {
    // rolling part of the relative angular velocity (twist about the normal excluded)
    const Vec3 wr = k.relative_angular_velocity - dot(k.relative_angular_velocity, k.normal) * k.normal;
    const double wn = norm(wr);
    if (wn <= 0.0) return;
    const double m = p.rolling_friction * k.effective_radius * std::abs(out.normal_force);
    out.rolling_torque += (-m / wn) * wr;
    out.friction_dissipation += m * wn * k.dt;
  }
};

const bool registered = RollingResistanceRegistry::add(
    "constant_torque", [] { return std::make_unique<ConstantTorqueRolling>(); });

}  // namespace
}  // namespace comminute
