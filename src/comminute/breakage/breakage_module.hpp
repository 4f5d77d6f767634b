#pragma once
// Particle-replacement breakage as an engine module (issue 3), a thin coordinator of its
// collaborators. Per step:
//   post_force   grow pending fragments towards their full radius (FragmentGrowth); build each
//                particle's stressing event from its contacts and ask its material's criterion
//                whether it breaks (StressingEvents; breakage is decided during loading),
//   end_of_step  replace the broken parents by fragments (Replacement, after the step's last
//                half kick, so the fragments inherit the parent's final velocity).
// The module holds the per-material settings, the shared per-particle fields and the strength
// stream of the particles it did not make (the fragments draw from their parent's streams,
// replacement.hpp); the energy ledger is a BreakageLedger, the event log an EventLog.
#include <cstdint>
#include <optional>
#include <vector>

#include "comminute/breakage/breakage_ledger.hpp"
#include "comminute/breakage/breakage_series.hpp"
#include "comminute/breakage/breakage_settings.hpp"
#include "comminute/breakage/event_log.hpp"
#include "comminute/breakage/fragment_growth.hpp"
#include "comminute/breakage/replacement.hpp"
#include "comminute/breakage/stressing_events.hpp"
#include "comminute/core/vec3.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

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
  std::size_t pending() const { return growth_.pending(); }
  std::uint64_t breakages() const { return log_.breakages(); }
  std::uint64_t events() const { return log_.events(); }
  const std::vector<EventRecord>& log() const { return log_.records(); }
  // One record per fragment of every breakage (breakage_fragments.csv).
  const std::vector<FragmentRecord>& fragment_log() const { return log_.fragments(); }
  // Fines booked as mass (FinesRule::mass), per material (kg), and their momentum (kg m/s).
  const std::vector<double>& fines_mass() const { return ledger_.fines_mass(); }
  Vec3 fines_momentum() const { return ledger_.fines_momentum(); }
  // Energy taken out by breakage so far (J), also added to sim.ledger.removed.
  double removed_energy() const { return ledger_.removed(); }
  // Elastic energy created by the starting overlaps and the growth of fragments (J); it is
  // counted in removed_energy() with a negative sign.
  double created_energy() const { return ledger_.created(); }
  // A rule that redistributes fragment masses (the texture module's), or null; not owned.
  void set_fragment_mass_rule(FragmentMassRule* rule) { mass_rule_ = rule; }
  const MaterialBreakage* material(std::size_t k) const {
    return k < materials_.size() && materials_[k] ? &*materials_[k] : nullptr;
  }

 private:
  void configure(Simulation& sim);  // what depends on the simulation (after setup or load)
  // Draws particle i's strength from rng (initialized set: reads and writes slot i only).
  void initialize_particle(Simulation& sim, std::size_t i, Rng& rng) const;
  Replacement::Context replacement_context(Simulation& sim);

  BreakageMaterials materials_;
  BreakageOptions opt_;
  // s: the Rayleigh time below which fragments are density scaled (0: no scaling)
  double rayleigh_floor(const Simulation& sim) const;
  BreakageFields fields_;
  Rng strength_rng_;  // the strengths of the particles the run starts with or inserts
  StressingEvents events_;
  FragmentGrowth growth_;
  Replacement replacement_;
  BreakageLedger ledger_;
  EventLog log_;
  BreakageSeries series_{*this, opt_.output_interval};
  FragmentMassRule* mass_rule_ = nullptr;
};

}  // namespace comminute::breakage
