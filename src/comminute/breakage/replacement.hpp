#pragma once
// Replacement of broken parents by their fragments, at the end of the step (after the step's last
// half kick, so the fragments inherit the parent's final velocity); every replacement_interval
// steps, batched. Books in the ledger the elastic energy that leaves with the parents' contacts,
// the kinetic energy difference of parent and fragments, the fines' potential energy and the
// elastic energy of the starting overlaps; logs each breakage.
// The parents of a batch are worked out on all threads, each from random streams of its own
// (rng.hpp: Rng(seed, rng_stream::breakage, parent id) for the progeny sizes and then the
// fragments' strengths, Rng(seed, rng_stream::placement, parent id) for the placement), so a
// parent's fragments do not depend on the other parents, the thread count or a restart; the
// fragments are appended, and the ledger and the log booked, in the order the parents broke.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "comminute/breakage/breakage_settings.hpp"
#include "comminute/breakage/event_log.hpp"
#include "comminute/breakage/fragment_mass_rule.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

class BreakageLedger;
class FragmentGrowth;

class Replacement {
 public:
  // What a replacement reads and books, owned by the module.
  struct Context {
    const BreakageMaterials& materials;
    const BreakageFields& fields;
    BreakageLedger& ledger;
    EventLog& log;
    FragmentGrowth& growth;
    // s: fragments whose Rayleigh time t_R is shorter become fines (FloorRule::fines) or get
    // mass scale (rayleigh_floor / t_R)^2 (FloorRule::density_scaling); 0: no floor
    double rayleigh_floor;
    FloorRule floor_rule;
    // A fragment took slot s (parent's fields copied, generation and target set): clear its
    // event and draw its strength from `rng`. Called on all threads, for distinct slots.
    std::function<void(std::size_t s, Rng& rng)> born;
    // Redistributes the fragment masses before placement (fragment_mass_rule.hpp), or null.
    FragmentMassRule* mass_rule = nullptr;
  };

  Replacement(std::shared_ptr<const FragmentPlacement> placement, int interval)
      : placement_(std::move(placement)), interval_(interval) {}

  // The particle with this id broke in event `record` during this step's loading.
  void enqueue(std::uint64_t id, const EventRecord& record) {
    broken_ids_.push_back(id);
    broken_records_.push_back(record);
  }
  // Replaces the queued parents when due.
  void end_of_step(Simulation& sim, const Context& ctx);

 private:
  // A neighbour of a parent: its owned slot, and the pair-list slots (parent's, its own) of the
  // pair that met them — a periodic image when one of them is a ghost (Simulation::pair_frame).
  struct Neighbour {
    std::uint32_t slot, parent_seen, seen;
  };
  // One parent's replacement, worked out before the store changes.
  struct Outcome {
    std::size_t parent = 0;  // slot
    double r_parent = 0;     // m: its radius, or its final one while it was still growing
    const std::vector<Neighbour>* around = nullptr;
    EventRecord rec;
    Progeny progeny;
    // per fragment: final radius (m), mass (kg; inertial once placed), moment of inertia of the
    // full-size sphere (kg m2), density scale (1 unless its Rayleigh time is below the floor)
    std::vector<double> radii, masses, inertia, scales;
    std::vector<Sphere> placed;  // starting centres and radii
    FragmentVelocities vel;
    double ke_out = 0, ke_in = 0;  // J: kinetic energy of the parent, of its fragments
    Vec3 parent_v;                 // m/s: the parent's velocity (its fines leave with it)
    double fines_pe =
        0;    // J: potential energy of the fines' mass at the parent's centre (inertial)
    Rng rng;  // the parent's breakage stream, left at its fragments' strengths
    std::size_t first_slot = 0;  // the first slot of its fragments appended to the store
    std::uint64_t first_id = 0;  // its fragments' ids are first_id, first_id + 1, ...
    std::size_t own = 0;         // the fragment in the parent's slot (placed.size(): none)
    std::uint64_t parent_id = 0;
    std::uint32_t generation = 0;    // of its fragments
    std::size_t growing = 0;         // fragments placed smaller than their final size
    std::vector<std::size_t> slots;  // of its fragments once in the store
    double created = 0;              // J: elastic energy of its fragments' starting overlaps
  };
  // Progeny sizes and masses (o.parent, o.rec and o.around set).
  void draw(const Simulation& sim, const Context& ctx, Outcome& o) const;
  // Placement inside the parent and the fragments' velocities (after the mass rule).
  void place(const Simulation& sim, const Context& ctx, Outcome& o) const;
  // Writes the fragments into the store at slots and ids laid out beforehand (o.first_slot,
  // o.first_id; parents on all threads). in_slot: the one with the most room inside the parent
  // takes the parent's slot, the others go to the appended slots; else all are appended and the
  // parent is marked for removal.
  void write(Simulation& sim, const Context& ctx, Outcome& o, bool in_slot) const;
  // Books the fragments of o (written) for the pair list, the log and growth: serial, in parent
  // order.
  void book_fragments(const Simulation& sim, const Context& ctx, const Outcome& o);
  // Elastic energy of the starting overlaps of outcome q's fragments with their siblings, the
  // neighbours and the walls; a neighbour that broke in this batch counts by its fragments, once
  // per pair of families (from the later parent). batch[j]: 1 + the outcome of slot j, or 0.
  double created_energy(const Simulation& sim, const std::vector<Outcome>& outcomes, std::size_t q,
                        const std::vector<std::uint32_t>& batch) const;

  std::shared_ptr<const FragmentPlacement> placement_;
  int interval_;
  std::vector<std::uint64_t> broken_ids_;  // found in post_force
  std::vector<EventRecord> broken_records_;
  std::vector<NewFragment> fragments_added_;  // put in the store this step
  std::vector<std::uint32_t> renewed_;        // parents' slots a fragment took this step
  // per slot, kept from step to step (assigned anew each step; large arrays reallocated every
  // step would take fresh pages, a page fault each): 0, or 1 + the parent's outcome; 1 for a
  // parent's slot of the pair list
  std::vector<std::uint32_t> batch_;
  std::vector<std::uint8_t> parent_slot_;
};

}  // namespace comminute::breakage
