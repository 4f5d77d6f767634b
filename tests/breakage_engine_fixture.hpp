#pragma once
// Engine-level set-ups for the breakage tests: a "gas" of weak particles in a closed box (many
// breakage events in few steps) and a bed compressed by a platen.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "comminute/breakage/breakage_module.hpp"
#include "comminute/breakage/criteria/tavares.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

namespace comminute::testing {

// Tavares material with absorbed-basis E_inf (J/kg), no size effect.
inline breakage::MaterialBreakage weak_material(double e_inf, double sigma, double min_breakable,
                                                double min_ratio, breakage::FinesRule fines,
                                                double release) {
  breakage::TavaresParameters tp;
  tp.size_effect = {e_inf, 0.0, 1.0, 1.0};
  tp.sigma = sigma;
  tp.damage.gamma = 3.0;
  breakage::MaterialBreakage m;
  m.criterion = std::make_unique<breakage::Tavares>(tp);
  m.min_breakable_size = min_breakable;
  m.min_fragment_ratio = min_ratio;
  m.fines = fines;
  m.release_fraction = release;
  return m;
}

// Particles of diameter d on a jittered cubic lattice filling [0, L]^3 with spacing a.
inline void lattice(Simulation& sim, double d, double a, double L, double speed, Rng& rng) {
  for (double x = a / 2; x < L; x += a)
    for (double y = a / 2; y < L; y += a)
      for (double z = a / 2; z < L; z += a)
        add_sphere(
            sim, {x, y, z}, d / 2,
            {speed * rng.uniform(-1, 1), speed * rng.uniform(-1, 1), speed * rng.uniform(-1, 1)});
}

// A gas of 3 mm spheres (E = 50 MPa, e = 0.8) on a 6 x 6 x 6 jittered lattice, speeds up to
// 3 m/s per axis, in a closed 21.6 mm box wall: many breakage events in few steps.
inline std::unique_ptr<Simulation> box_gas(double friction, std::uint64_t seed) {
  DemSetup s;
  s.youngs = 5e7;
  s.restitution = 0.8;
  s.friction = friction;
  auto sim = make_simulation(s);
  Rng rng(seed);
  const double d = 0.003, a = 0.0036, L = 6 * a;
  lattice(*sim, d, a, L, 3.0, rng);
  sim->walls.push_back(
      std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{L, L, L}, std::array<bool, 6>{}));
  return sim;
}

// The gas of box_gas (friction 0.3) as a breakage test runs it: weak Tavares particles
// (weak_material: E_inf 0.02 J/kg, sigma 0.3; fragments below 0.3 of the parent's diameter go to
// the fines by mass; 20 % of the absorbed energy given as radial speed) breakable down to
// `min_breakable` (m), the breakage module registered (returned in `module`), and a time step of a
// fifth of the Rayleigh time of the smallest fragment (r = 0.18 mm); `seed` jitters the lattice and
// the starting velocities.
inline std::unique_ptr<Simulation> breakage_gas(breakage::BreakageModule** module,
                                                double min_breakable = 0.0012,
                                                std::uint64_t seed = 29) {
  auto sim = box_gas(0.3, seed);
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(weak_material(0.02, 0.3, min_breakable, 0.3, breakage::FinesRule::mass, 0.2));
  auto mod =
      std::make_unique<breakage::BreakageModule>(std::move(mats), breakage::BreakageOptions{});
  mod->register_fields(sim->particles);
  *module = mod.get();
  sim->modules.push_back(std::move(mod));
  sim->dt = 0.2 * 3.1416 * 0.00018 * std::sqrt(2500 / (5e7 / 2.6)) / (0.1631 * 0.3 + 0.8766);
  return sim;
}

// Records mass and momentum (particles + fines booked as mass) around the breakage module's
// end_of_step: `before` runs just ahead of it, `after` just behind it.
struct BreakageProbe {
  const breakage::BreakageModule* module = nullptr;
  double mass_before = 0, mass_after = 0;
  Vec3 momentum_before, momentum_after;
  double ke_before = 0, ke_after = 0;
  double worst_mass_error = 0;      // relative
  double worst_momentum_error = 0;  // kg m/s, absolute (the test scales it)
  double worst_ke_excess = 0;       // max over steps of (KE jump - configured released energy) / KE
  std::uint64_t breakages_before = 0;
  double max_rigid_speed_before = 0;  // m/s, max over particles of |v| + |w| r before replacement
  std::uint64_t next_id_before = 0;
  double worst_fragment_speed_ratio = 0;  // max over new fragments of speed / bound
};

inline double fines_total(const breakage::BreakageModule& m) {
  double s = 0;
  for (double f : m.fines_mass()) s += f;
  return s;
}

inline double kinetic_energy(const ParticleStore& p) {
  double ke = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    ke += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]);
  return ke;
}

class ProbeBefore final : public Module {
 public:
  explicit ProbeBefore(BreakageProbe* p) : p_(p) {}
  std::string name() const override { return "probe_before"; }
  void end_of_step(Simulation& sim) override {
    p_->mass_before = sim.particles.total_mass() + fines_total(*p_->module);
    p_->momentum_before = sim.particles.total_momentum() + p_->module->fines_momentum();
    p_->ke_before = kinetic_energy(sim.particles);
    p_->breakages_before = p_->module->breakages();
    p_->next_id_before = sim.particles.next_id();
    p_->max_rigid_speed_before = 0;
    const auto& p = sim.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      p_->max_rigid_speed_before =
          std::max(p_->max_rigid_speed_before, norm(p.v[i]) + norm(p.w[i]) * p.radius[i]);
  }

 private:
  BreakageProbe* p_;
};

class ProbeAfter final : public Module {
 public:
  ProbeAfter(BreakageProbe* p, double release_fraction)
      : p_(p), release_fraction_(release_fraction) {}
  std::string name() const override { return "probe_after"; }
  void end_of_step(Simulation& sim) override {
    const double mass = sim.particles.total_mass() + fines_total(*p_->module);
    const Vec3 mom = sim.particles.total_momentum() + p_->module->fines_momentum();
    p_->worst_mass_error =
        std::max(p_->worst_mass_error, std::abs(mass - p_->mass_before) / p_->mass_before);
    p_->worst_momentum_error = std::max(p_->worst_momentum_error, norm(mom - p_->momentum_before));
    // Configured released energy of this step's breakages: eta x absorbed energy x parent mass.
    double released = 0;
    const auto& log = p_->module->log();
    const std::uint64_t new_breaks = p_->module->breakages() - p_->breakages_before;
    std::uint64_t seen = 0;
    for (auto it = log.rbegin(); it != log.rend() && seen < new_breaks; ++it)
      if (it->broken) {
        ++seen;
        released += release_fraction_ * it->specific_energy * it->mass;
      }
    // Fragments leave no faster than their parent's rigid motion plus the radial release cap
    // 2 c, c <= sqrt(8 eta E) (fragment_velocities): checked against the fastest parent of the
    // step and the largest absorbed energy among this step's breakages.
    if (new_breaks > 0) {
      double e_max = 0;
      std::uint64_t k = 0;
      for (auto it = log.rbegin(); it != log.rend() && k < new_breaks; ++it)
        if (it->broken) {
          ++k;
          e_max = std::max(e_max, it->specific_energy);
        }
      const double bound =
          p_->max_rigid_speed_before + 2 * std::sqrt(8 * release_fraction_ * e_max);
      for (std::size_t i = 0; i < sim.particles.size(); ++i)
        if (sim.particles.id[i] >= p_->next_id_before)
          p_->worst_fragment_speed_ratio =
              std::max(p_->worst_fragment_speed_ratio, norm(sim.particles.v[i]) / bound);
    }
    // KE of fines booked as mass leaves with them, so it only lowers the after-value.
    const double jump = kinetic_energy(sim.particles) - p_->ke_before - released;
    p_->worst_ke_excess = std::max(p_->worst_ke_excess, jump / std::max(p_->ke_before, 1e-30));
  }

 private:
  BreakageProbe* p_;
  double release_fraction_;
};

}  // namespace comminute::testing
