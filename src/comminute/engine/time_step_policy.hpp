#pragma once
// The one place that sets the time step, once, before a run. Keys of [simulation]: time_step (s)
// or time_step_fraction (-, default 0.2) of the smallest Rayleigh time (docs/models.md eq. R1)
// among the particles the run can hold: the inserted ones, and those modules announce (breakage:
// the smallest fragment each material can produce). A given time_step above 30 % of the Rayleigh
// time is a warning for inserted particles and an error for announced ones (fragments are born
// fast and overlapping). The contact law's own limit for the lightest inserted pair is checked
// last (a warning).
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
  explicit TimeStepPolicy(const CaseTable& simulation);
  void add(ParticleSize s) { sizes_.push_back(std::move(s)); }

  struct Decision {
    double dt = 0;                      // s
    std::string note;                   // how it was chosen
    std::vector<std::string> warnings;  // limits it exceeds
  };
  // Collects the modules' announcements, decides and sets sim.dt. Throws InputError naming
  // [simulation] time_step when a given step cannot resolve an announced particle.
  Decision decide(Simulation& sim) const;

 private:
  CaseTable table_;
  double fraction_ = 0.2;
  double given_ = 0;  // s, 0: not given
  std::vector<ParticleSize> sizes_;
};

}  // namespace comminute
