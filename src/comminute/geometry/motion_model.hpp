#pragma once
// Prescribed motion of a wall as functions of time: the velocity of its rotation centre and its
// angular velocity at time t (s, from the start of the run). Each model is a plug-in of
// MotionRegistry reading its [walls.motion] table: constant, rotation (rad/s or rpm, optional
// linear ramp), oscillation (sinusoidal translation), eccentric (circular translation of an
// eccentric shaft plus an optional swing, a jaw crusher), table (piecewise-linear in time).
// A model has no state of its own: the wall integrates the pose and saves its own time.
#include <memory>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

class MotionModel {
 public:
  virtual ~MotionModel() = default;
  // Velocity (m/s) of the rotation centre and angular velocity (rad/s) at time t (s).
  virtual void at(double t, Vec3& velocity, Vec3& angular_velocity) const = 0;
  // A model whose pose is known in closed form (a linkage) returns true and sets, at time t, the
  // displacement (m) of the rotation centre since t = 0 and the rotation vector (rad, axis times
  // angle) of the body since t = 0 about that centre: a mesh wall then places itself exactly
  // instead of integrating at(). Default: false (the pose is integrated).
  virtual bool pose(double /*t*/, Vec3& /*displacement*/, Vec3& /*rotation*/) const {
    return false;
  }
};

using MotionRegistry = Registry<MotionModel, const CaseTable&>;

// The model named by `type` in table t (InputError naming the key for an unknown one).
std::unique_ptr<MotionModel> make_motion(const CaseTable& t);

}  // namespace comminute
