#pragma once
// The collision record of a contact, kept for the collision log: from the first touch of two
// bodies to their separation, the relative normal speed at the first touch, the largest overlap
// and normal force, the energy the normal dashpot dissipated and the rest of the contact's
// dissipation (tangential dashpot, sliding, rolling), and the time in contact. A contact
// sub-model like the loading record: its slots exist only when a module asks for it. The sums
// over steps are in double precision (an enduring contact adds 1e5 small steps: in single
// precision a step below half a unit of the sum's last place would be lost); the speed, overlap
// and force in single (relative rounding 1e-7, far below any statistic drawn from the log).
#include <algorithm>
#include <cmath>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

// What a contact left when it ended (SI units).
struct CollisionTotals {
  double duration = 0;               // s, in contact
  double impact_speed = 0;           // m/s, relative normal speed at the first touch
  double max_overlap = 0;            // m
  double max_normal_force = 0;       // N, the law's (elastic + damping, adhesion excluded)
  double dissipated_normal = 0;      // J, normal dashpot
  double dissipated_tangential = 0;  // J, tangential dashpot, sliding and rolling
};

class CollisionRecord {
 public:
  void declare(ContactStateStore& layout) {
    duration_ = layout.declare_f64("collision_duration", SwapRule::keep);
    speed_ = layout.declare_f32("collision_impact_speed", SwapRule::keep);
    overlap_ = layout.declare_f32("collision_max_overlap", SwapRule::keep);
    force_ = layout.declare_f32("collision_max_normal_force", SwapRule::keep);
    normal_ = layout.declare_f64("collision_dissipated_normal", SwapRule::keep);
    tangential_ = layout.declare_f64("collision_dissipated_tangential", SwapRule::keep);
  }
  // The energy the law's normal dashpot dissipated this step (J): its force F_n - F_n,el times
  // the overlap rate; call with the law's result, before adhesion changes the normal force.
  static double normal_dissipation(const ContactKinematics& k, const ContactForces& law) {
    return (law.normal_force - law.elastic_normal_force) * k.overlap_rate * k.dt;
  }
  // After every sub-model computed `out`; `normal` from normal_dissipation(), `law_force` the
  // law's normal force.
  void record(const StateRef& s, const ContactKinematics& k, const ContactForces& out,
              double normal, double law_force) const {
    double& duration = s.f64(duration_);
    if (duration == 0.0) s.f32(speed_) = static_cast<float>(std::abs(k.overlap_rate));
    duration += k.dt;
    float& overlap = s.f32(overlap_);
    overlap = std::max(overlap, static_cast<float>(k.overlap));
    float& force = s.f32(force_);
    force = std::max(force, static_cast<float>(law_force));
    s.f64(normal_) += normal;
    s.f64(tangential_) += out.damping_dissipation + out.friction_dissipation - normal;
  }
  // What contact `s` holds (call before its state is cleared).
  CollisionTotals totals(const StateRef& s) const {
    return {s.f64(duration_), s.f32(speed_),  s.f32(overlap_),
            s.f32(force_),    s.f64(normal_), s.f64(tangential_)};
  }

 private:
  SlotId duration_ = 0, speed_ = 0, overlap_ = 0, force_ = 0, normal_ = 0, tangential_ = 0;
};

}  // namespace comminute
