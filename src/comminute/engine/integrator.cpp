#include "comminute/engine/integrator.hpp"

#include <algorithm>
#include <limits>

#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

double VelocityVerlet::kick_drift(ParticleStore& p, double dt, const Vec3& gravity,
                                  const std::vector<Vec3>& x_build) {
  const std::size_t n = p.owned();
  // (the build positions also hold the ghosts of a periodic run, after the owned particles)
  const bool track = x_build.size() >= n;
  const double h = 0.5 * dt;
  const Vec3 g = gravity;
  double worst = 0;
#pragma omp parallel for schedule(static) reduction(max : worst) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
      p.x[i] += dt * p.v[i];
    }
    p.f[i] = p.mass[i] * g;
    p.t[i] = {};
    if (track) worst = std::max(worst, norm2(p.x[i] - x_build[i]));
  }
  return track ? worst : std::numeric_limits<double>::infinity();
}

bool VelocityVerlet::kick(ParticleStore& p, double dt) {
  const std::size_t n = p.owned();
  const double h = 0.5 * dt;
  bool bad = false;
#pragma omp parallel for schedule(static) reduction(|| : bad) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
    }
    bad = bad || !is_finite(p.x[i]) || !is_finite(p.v[i]) || !is_finite(p.w[i]);
  }
  return bad;
}

void VelocityVerlet::start_forces(ParticleStore& p, const Vec3& gravity) {
  const std::size_t n = p.owned();  // ghosts start from zero: their owners carry the gravity
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    p.f[i] = p.mass[i] * gravity;
    p.t[i] = {};
  }
}

}  // namespace comminute
