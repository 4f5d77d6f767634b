#pragma once
// The DEM engine: particles, materials, walls, one contact law, gravity, modules and the time
// loop (velocity Verlet for translation and rotation).
#include <cstdint>
#include <memory>
#include <vector>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/contact_state.hpp"
#include "comminute/contact/rolling_resistance.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

// A particle–wall contact candidate, keyed by particle id, wall and feature; its state is in
// wall_state() at the same index. wall_contacts() lists those touching in the last force
// computation, with `candidate` pointing to their state.
struct WallContactRecord {
  std::uint32_t particle = 0;  // current slot
  std::uint32_t wall = 0;
  std::int32_t feature = 0;
  std::uint32_t candidate = 0;  // index in the candidate list (and wall_state())
  std::uint64_t id = 0;         // particle id
};

// Running energy ledger (J), for the time-series output and conservation checks.
struct EnergyLedger {
  double damping = 0;    // dissipated by normal/tangential dashpots
  double friction = 0;   // dissipated by sliding and rolling friction
  double removed = 0;    // taken out by modules (breakage, particle removal), see their logs
  double wall_work = 0;  // work done on the particles by moving walls
};

struct Observables {
  double time = 0;
  std::uint64_t step = 0;
  std::size_t particles = 0;
  std::size_t contacts = 0;          // particle–particle contacts with overlap > 0
  std::size_t wall_contacts = 0;     // particle–wall contacts with overlap > 0
  double kinetic_translational = 0;  // J
  double kinetic_rotational = 0;     // J
  double potential_gravity = 0;      // J, relative to z = 0 along -gravity
  double elastic = 0;                // J, stored in contacts
  EnergyLedger ledger;
};

// A fragment appended by a breakage module: its id and the radius it will grow to.
struct NewFragment {
  std::uint64_t id = 0;
  double final_radius = 0;  // m
};

struct SimulationOptions {
  double skin = 0;      // m, Verlet skin (0: 0.2 x mean diameter at the first build with particles)
  int sort_every = 20;  // re-sort particles by cell every this many list rebuilds (0: never)
};

class Simulation {
 public:
  Simulation();
  ~Simulation();

  ParticleStore particles;
  MaterialTable materials;
  std::vector<std::unique_ptr<Wall>> walls;
  std::unique_ptr<ContactLaw> law;
  std::unique_ptr<RollingResistance> rolling;  // may be null (no rolling resistance)
  std::unique_ptr<Cohesion> cohesion;          // may be null (no adhesion)
  std::vector<std::unique_ptr<Module>> modules;
  Vec3 gravity{0, 0, -9.81};  // m/s2
  double dt = 0;              // s
  double time = 0;            // s
  std::uint64_t step_count = 0;
  std::uint64_t seed = 1;
  SimulationOptions options;
  EnergyLedger ledger;

  // Prepares neighbour search and modules; call after particles/walls/law are set.
  void setup();
  // Advances n steps. Throws SimulationError on a non-finite position/velocity (names id, time).
  void run(std::uint64_t n);
  void step();
  // Forces the neighbour list to be rebuilt before the next force computation.
  void particles_changed() {
    need_rebuild_ = true;
    forces_cleared_ = false;
  }
  // After compact() removed broken parents and their fragments were appended: updates the
  // neighbour list in place instead of rebuilding it. Each fragment gets every partner within
  // skin of its sphere at its final radius (a local search of the build's cell grids), so the
  // usual skin/2 trigger stays exact and growth needs no rebuild. Falls back to
  // particles_changed() when the update is not possible.
  void particles_replaced(const std::vector<NewFragment>& fragments);
  // How much particle i may still move or grow (m) before the neighbour list stops covering it:
  // skin/2 - (|x - x_build| + r - r_build). Radii may change between rebuilds only for particles
  // flagged pflag::growing (and fragments); a module that grows one by more than this margin must
  // call particles_changed().
  double reach_margin(std::size_t i) const;

  const NeighborList& pairs() const { return nlist_; }
  NeighborList& pairs() { return nlist_; }
  // Per-pair state, indexed like pairs(); per wall-candidate state, indexed by
  // WallContactRecord::candidate.
  const ContactStateStore& pair_state() const { return pair_state_; }
  const ContactStateStore& wall_state() const { return wall_state_; }
  const std::vector<WallContactRecord>& wall_contacts() const { return wall_contacts_; }
  // The contact model (law, rolling, adhesion, loading record), assembled at setup or load.
  const ContactPipeline& contacts() const { return contacts_; }
  Observables observe() const;
  // Smallest Rayleigh time over the particles (s): pi R sqrt(rho/G) / (0.1631 nu + 0.8766).
  double rayleigh_time() const;
  std::uint64_t neighbor_rebuilds() const { return rebuilds_; }

  void save(Archive& a) const;
  void load(const Archive& a);

 private:
  void assemble_contacts();
  void compute_forces();
  void particle_particle_forces();
  void particle_wall_forces();
  void rebuild();
  void build_wall_candidates();
  void add_wall_candidates(std::uint32_t i, std::uint32_t w, const Vec3& x, double r,
                           std::vector<WallContact>& found,
                           std::vector<WallContactRecord>& into) const;
  void kick_drift();
  bool kick();
  [[noreturn]] void report_non_finite() const;

  NeighborList nlist_;
  ContactPipeline contacts_;
  ContactStateStore pair_state_, wall_state_;
  std::vector<WallContactRecord> wall_candidates_;  // near walls at the last build
  std::vector<WallContactRecord> wall_contacts_;    // touching now
  std::vector<std::uint8_t> wall_full_scan_;        // per wall: surface moves, check every step
  std::vector<double> wall_travel_;                 // per wall: distance moved since the build
  // Reach at the last build: a particle's pairs cover every sphere within skin of the sphere
  // (x_at_build_, r_at_build_); fragments appended in place get theirs at insertion.
  std::vector<Vec3> x_at_build_;
  std::vector<double> r_at_build_;
  std::vector<std::uint32_t> reach_tracked_;  // slots whose radius or reach changed since the build
  struct CrossForce {  // a pair's share for a particle owned by another thread
    std::uint32_t particle;
    Vec3 force, torque;
  };
  std::vector<std::vector<CrossForce>> cross_;  // per thread, reused
  bool need_rebuild_ = true;
  bool forces_cleared_ = false;
  bool is_setup_ = false;
  std::uint64_t rebuilds_ = 0;
  double elastic_energy_ = 0;
  double max_disp2_ = 0;
  double reach_change(std::size_t i) const;  // |x - x_build| + r - r_build (m)
};

}  // namespace comminute
