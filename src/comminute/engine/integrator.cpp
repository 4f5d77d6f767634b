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

int threads_for(std::size_t n) {
  return n >= kParallelMin ? max_threads() : 1;
}

// What one thread's range of a pass found (on a cache line of its own: the threads write them side
// by side).
struct alignas(64) Partial {
  double worst = 0, step = 0, probe = 0;
};
}  // namespace

VelocityVerlet::Drift VelocityVerlet::kick_drift(ParticleStore& p, double dt, const Vec3& gravity,
                                                 const std::vector<Vec3>* x_build,
                                                 const ParticleRanges& ranges) {
  const std::size_t n = p.owned();
  // (the build positions also hold the ghosts of a periodic run, after the owned particles)
  const bool track = x_build != nullptr && x_build->size() >= n;
  const Vec3* xb = track ? x_build->data() : nullptr;
  const double h = 0.5 * dt;
  const Vec3 g = gravity;
  const int nt = threads_for(n);
  std::vector<Partial> part(static_cast<std::size_t>(nt));
  for_each_range(ranges, n, nt, [&](std::size_t b, std::size_t e, int t) {
    double worst = 0, step = 0;
    double probe = 0;  // stays exactly 0 while every position is finite, in any summation order
    for (std::size_t i = b; i < e; ++i) {
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
    part[static_cast<std::size_t>(t)] = {worst, step, probe};
  });
  double worst = 0, step = 0, probe = 0;
  for (const Partial& q : part) {
    worst = std::max(worst, q.worst);
    step = std::max(step, q.step);
    probe += q.probe;
  }
  const double from_build2 =
      track ? worst : (x_build ? std::numeric_limits<double>::infinity() : 0.0);
  return {from_build2, step, probe == 0};
}

bool VelocityVerlet::kick(ParticleStore& p, double dt, const ParticleRanges& ranges) {
  const std::size_t n = p.owned();
  const double h = 0.5 * dt;
  const int nt = threads_for(n);
  std::vector<Partial> part(static_cast<std::size_t>(nt));
  for_each_range(ranges, n, nt, [&](std::size_t b, std::size_t e, int t) {
    double probe = 0;  // stays exactly 0 while every velocity is finite, in any summation order
    for (std::size_t i = b; i < e; ++i) {
      if (!(p.flags[i] & pflag::fixed)) {
        p.v[i] += (h / p.mass[i]) * p.f[i];
        p.w[i] += (h / p.inertia[i]) * p.t[i];
      }
      probe += finite_probe(p.v[i]) + finite_probe(p.w[i]);
    }
    part[static_cast<std::size_t>(t)].probe = probe;
  });
  double probe = 0;
  for (const Partial& q : part) probe += q.probe;
  return !(probe == 0);
}

void VelocityVerlet::start_forces(ParticleStore& p, const Vec3& gravity,
                                  const ParticleRanges& ranges) {
  const std::size_t n = p.owned();  // ghosts start from zero: their owners carry the gravity
  for_each_range(ranges, n, threads_for(n), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t i = b; i < e; ++i) {
      p.f[i] = p.mass[i] * gravity;
      p.t[i] = {};
    }
  });
}

}  // namespace comminute
