#pragma once
// Replacement of broken parents by their fragments, at the end of the step (after the step's last
// half kick, so the fragments inherit the parent's final velocity); every replacement_interval
// steps, batched. Books in the ledger the elastic energy that leaves with the parents' contacts,
// the kinetic energy difference of parent and fragments, the fines' potential energy and the
// elastic energy of the starting overlaps; logs each breakage.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
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
    Rng& strength_rng;   // progeny sizes (and the fragments' strengths, drawn by `born`)
    Rng& placement_rng;  // placement inside the parent
    BreakageLedger& ledger;
    EventLog& log;
    FragmentGrowth& growth;
    // s: fragments whose Rayleigh time t_R is shorter become fines (FloorRule::fines) or get
    // mass scale (rayleigh_floor / t_R)^2 (FloorRule::density_scaling); 0: no floor
    double rayleigh_floor;
    FloorRule floor_rule;
    // A fragment took slot s (parent's fields copied, generation and target set): clear its
    // event and draw its strength.
    std::function<void(std::size_t s)> born;
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
  void replace(Simulation& sim, const Context& ctx, std::size_t parent,
               const std::vector<Neighbour>& around, const EventRecord& rec);

  std::shared_ptr<const FragmentPlacement> placement_;
  int interval_;
  std::vector<std::uint64_t> broken_ids_;  // found in post_force
  std::vector<EventRecord> broken_records_;
  std::vector<NewFragment> fragments_added_;  // appended this step
  // slots [begin, end) of the fragments of each parent replaced this step, by parent id
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> fragment_slots_;
};

}  // namespace comminute::breakage
