#pragma once
// The time step during a run that lets it follow the particles present (set by TimeStepPolicy
// when [simulation] time_step is not given and a module can create particles smaller than the
// inserted ones, i.e. breakage). Before each step (docs/models.md, "Time step"):
//   dt = min(ceiling, f t_R(i, j) over the pairs (i, j) and particle-wall pairs that touch or
//        could touch within a step of `ceiling`)
// with t_R(i, j) the smaller Rayleigh time (docs/models.md eq. R1) of the two particles and
// `ceiling` the step of the inserted sizes: a contact is resolved from its first step on, and a
// small fragment flying free does not hold back everyone. "Could touch" is tested on the
// neighbour lists: a listed pair whose gap is below twice its relative displacement over a step
// of `ceiling`; pairs outside the lists cannot touch while every particle keeps its reach margin
// (skin/2 minus its motion since the build) above twice its own displacement over such a step
// (static walls likewise with their candidates; moving walls are tested against every particle).
// Where that cannot be shown (lists out of date, a margin too small) the step is the fraction of
// the smallest Rayleigh time of all particles present, and when it was a margin the lists are
// rebuilt after this step's drift, so the next step can be long again. A fragment still growing
// counts at its full size (the radius its mass has at its material's density). The step is a
// function of the checkpointed state (particles, forces, lists), so a restart takes the same
// steps.
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

class Simulation;

class TimeStepControl {
 public:
  // fraction in (0, 1]; ceiling (s) > 0.
  TimeStepControl(double fraction, double ceiling) : fraction_(fraction), ceiling_(ceiling) {}

  struct Step {
    double dt = 0;         // s
    bool rebuild = false;  // the neighbour lists should be rebuilt after this step's drift
  };
  // The step for the simulation's state at the start of a step.
  Step decide(const Simulation& sim) const;
  // The conservative step: the fraction of the smallest Rayleigh time of all particles present
  // (at most the ceiling).
  double all_present(const Simulation& sim) const;
  double fraction() const { return fraction_; }
  double ceiling() const { return ceiling_; }

 private:
  void particle_limits(const Simulation& sim) const;

  double fraction_;
  double ceiling_;  // s
  // scratch, per particle: full radius (m), f t_R (s), velocity after the opening half kick of a
  // step of `ceiling` (m/s)
  mutable std::vector<double> radius_, limit_;
  mutable std::vector<Vec3> v_half_;
};

}  // namespace comminute
