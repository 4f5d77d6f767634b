#pragma once
// The one place that sets the time step, before a run. Keys of [simulation]: time_step (s), kept
// for the whole run, or time_step_fraction (-, default 0.2) of the smallest Rayleigh time
// (docs/models.md eq. R1) of the inserted particles. When a module announces smaller particles
// (breakage: the smallest fragment each material can produce), the step is not cut for them up
// front: the simulation gets a TimeStepControl that sets, before every step, the fraction of the
// smallest Rayleigh time among the particles present (never above the inserted particles' step).
// A given time_step above 30 % of the Rayleigh time is a warning for inserted particles and an
// error for announced ones (fragments are born fast and overlapping). The contact law's own limit
// for the lightest inserted pair is checked last (a warning). The run must take at least one step
// and at most max_steps: more is a mistake (a time step in the wrong unit, an end time in ms); both
// are refused naming the key.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/case_table.hpp"

namespace comminute {

class Simulation;

struct ParticleSize {
  double radius = 0;  // m
  std::uint16_t material = 0;
  std::string what;        // for messages: "the smallest fragment (..) material 'x' can produce"
  bool announced = false;  // by a module (true) or inserted by the case (false)
};

class TimeStepPolicy {
 public:
  // At 10^6 particle-steps/s a run of one particle would take 10^3 s per 10^9 steps.
  static constexpr double max_steps = 1e9;

  // `simulation`: the [simulation] table (its time-step keys); end_time in s.
  TimeStepPolicy(const CaseTable& simulation, double end_time);
  void add(ParticleSize s) { sizes_.push_back(std::move(s)); }

  struct Decision {
    double dt = 0;                      // s
    std::string note;                   // how it was chosen
    std::vector<std::string> warnings;  // limits it exceeds
  };
  // Collects the modules' announcements, decides and sets sim.dt (the first step) and
  // sim.step_control (whether it follows the particles present). Throws InputError naming
  // [simulation] time_step when a given step cannot resolve an announced particle, or when the
  // step count is below one or above max_steps.
  Decision decide(Simulation& sim) const;

 private:
  CaseTable table_;
  double fraction_ = 0.2;
  double given_ = 0;  // s, 0: not given
  double end_time_ = 0;
  std::vector<ParticleSize> sizes_;
};

}  // namespace comminute
