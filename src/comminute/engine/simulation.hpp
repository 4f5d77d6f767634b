#pragma once
// The DEM engine: particles, materials, walls, one contact model, gravity, modules and the time
// loop. The loop delegates to collaborators that own their state: the integrator (velocity
// Verlet), the pair tracker (neighbour list, wall candidates, rebuild trigger, in-place updates),
// the contact pipeline and the pair and wall force loops; per-contact state is in two stores the
// engine owns.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/contact_state.hpp"
#include "comminute/contact/rolling_resistance.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/energy_tally.hpp"
#include "comminute/engine/ghost_exchange.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/pair_force_loop.hpp"
#include "comminute/engine/pair_tracker.hpp"
#include "comminute/engine/time_step_control.hpp"
#include "comminute/engine/wall_contact.hpp"
#include "comminute/engine/wall_force_loop.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

struct Observables {
  double time = 0;
  std::uint64_t step = 0;
  double dt = 0;  // s, the step just taken
  std::size_t particles = 0;
  std::size_t contacts = 0;          // particle–particle contacts with overlap > 0
  std::size_t wall_contacts = 0;     // particle–wall contacts with overlap > 0
  double kinetic_translational = 0;  // J
  double kinetic_rotational = 0;     // J
  double potential_gravity = 0;      // J, relative to z = 0 along -gravity
  double elastic = 0;                // J, stored in contacts
  EnergyLedger ledger;
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
  double dt = 0;              // s, of the step being taken (or last taken)
  // When set, dt follows the particles present: decided before every step (time_step_control.hpp).
  std::optional<TimeStepControl> step_control;
  double time = 0;  // s
  std::uint64_t step_count = 0;
  std::uint64_t seed = 1;
  SimulationOptions options;
  EnergyLedger ledger;

  // Periodic boundaries (geometry/periodic_map.hpp): set before setup() or load(). Ghosts are in
  // the store from the force computation to the modules' post_force (ParticleStore::owned()).
  void set_periodic(const PeriodicMap& map) { ghosts_.map = map; }
  const PeriodicMap& periodic() const { return ghosts_.map; }
  std::size_t ghost_count() const { return ghosts_.size(); }
  // The owned particle a slot of the pair list stands for, where that slot is, and a point seen
  // from the slot brought into its owner's frame (a ghost's slot stays valid after the ghosts are
  // dropped, until the next rebuild; for owned slots: the slot, its position, the point).
  std::size_t slot_owner(std::size_t slot) const;
  Vec3 slot_position(std::size_t slot) const;
  Vec3 to_owner_frame(std::size_t slot, const Vec3& x) const;
  // A point given in the frame of slot `seen`'s owner, as the owner of slot `from` sees it across
  // their pair (the identity unless one of the two is a ghost).
  Vec3 pair_frame(std::size_t from, std::size_t seen, const Vec3& x) const;

  // Prepares neighbour search and modules; call after particles/walls/law are set.
  void setup();
  // Advances n steps. Throws SimulationError on a non-finite position/velocity (names id, time).
  void run(std::uint64_t n);
  void step();
  // Forces the neighbour list to be rebuilt before the next force computation.
  void particles_changed() {
    tracker_.invalidate();
    forces_cleared_ = false;
  }
  // After breakage replaced parents by fragments (`fragments`, all of them): either compact()
  // removed the parents and every fragment was appended (`renewed` empty), or one fragment of
  // each parent took its parent's slot (ParticleStore::renew; `renewed` lists those slots) and
  // the others were appended. Updates the neighbour list in place instead of rebuilding it. Each
  // appended fragment gets every partner within skin of its sphere at its final radius (a local
  // search of the build's cell grids), so the usual skin/2 trigger stays exact and growth needs
  // no rebuild. Falls back to particles_changed() when the update is not possible.
  void particles_replaced(const std::vector<NewFragment>& fragments,
                          const std::vector<std::uint32_t>& renewed);
  // How much particle i may still move or grow (m) before the neighbour list stops covering it:
  // skin/2 - (|x - x_build| + r - r_build). Radii may change between rebuilds only for particles
  // flagged pflag::growing (and fragments); a module that grows one by more than this margin must
  // call particles_changed().
  double reach_margin(std::size_t i) const;

  const NeighborList& pairs() const { return tracker_.pairs(); }
  // The pairs of pairs() with a flagged slot (one flag per slot of the list, ghosts included),
  // ascending. Breakage asks for its parents' pairs; an in-place replacement that renews exactly
  // those slots then reuses the answer.
  const std::vector<std::uint32_t>& pairs_flagged(const std::vector<std::uint8_t>& flags) {
    return tracker_.pairs_flagged(flags);
  }
  // Per-pair state, indexed like pairs(); per wall-candidate state, indexed by
  // WallContactRecord::candidate.
  const ContactStateStore& pair_state() const { return pair_state_; }
  const ContactStateStore& wall_state() const { return wall_state_; }
  const std::vector<WallContactRecord>& wall_contacts() const { return wall_contacts_; }
  // Every particle–wall candidate of the lists, indexed like wall_state().
  const std::vector<WallContactRecord>& wall_candidates() const {
    return tracker_.wall_candidates().records();
  }
  // The contacts that ended in the last force computation (pairs, then walls, in list order),
  // when the contact model keeps the collision record (a module asked for it); else empty.
  const std::vector<EndedContact>& ended_contacts() const { return ended_contacts_; }
  // The contact model (law, rolling, adhesion, loading record), assembled at setup or load.
  const ContactPipeline& contacts() const { return contacts_; }
  Observables observe() const;
  std::uint64_t neighbor_rebuilds() const { return tracker_.rebuilds(); }
  // How often the force loop's pruned pair list was made (options.prune_buffer).
  std::uint64_t pair_prunes() const { return tracker_.prunes(); }

  void save(Archive& a) const;
  void load(const Archive& a);

 private:
  void assemble_contacts();
  void compute_forces();
  void rekey_wrapped_wall_contacts();
  [[noreturn]] void report_non_finite() const;

  ContactPipeline contacts_;
  ContactStateStore pair_state_, wall_state_;
  PairTracker tracker_;
  GhostExchange ghosts_;
  std::size_t n_owned_ = 0;  // owned particles at the last force computation
  PairForceLoop pair_loop_;
  WallForceLoop wall_loop_;
  std::vector<WallContactRecord> wall_contacts_;  // touching now
  std::vector<EndedContact> ended_contacts_;      // ended in the last force computation
  bool forces_cleared_ = false;
  bool is_setup_ = false;
  double elastic_energy_ = 0;
};

}  // namespace comminute
