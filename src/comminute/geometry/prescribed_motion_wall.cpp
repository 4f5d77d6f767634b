#include "comminute/geometry/prescribed_motion_wall.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute {

PrescribedMotionWall::PrescribedMotionWall(std::unique_ptr<Wall> inner,
                                           std::unique_ptr<MotionModel> motion)
    : inner_(std::move(inner)), motion_(std::move(motion)) {
  name = inner_->name;
  material = inner_->material;
  kinematics = inner_->kinematics;
  motion_->at(0.0, kinematics.velocity, kinematics.angular_velocity);
  sync();
}

void PrescribedMotionWall::advance(double dt) {
  motion_->at(time_ + 0.5 * dt, kinematics.velocity, kinematics.angular_velocity);
  sync();
  inner_->advance(dt);
  kinematics.center = inner_->kinematics.center;
  time_ += dt;
  motion_->at(time_, kinematics.velocity, kinematics.angular_velocity);
  sync();
}

// A model may be at rest now and move later (a table, a ramp from zero): the candidates must be
// re-found whenever the surface may move at all, so these ask the inner wall about a moving state
// when this one is at rest.
bool PrescribedMotionWall::surface_moves() const {
  return true;
}

double PrescribedMotionWall::travel(double dt) const {
  return inner_->travel(dt);
}

bool PrescribedMotionWall::full_scan() const {
  return inner_->full_scan();
}

void PrescribedMotionWall::save(Archive& a, const std::string& prefix) const {
  inner_->save(a, prefix);
  a.put(prefix + "motion_time", std::vector<double>{time_});
}

void PrescribedMotionWall::load(const Archive& a, const std::string& prefix) {
  inner_->load(a, prefix);
  const auto t = a.get<double>(prefix + "motion_time");
  if (t.size() != 1 || !std::isfinite(t[0]))
    throw Error(fmt::format("checkpoint entry '{}motion_time' does not hold one time", prefix));
  time_ = t[0];
  kinematics.center = inner_->kinematics.center;
  motion_->at(time_, kinematics.velocity, kinematics.angular_velocity);
  sync();
}

}  // namespace comminute
