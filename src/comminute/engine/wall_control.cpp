#include "comminute/engine/wall_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

namespace {
SampleRows motion_columns(const std::vector<WallControlSpec>& walls) {
  std::vector<Column> cols{{"time", "s"}};
  for (const auto& s : walls) {
    cols.push_back({s.name + "_displacement", "m"});
    cols.push_back({s.name + "_velocity", "m/s"});
    cols.push_back({s.name + "_force", "N"});
    cols.push_back({s.name + "_stress", "Pa"});
    if (std::isfinite(s.gap)) cols.push_back({s.name + "_gap", "m"});
  }
  return SampleRows(std::move(cols), {});
}
}  // namespace

// The velocity v of a wall at displacement d over the next step of length dt, halted at its stop
// (max_travel): it arrives there at the end of the step and stays (an inelastic stop).
double WallControlModule::stopped(const WallControlSpec& s, double d, double v, double dt) {
  return d + v * dt > s.max_travel ? std::max(0.0, s.max_travel - d) / dt : v;
}

WallControlModule::WallControlModule(std::vector<WallControlSpec> walls)
    : specs_(std::move(walls)),
      displacement_(specs_.size(), 0.0),
      samples_(motion_columns(specs_)) {}

double WallControlModule::force(const Simulation& sim, std::size_t k) const {
  return -dot(sim.walls.at(specs_[k].wall)->force, specs_[k].direction);
}

void WallControlModule::setup(Simulation& sim) {
  for (const auto& s : specs_) {
    Wall& w = *sim.walls.at(s.wall);
    w.kinematics.velocity = {};
    // a free body from rest: the first step moves at the mid-step velocity 0 + a dt/2, with the
    // particles' force at t = 0 taken as zero (the forces are computed after set-up)
    if (s.free_body()) {
      const double a = dot(sim.gravity, s.direction) + s.push / s.mass;
      w.kinematics.velocity = stopped(s, 0.0, 0.5 * sim.dt * a, sim.dt) * s.direction;
    }
  }
}

void WallControlModule::post_force(Simulation& sim) {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const WallControlSpec& s = specs_[k];
    Wall& w = *sim.walls[s.wall];
    const double v_now = dot(w.kinematics.velocity, s.direction);
    displacement_[k] += v_now * sim.dt;  // the wall moved with it in this step's drift
    double v_next = 0;
    if (s.mode == WallControlSpec::Mode::servo) {
      // Thornton, Géotechnique 50 (2000) 43, servo walls (as PFC): v = G (F_target − F), eq. W1
      // the pre-load until the hold ends, then the target
      const double target = sim.time < s.preload_time ? s.preload_force : s.target_force;
      v_next = std::clamp(s.gain * (target - force(sim, k)), -s.max_speed, s.max_speed);
    } else {
      // Newton's second law along n, m dv/dt = m g·n + F_push + F·n − c v, leapfrog:
      // docs/models.md eqs. W2 (dead weight) and W4 (floating, F_push and c)
      const double a = dot(sim.gravity, s.direction) +
                       (s.push + dot(w.force, s.direction) - s.damping * v_now) / s.mass;
      v_next = stopped(s, displacement_[k], v_now + a * sim.dt, sim.dt);
    }
    w.kinematics.velocity = v_next * s.direction;
  }
}

void WallControlModule::sample(const Simulation& sim) {
  std::vector<double> row;
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const WallControlSpec& s = specs_[k];
    const double f = force(sim, k);
    row.insert(row.end(),
               {displacement_[k], dot(sim.walls[s.wall]->kinematics.velocity, s.direction), f,
                s.area > 0 ? f / s.area : 0.0});
    if (std::isfinite(s.gap)) row.push_back(s.gap - displacement_[k]);
  }
  samples_.add(sim.time, row);
}

std::vector<Table> WallControlModule::tables(const Simulation&) const {
  return {samples_.table("wall_control")};
}

void WallControlModule::save(Archive& a) const {
  a.put("wall_control/displacement", displacement_);
  samples_.save(a, "wall_control/samples");
}

void WallControlModule::load(const Archive& a) {
  displacement_ = a.get<double>("wall_control/displacement");
  samples_.load(a, "wall_control/samples");
  if (displacement_.size() != specs_.size())
    throw Error(
        fmt::format("checkpoint entry 'wall_control/displacement' holds {} walls, the "
                    "case {}",
                    displacement_.size(), specs_.size()));
  for (double d : displacement_)
    if (!std::isfinite(d))
      throw Error("checkpoint entry 'wall_control/displacement' is not finite");
}

}  // namespace comminute
