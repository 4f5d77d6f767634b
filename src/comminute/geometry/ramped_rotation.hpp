#pragma once
// Steady rotation at a fixed angular velocity vector, reached linearly from rest over a ramp:
// the drive of a mill shell or a roll (a MotionModel built by a generator, not read from a
// [walls.motion] table).
#include <algorithm>

#include "comminute/geometry/motion_model.hpp"

namespace comminute {

class RampedRotation : public MotionModel {
 public:
  // omega: the angular velocity (rad/s) after the ramp; ramp_time (s) 0: from the start.
  RampedRotation(const Vec3& omega, double ramp_time) : omega_(omega), ramp_(ramp_time) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = {};
    w = omega_ * (ramp_ > 0 ? std::min(1.0, t / ramp_) : 1.0);
  }

 private:
  Vec3 omega_;
  double ramp_;
};

}  // namespace comminute
