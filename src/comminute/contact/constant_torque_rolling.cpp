// Constant directional torque rolling resistance (Ai, Chen, Rotter & Ooi, Powder Technol. 206
// (2011) 269, model A):
// M_r = -mu_r R* |F_n| w_rel/|w_rel|, with w_rel the relative rolling angular velocity. The torque
// is capped at I* |w_rel| / dt so that it stops the relative rolling within a step instead of
// reversing it (the chatter of model A at rest).
#include <algorithm>
#include <cmath>

#include "comminute/contact/rolling_resistance.hpp"

namespace comminute {
namespace {

class ConstantTorqueRolling final : public RollingResistance {
 public:
  std::string name() const override { return "constant_torque"; }
  void compute(const ContactKinematics& k, const PairParameters& p, const StateRef&,
               ContactForces& out) const override {
    // rolling part of the relative angular velocity (twist about the normal excluded)
    const Vec3 wr =
        k.relative_angular_velocity - dot(k.relative_angular_velocity, k.normal) * k.normal;
    const double wn = norm(wr);
    if (wn <= 0.0) return;
    const double cap = k.effective_inertia * wn / k.dt;
    const double m =
        std::min(p.rolling_friction * k.effective_radius * std::abs(out.normal_force), cap);
    out.rolling_torque += (-m / wn) * wr;
    // kinetic energy of the relative rotation removed by the torque over the step
    out.friction_dissipation +=
        m * wn * k.dt -
        (k.effective_inertia > 0 ? 0.5 * m * m * k.dt * k.dt / k.effective_inertia : 0.0);
  }
};

const bool registered = RollingResistanceRegistry::add(
    "constant_torque", [](const CaseTable&) { return std::make_unique<ConstantTorqueRolling>(); });

}  // namespace
}  // namespace comminute
