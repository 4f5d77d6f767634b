#include "comminute/engine/time_step_policy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "comminute/core/units.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/fracture/rayleigh_time.hpp"

namespace comminute {

TimeStepPolicy::TimeStepPolicy(const CaseTable& simulation, double end_time)
    : table_(simulation), end_time_(end_time) {
  fraction_ = simulation.number("time_step_fraction", Limits{0.0, 1.0, true, false}, 0.2);
  if (simulation.has("time_step")) given_ = simulation.number("time_step", Limits::positive());
}

TimeStepPolicy::Decision TimeStepPolicy::decide(Simulation& sim) const {
  std::vector<ParticleSize> sizes = sizes_;
  for (const auto& m : sim.modules) m->announce_sizes(sizes, sim);
  const auto rayleigh = [&sim](const ParticleSize& s) {
    const Material& m = sim.materials.material(s.material);
    return fracture::rayleigh_time(2 * s.radius, m.density, m.shear_modulus(), m.poisson_ratio);
  };
  // the smallest Rayleigh time of the inserted particles, and the lightest inserted particle
  double t_inserted = std::numeric_limits<double>::infinity();
  const ParticleSize* lightest = nullptr;
  for (const auto& s : sizes)
    if (!s.announced) {
      t_inserted = std::min(t_inserted, rayleigh(s));
      if (lightest == nullptr || s.radius < lightest->radius) lightest = &s;
    }
  Decision d;
  double dt_smallest = 0;  // s, the smallest step a following step can reach (0: fixed step)
  sim.step_control.reset();
  if (given_ > 0) {
    d.dt = given_;
    d.note = fmt::format("time step {:.4g} s (set) = {:.1f} % of the Rayleigh time {:.4g} s", d.dt,
                         100 * d.dt / t_inserted, t_inserted);
    if (d.dt > 0.3 * t_inserted)
      d.warnings.push_back(fmt::format(
          "the time step {:.4g} s is {:.0f} % of the Rayleigh time {:.4g} s of the smallest "
          "particle; above ~30 % contacts are under-resolved and the run may blow up",
          d.dt, 100 * d.dt / t_inserted, t_inserted));
    for (const auto& s : sizes)
      if (s.announced && d.dt > 0.3 * rayleigh(s))
        table_.fail("time_step", fmt::format("{:.4g} s is {:.0f} % of the Rayleigh time {:.4g} s "
                                             "of {}",
                                             d.dt, 100 * d.dt / rayleigh(s), rayleigh(s), s.what));
  } else {
    d.dt = fraction_ * t_inserted;
    d.note = fmt::format("time step {:.4g} s = {:.0f} % of the Rayleigh time {:.4g} s", d.dt,
                         100 * fraction_, t_inserted);
    // Smaller particles can appear (fragments): the step follows the particles present, down to
    // the smallest one announced, instead of being cut for it from the start.
    const ParticleSize* smallest = nullptr;
    for (const auto& s : sizes)
      if (s.announced && fraction_ * rayleigh(s) < d.dt &&
          (smallest == nullptr || rayleigh(s) < rayleigh(*smallest)))
        smallest = &s;
    if (smallest != nullptr) {
      sim.step_control.emplace(fraction_, d.dt);
      dt_smallest = fraction_ * rayleigh(*smallest);
      d.note += fmt::format(
          "; follows the particles present: {:.0f} % of the Rayleigh time of the smallest, down "
          "to {:.4g} s for {}",
          100 * fraction_, fraction_ * rayleigh(*smallest), smallest->what);
    }
  }
  if (lightest != nullptr) {  // the law's own limit for the lightest pair
    const Material& m = sim.materials.material(lightest->material);
    const StepLimit limit =
        sim.law->step_limit(sim.materials.pair(lightest->material, lightest->material),
                            lightest->radius, m.density * units::sphere_volume(lightest->radius));
    if (d.dt > limit.dt)
      d.warnings.push_back(fmt::format("the time step {:.4g} s {}", d.dt, limit.reason));
  }
  const std::string key = given_ > 0 ? "time_step" : "end_time";
  if (!(d.dt > 0) || !std::isfinite(d.dt))
    table_.fail(key, fmt::format("time step {:.4g} s", d.dt));
  if (d.dt > end_time_)
    table_.fail(key, fmt::format("the time step {:.4g} s exceeds the end time {:.4g} s: the run "
                                 "would take no step",
                                 d.dt, end_time_));
  // with a following step, the count at its smallest (a run of small fragments only)
  const double dt_min = dt_smallest > 0 ? dt_smallest : d.dt;
  if (end_time_ / dt_min > max_steps)
    table_.fail(key, fmt::format("end time {:.4g} s / time step {:.4g} s = {:.3g} steps, more than "
                                 "the limit of {:.0e} steps",
                                 end_time_, dt_min, end_time_ / dt_min, max_steps));
  sim.dt = d.dt;
  return d;
}

}  // namespace comminute
