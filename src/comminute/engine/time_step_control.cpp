#include "comminute/engine/time_step_control.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/engine/simulation.hpp"
#include "comminute/fracture/rayleigh_time.hpp"

namespace comminute {

void TimeStepControl::particle_limits(const Simulation& sim) const {
  const ParticleStore& p = sim.particles;
  const std::size_t n = p.size();
  radius_.resize(n);
  limit_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Material& m = sim.materials.material(p.material[i]);
    double r = p.radius[i];
    if (p.flags[i] & pflag::growing)  // at full size: R = (3 m / (4 pi rho))^(1/3)
      r = std::max(r, std::cbrt(3 * p.mass[i] / (4 * std::numbers::pi * m.density)));
    radius_[i] = r;
    // docs/models.md eq. R1 (Li, Xu & Thornton, Powder Technol. 2005)
    limit_[i] =
        fraction_ * fracture::rayleigh_time(2 * r, m.density, m.shear_modulus(), m.poisson_ratio);
  }
}

double TimeStepControl::all_present(const Simulation& sim) const {
  particle_limits(sim);
  double dt = ceiling_;
  for (double l : limit_) dt = std::min(dt, l);
  return dt;
}

TimeStepControl::Step TimeStepControl::decide(const Simulation& sim) const {
  const ParticleStore& p = sim.particles;
  const std::size_t n = p.size();
  const NeighborList& nl = sim.pairs();
  if (nl.ids_at_build() != p.id) return {all_present(sim), false};  // lists out of date
  particle_limits(sim);
  const double h = ceiling_;
  v_half_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    v_half_[i] = p.v[i];
    if (!(p.flags[i] & pflag::fixed)) v_half_[i] += (0.5 * h / p.mass[i]) * p.f[i];
    // a pair outside the lists could touch within this step: the conservative step, and new
    // lists after the drift
    if (sim.reach_margin(i) < 2 * h * norm(v_half_[i])) {
      double dt = ceiling_;
      for (double l : limit_) dt = std::min(dt, l);
      return {dt, true};
    }
  }
  double dt = ceiling_;
  for (std::size_t k = 0; k < nl.size(); ++k) {
    const std::uint32_t i = nl.first[k], j = nl.second[k];
    const double lim = std::min(limit_[i], limit_[j]);
    if (lim >= dt) continue;
    const double gap = norm(p.x[i] - p.x[j]) - radius_[i] - radius_[j];
    if (gap <= 2 * h * norm(v_half_[i] - v_half_[j])) dt = lim;
  }
  std::vector<WallContact> found;
  auto near_wall = [&](std::size_t i, const Wall& w) {
    const double speed = norm(v_half_[i]) + norm(w.kinematics.velocity_at(p.x[i]));
    found.clear();
    return w.contacts(p.x[i], radius_[i], 2 * h * speed, found) > 0;
  };
  // static walls: a particle that keeps its reach margin can only touch its candidates
  for (const WallContactRecord& c : sim.wall_candidates())
    if (limit_[c.particle] < dt && !sim.walls[c.wall]->kinematics.moving() &&
        near_wall(c.particle, *sim.walls[c.wall]))
      dt = limit_[c.particle];
  // moving walls travel regardless of the particles' margins: every particle is tested
  for (const auto& w : sim.walls)
    if (w->kinematics.moving())
      for (std::size_t i = 0; i < n; ++i)
        if (limit_[i] < dt && near_wall(i, *w)) dt = limit_[i];
  return {dt, false};
}

}  // namespace comminute
