#pragma once
// Stressing events of the particles (docs/breakage.md). S(t) = sum over a particle's touching
// contacts c of e_c W_c / m, where W_c is the contact's loading work (elastic work of the normal
// force up to the contact's largest overlap) and e_c = 1/(1 + k_p/k_o) the particle's share. An
// event starts when S rises above the baseline left by the previous event (0 for a particle
// without contacts); its energy is the running maximum of S - baseline and its force the running
// maximum of the largest single elastic normal contact force (or of their sum, by the material's
// force_measure). It ends when the particle loses all contacts, or when S has not risen for
// `event_end_steps` steps; then, if it did not break, the criterion's survive() applies (damage),
// and the baseline becomes the current S. Particles of generation max_generations or later are
// not assessed.
// The event's stressing energy (J/kg) is the running maximum of S - baseline + K, K = sum over the
// touching contacts of e_c (1/2) mu_c u_c^2 / m: the particle's share of the normal relative
// kinetic energy of the contacts still approaching (u_c > 0 the approach speed, mu_c the reduced
// mass; m for a wall). For a single impact it is e E from the first step of contact, E the
// impact energy per unit mass, before the dashpot takes any; for a slow compression it is S.
// Owns the per-particle event fields (breakage.in_event, event_energy, event_force, baseline,
// quiet_steps, stressing_energy) and the energy shares per material pair.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "comminute/breakage/breakage_settings.hpp"
#include "comminute/breakage/event_log.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

class StressingEvents {
 public:
  // A particle (slot) broke in the event `record`; it is flagged unbreakable until replaced.
  using BrokeFn = std::function<void(std::size_t slot, const EventRecord& record)>;

  StressingEvents(int end_steps, bool log_all, std::uint32_t max_generations)
      : end_steps_(end_steps), log_all_(log_all), max_generations_(max_generations) {}

  void register_fields(ParticleStore& p);
  // Energy shares e of every material pair (after setup or a checkpoint).
  void configure(const Simulation& sim);
  // A new fragment starts without an event.
  void clear(ParticleStore& p, std::size_t i) const;

  // Sums each particle's contact loads (pairs, then wall contacts).
  void gather_loads(const Simulation& sim);
  // Advances each breakable particle's event with the gathered loads and asks its criterion
  // whether it breaks; ended events are counted (and logged with log_all) in `log`.
  void assess(Simulation& sim, const BreakageMaterials& materials, const BreakageFields& f,
              EventLog& log, const BrokeFn& on_break);

 private:
  int end_steps_;
  bool log_all_;
  std::uint32_t max_generations_;  // particles of this generation or later are not assessed
  std::vector<double> share_;      // e for material a against b: share_[a * n + b]
  std::size_t n_materials_ = 0;
  std::size_t f_in_event_ = 0, f_energy_ = 0, f_force_ = 0, f_baseline_ = 0, f_quiet_ = 0,
              f_stressing_ = 0;
  struct ContactLoad {
    double work = 0;      // J, share of the contacts' loading work
    double force = 0;     // N, sum of the elastic normal contact forces
    double largest = 0;   // N, largest single elastic normal contact force
    double approach = 0;  // J, share of the normal kinetic energy of the approaching contacts
    double of(ForceMeasure m) const { return m == ForceMeasure::contact_sum ? force : largest; }
  };
  std::vector<ContactLoad> contact_load_;  // per slot, scratch
  // scratch of gather_loads, kept between steps: owner_scatter's queues, the pairs in contact and
  // parallel_select's parts
  OwnerScatterQueues<ContactLoad> load_queues_;
  std::vector<std::uint32_t> touching_;
  std::vector<std::vector<std::uint32_t>> select_parts_;
  // What one range of particles hands on after assess_range, in slot order.
  struct AssessOutcome {
    std::uint64_t ended = 0;                  // events that ended (broken or not)
    std::vector<EventRecord> logged;          // ended without breaking (log_all)
    std::vector<std::size_t> broken_slots;    // broke, with ...
    std::vector<EventRecord> broken_records;  // ... their events
    void clear() {
      ended = 0;
      logged.clear();
      broken_slots.clear();
      broken_records.clear();
    }
  };
  std::vector<AssessOutcome> outcome_;  // per block of slots, scratch
  void assess_range(Simulation& sim, const BreakageMaterials& materials, const BreakageFields& f,
                    std::size_t i0, std::size_t i1, AssessOutcome& out) const;
};

}  // namespace comminute::breakage
