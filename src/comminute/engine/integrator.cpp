#include "comminute/engine/integrator.hpp"

#include <algorithm>
#include <limits>

#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

namespace {
// 0 when every component of `a` is finite, else NaN (inf - inf and NaN - NaN are NaN): summed over
// the particles without a branch per component.
inline double finite_probe(const Vec3& a) {
  return (a.x - a.x) + (a.y - a.y) + (a.z - a.z);
}
}  // namespace

VelocityVerlet::Drift VelocityVerlet::kick_drift(ParticleStore& p, double dt, const Vec3& gravity,
                                                 const std::vector<Vec3>* x_build) {
  const std::size_t n = p.owned();
  // (the build positions also hold the ghosts of a periodic run, after the owned particles)
  const bool track = x_build != nullptr && x_build->size() >= n;
  const Vec3* xb = track ? x_build->data() : nullptr;
  const double h = 0.5 * dt;
  const Vec3 g = gravity;
  double worst = 0, step = 0;
  double probe = 0;  // stays exactly 0 while every position is finite, in any summation order
#pragma omp parallel for schedule(static) reduction(max : worst, step) reduction(+ : probe) \
    if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
      const Vec3 dx = dt * p.v[i];
      p.x[i] += dx;
      step = std::max(step, norm2(dx));
    }
    p.f[i] = p.mass[i] * g;
    p.t[i] = {};
    probe += finite_probe(p.x[i]);
    if (track) worst = std::max(worst, norm2(p.x[i] - xb[i]));
  }
  const double from_build2 =
      track ? worst : (x_build ? std::numeric_limits<double>::infinity() : 0.0);
  return {from_build2, step, probe == 0};
}

bool VelocityVerlet::kick(ParticleStore& p, double dt) {
  const std::size_t n = p.owned();
  const double h = 0.5 * dt;
  double probe = 0;  // stays exactly 0 while every velocity is finite, in any summation order
#pragma omp parallel for schedule(static) reduction(+ : probe) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
    }
    probe += finite_probe(p.v[i]) + finite_probe(p.w[i]);
  }
  return !(probe == 0);
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
