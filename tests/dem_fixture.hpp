#pragma once
// Small DEM set-ups shared by the engine tests.
#include <memory>

#include "comminute/engine/simulation.hpp"
#include "comminute/geometry/box_wall.hpp"

namespace comminute::testing {

struct DemSetup {
  std::string law = "hertz_mindlin";
  double restitution = 0.5;
  double friction = 0.0;
  double dynamic_friction = -1.0;  // < 0: the same as friction
  double rolling_friction = 0.0;
  double cohesion = 0.0;          // J/m3
  double linear_stiffness = 1e5;  // N/m (linear law)
  double youngs = 1e7, poisson = 0.3, density = 2500;
  std::string rolling;  // "" = none
  Vec3 gravity{0, 0, 0};
  std::string contact_keys;  // more lines of the [contact] table (TOML)
};

// Gravity, sliding friction 0.5 and EPSD rolling resistance (rolling friction 0.1): a bed whose
// contacts carry tangential and rolling springs.
inline DemSetup frictional_rolling_setup() {
  DemSetup s;
  s.gravity = {0, 0, -9.81};
  s.friction = 0.5;
  s.rolling = "epsd";
  s.rolling_friction = 0.1;
  return s;
}

inline std::unique_ptr<Simulation> make_simulation(const DemSetup& s) {
  auto sim = std::make_unique<Simulation>();
  sim->materials.add({"m", s.density, s.youngs, s.poisson});
  PairInput pi;
  pi.restitution = s.restitution;
  pi.friction = s.friction;
  pi.dynamic_friction = s.dynamic_friction;
  pi.rolling_friction = s.rolling_friction;
  pi.cohesion_energy_density = s.cohesion;
  sim->materials.set_pair(0, 0, pi);
  // the [contact] table the models read their keys from
  const CaseFile contact = CaseFile::parse(
      "normal_stiffness = " + std::to_string(s.linear_stiffness) + "\n" + s.contact_keys);
  sim->law = ContactLawRegistry::create(s.law, contact.root());
  if (!s.rolling.empty())
    sim->rolling = RollingResistanceRegistry::create(s.rolling, contact.root());
  if (s.cohesion > 0) sim->cohesion = CohesionRegistry::create("sjkr", contact.root());
  sim->gravity = s.gravity;
  return sim;
}

// A box from lo to hi without its top face (+z open): a bin for beds that settle or are pressed.
inline Wall& add_open_top_box(Simulation& sim, Vec3 lo, Vec3 hi) {
  sim.walls.push_back(std::make_unique<BoxWall>(
      lo, hi, std::array<bool, 6>{false, false, false, false, false, true}));
  return *sim.walls.back();
}

inline std::uint64_t add_sphere(Simulation& sim, Vec3 x, double r, Vec3 v = {}, Vec3 w = {}) {
  ParticleInit p;
  p.x = x;
  p.v = v;
  p.w = w;
  p.radius = r;
  p.density = sim.materials.material(0).density;
  return sim.particles.add(p);
}

inline std::size_t slot_of(const Simulation& sim, std::uint64_t id) {
  for (std::size_t i = 0; i < sim.particles.size(); ++i)
    if (sim.particles.id[i] == id) return i;
  return static_cast<std::size_t>(-1);
}

}  // namespace comminute::testing
