#pragma once
// The time step during a run that lets it follow the particles present (set by TimeStepPolicy
// when [simulation] time_step is not given and a module can create particles smaller than the
// inserted ones, i.e. breakage). Before each step:
//   dt = min(ceiling, fraction x min over the particles present of t_R(R_i, material_i))
// with t_R the Rayleigh time (docs/models.md eq. R1) and `ceiling` the step of the inserted sizes.
// A fragment still growing counts at its full size, the radius its mass has at its material's
// density, so growth never moves the step. The step is a function of the particle state alone
// (radius, mass, flags, material: all checkpointed), so a restart takes the same steps.
#include <vector>

#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class TimeStepControl {
 public:
  // fraction in (0, 1]; ceiling (s) > 0.
  TimeStepControl(double fraction, double ceiling) : fraction_(fraction), ceiling_(ceiling) {}

  // The step (s) for the particles in `p`.
  double decide(const ParticleStore& p, const MaterialTable& materials) const;
  double fraction() const { return fraction_; }
  double ceiling() const { return ceiling_; }

 private:
  double fraction_;
  double ceiling_;                     // s
  mutable std::vector<double> r_min_;  // m, per material (scratch)
};

}  // namespace comminute
