#pragma once
// Velocity Verlet for translation and rotation (spheres: isotropic inertia), split as the step
// needs it: the first half kick and the drift, then — after the forces — the second half kick.
// Each pass runs over the threads' particle ranges (particle_ranges.hpp).
#include <vector>

#include "comminute/core/vec3.hpp"
#include "comminute/engine/particle_ranges.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class VelocityVerlet {
 public:
  // What a drift moved: the largest |x - x_build|^2 when `x_build` is given (infinity when it
  // does not hold a position per owned particle: the caller then rebuilds; 0 when not given), the
  // largest squared displacement of this drift (m2), and whether every position is finite.
  struct Drift {
    double from_build2 = 0;
    double step2 = 0;
    bool finite = true;
  };
  // First half kick and drift of every free owned particle (ghosts follow their owners), and the
  // start of the force sum (gravity, zero torque) in the same pass.
  static Drift kick_drift(ParticleStore& p, double dt, const Vec3& gravity,
                          const std::vector<Vec3>* x_build, const ParticleRanges& ranges);
  // Second half kick of the owned particles; true when some particle's velocity became
  // non-finite (the drift checks the positions).
  static bool kick(ParticleStore& p, double dt, const ParticleRanges& ranges);
  // Sets every owned particle's force to its weight and its torque to zero.
  static void start_forces(ParticleStore& p, const Vec3& gravity, const ParticleRanges& ranges);
};

}  // namespace comminute
