#pragma once
// Particle-replacement breakage as an engine module (issue 3). Per step:
//   post_force   grow pending fragments towards their full radius (overlaps capped); build each
//                particle's stressing event from its contacts and ask its material's criterion
//                whether it breaks (breakage is decided during loading),
//   end_of_step  replace the broken parents by fragments (after the step's last half kick, so
//                the fragments inherit the parent's final velocity).
//
// Stressing event of a particle (docs/breakage.md): S(t) = sum over its touching contacts c of
// e_c W_c / m, where W_c is the contact's loading work (elastic work of the normal force up to the
// contact's largest overlap) and e_c = 1/(1 + k_p/k_o) the particle's share. An event starts when
// S rises above the baseline left by the previous event (0 for a particle without contacts); its
// energy is the running maximum of S - baseline and its force the running maximum of the summed
// elastic normal forces. It ends when the particle loses all contacts, or when S has not risen for
// `event_end_steps` steps; then, if it did not break, the criterion's survive() applies (damage),
// and the baseline becomes the current S.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "comminute/breakage/breakage_series.hpp"
#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/breakage/placement/placement_model.hpp"
#include "comminute/breakage/progeny/progeny_sizes.hpp"
#include "comminute/breakage/progeny/t10_progeny.hpp"
#include "comminute/core/vec3.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

// Breakage settings of one material.
struct MaterialBreakage {
  std::unique_ptr<BreakageCriterion> criterion;
  std::unique_ptr<ProgenyModel> progeny = std::make_unique<T10Progeny>(T10Progeny::illustrative());
  double reference_energy = -1;      // J/kg, E50b for t10 when the criterion has no median
  double min_breakable_size = 0;     // m, smaller particles never break
  double min_fragment_size = 0;      // m, smaller fragments become fines
  double min_fragment_ratio = 0.05;  // fragments below this fraction of the parent diameter: fines
  FinesRule fines = FinesRule::particles;
  double release_fraction = 0;  // eta: fraction of the absorbed energy given as radial speed
};

struct BreakageOptions {
  PlacementOptions placement;  // of the default placement model when placement_model is empty
  std::shared_ptr<const FragmentPlacement> placement_model;
  double growth_overlap_ratio = 0.001;  // largest overlap growth may create, fraction of the
                                        // smaller radius (each growth step pumps in U(eps))
  double growth_step = 0.005;    // largest radius increment per step, fraction of the final radius
  int event_end_steps = 20;      // steps without new loading that end a stressing event
  int replacement_interval = 1;  // replace broken parents every this many steps (batched; each
                                 // replacement makes the engine rebuild its neighbour list)
  bool log_all_events = false;   // also log events that did not break (probability plots)
  double output_interval = 0;    // s between ledger rows / table rewrites (0: every 1000 steps)
};

// One row of the event log (SI units; strength in the criterion's unit).
struct EventRecord {
  double time = 0;  // s
  std::uint64_t parent_id = 0;
  std::uint32_t material = 0;
  std::uint32_t generation = 0;  // 0 for particles of the initial set
  double diameter = 0;           // m
  double mass = 0;               // kg, of the parent
  double specific_energy = 0;    // J/kg absorbed in the event
  double peak_force = 0;         // N
  double strength = 0;           // J/kg (energy criteria) or N (force criteria) before the event
  double damage_before = 0;      // accumulated damage before the event
  std::uint32_t broken = 0;      // 1 if it broke
  std::uint32_t fragments = 0;   // resolved fragments
  std::uint32_t fines_particles = 0;
  std::uint32_t reserved = 0;  // explicit padding: checkpoint bytes are fully initialised
  double fines_mass = 0;       // kg booked as mass
  double t10 = 0;              // %
};
static_assert(sizeof(EventRecord) == 13 * 8, "EventRecord must have no padding (checkpoints)");

class BreakageModule final : public Module {
 public:
  // per_material[k]: settings of material k, or empty (material k never breaks).
  BreakageModule(std::vector<std::optional<MaterialBreakage>> per_material, BreakageOptions opt);
  ~BreakageModule() override;

  std::string name() const override { return "breakage"; }
  // Registers the module's and the criteria's per-particle fields. Called by setup(); call it
  // once right after construction as well, so that a checkpoint restores the fields.
  void register_fields(ParticleStore& p);
  // Breakage reads each contact's loading record.
  void declare_contact_state(ContactPipeline& c) override { c.require_loading_record(); }
  void setup(Simulation& sim) override;
  void post_force(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  void restored(Simulation& sim) override;
  // Fragments are smaller than the inserted particles: the time step must resolve the smallest
  // one each material can produce, max(min_fragment_size, min_fragment_ratio x
  // min_breakable_size).
  void announce_sizes(std::vector<ParticleSize>& sizes, const Simulation& sim) const override;
  // Event log, ledger and model curves (breakage_series.hpp), written by the output module.
  SeriesSource* series_source() override { return &series_; }

  // Fragments still growing to full size.
  std::size_t pending() const { return pending_; }
  std::uint64_t breakages() const { return breakages_; }
  std::uint64_t events() const { return events_; }
  const std::vector<EventRecord>& log() const { return log_; }
  // Fines booked as mass (FinesRule::mass), per material (kg), and their momentum (kg m/s).
  const std::vector<double>& fines_mass() const { return fines_mass_; }
  Vec3 fines_momentum() const { return fines_momentum_; }
  // Energy taken out by breakage so far (J), also added to sim.ledger.removed.
  double removed_energy() const { return removed_; }
  // Elastic energy created by the starting overlaps and the growth of fragments (J); it is
  // counted in removed_energy() with a negative sign.
  double created_energy() const { return created_; }
  const MaterialBreakage* material(std::size_t k) const {
    return k < materials_.size() && materials_[k] ? &*materials_[k] : nullptr;
  }

 private:
  void configure(Simulation& sim);  // what depends on the simulation (after setup or load)
  void initialize_particle(Simulation& sim, std::size_t i);
  void update_events(Simulation& sim);
  void replace(Simulation& sim, std::size_t parent, const std::vector<std::uint32_t>& around,
               const EventRecord& rec);
  void add_energy(Simulation& sim, double joules);  // elastic energy created by placement/growth
  void grow(Simulation& sim);

  std::vector<std::optional<MaterialBreakage>> materials_;
  BreakageOptions opt_;
  std::vector<double> share_;  // e for material a against b: share_[a * n + b]
  std::size_t n_materials_ = 0;
  // field indices
  std::size_t f_init_ = 0, f_generation_ = 0, f_target_ = 0, f_in_event_ = 0, f_energy_ = 0,
              f_force_ = 0, f_baseline_ = 0, f_quiet_ = 0;
  struct ContactLoad {
    double work = 0;   // J, share of the contacts' loading work
    double force = 0;  // N, sum of the elastic normal contact forces
  };
  std::vector<ContactLoad> contact_load_;     // per slot, scratch
  std::vector<NewFragment> fragments_added_;  // appended this step
  // slots [begin, end) of the fragments of each parent replaced this step, by parent id
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> fragment_slots_;
  std::vector<std::uint64_t> broken_ids_;  // found in post_force
  std::vector<EventRecord> broken_records_;
  Rng strength_rng_, placement_rng_;
  std::size_t pending_ = 0;
  std::uint64_t breakages_ = 0, events_ = 0;
  std::vector<EventRecord> log_;
  std::vector<double> fines_mass_;
  Vec3 fines_momentum_;
  double removed_ = 0;
  double created_ = 0;
  BreakageSeries series_{*this, opt_.output_interval};
};

}  // namespace comminute::breakage
