#pragma once
// Steady rotation at a fixed angular velocity vector, reached linearly from rest over a ramp:
// the drive of a mill shell or a roll (a MotionModel built by a generator, not read from a
// [walls.motion] table). A floating roll (free_translation) keeps the translation velocity that
// its force control (engine/wall_control.hpp) sets: the rotation is prescribed, the translation
// is not.
#include <algorithm>

#include "comminute/geometry/motion_model.hpp"

namespace comminute {

class RampedRotation : public MotionModel {
 public:
  // omega: the angular velocity (rad/s) after the ramp; ramp_time (s) 0: from the start.
  RampedRotation(const Vec3& omega, double ramp_time, bool free_translation = false)
      : omega_(omega), ramp_(ramp_time), free_(free_translation) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    if (!free_) v = {};
    w = omega_ * (ramp_ > 0 ? std::min(1.0, t / ramp_) : 1.0);
  }

 private:
  Vec3 omega_;
  double ramp_;
  bool free_;  // the translation velocity is not this model's
};

}  // namespace comminute
