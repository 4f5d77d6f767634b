#pragma once
// The collision log: every contact event (first touch to separation) of the run, as the contact
// model's collision record leaves it when the bodies separate (Simulation::ended_contacts()),
// classified by contact type (particle–particle by material pair, particle–wall by wall and
// material) and reduced on the fly (no event is held): counts, sums and log-binned histograms of
// the impact energy (reduced-mass and average-mass variants), the normal and tangential
// dissipated energy and their total, over a steady-state window (from a start time, or from the
// steady state detected in the power and kinetic-energy series, steady_state.hpp).
// Tables (docs/outputs.md): collisions.csv (per type), collision_distributions.csv (cumulative
// distributions), collision_spectrum_<type>.csv (energy_J, frequency_per_s: the collision
// spectrum `comminute pbm` reads, pbm/collision_spectrum.hpp) and
// collision_specific_energy_<type>.csv (specific_energy_J_per_kg, probability: the mass-specific
// impact energy distribution of the `capece` rate, pbm/capece_rate.hpp).
// Checkpointed under collisions/: open events are in the contact store, everything else here.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "comminute/analysis/energy_histogram.hpp"
#include "comminute/analysis/steady_state.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::analysis {

// The energy a spectrum file lists per collision.
enum class SpectrumEnergy : int {
  impact_reduced_mass = 0,  // 1/2 m* v_n^2, m* = m1 m2 / (m1 + m2) (wall: m1)
  impact_average_mass = 1,  // 1/2 m_avg v_n^2, m_avg = (m1 + m2) / 2 (wall: m1)
  dissipated = 4,           // normal + tangential dissipated energy of the event
};

struct CollisionLogSettings {
  double start = 0;                                      // s, window start (unless detected)
  bool detect = false;                                   // window from the detected steady state
  SteadyStateRule rule;                                  // for detection
  double end = std::numeric_limits<double>::infinity();  // s, window end
  double energy_min = 1e-9;                              // J, first bin edge
  double energy_max = 1e3;                               // J, last bin edge
  int bins = 120;                                        // log-spaced bins between them
  SpectrumEnergy spectrum = SpectrumEnergy::impact_reduced_mass;
  double interval = 0;                 // s between rewrites of the tables (0: every 5000 steps)
  std::vector<std::string> materials;  // names, by index
  std::vector<std::string> walls;      // names, by index
};

// Sums over the events of one contact type in the window (SI units; counts as doubles).
struct CollisionSums {
  double events_total = 0;                        // every event of the run, in the window or not
  double events = 0;                              // in the window
  double impact_reduced = 0, impact_average = 0;  // J
  double dissipated_normal = 0, dissipated_tangential = 0;     // J
  double duration = 0, max_overlap = 0, max_normal_force = 0;  // s, m, N
  double diameter_1 = 0, diameter_2 = 0;                       // m
};

class CollisionLogModule final : public Module, public SeriesSource {
 public:
  // The quantities binned per type, in this order.
  // The last, impact_specific_energy = 1/2 v_n^2 (J/kg), is binned on the same edges (read in
  // J/kg) and written only as the Capece specific-energy file.
  static constexpr int n_quantities = 6;
  static const std::array<const char*, n_quantities> quantity_names;

  explicit CollisionLogModule(CollisionLogSettings s);
  std::string name() const override { return "collisions"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void declare_contact_state(ContactPipeline& pipeline) override;
  void post_force(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  Cadence output_cadence() const override { return Cadence::interval_or_steps(s_.interval, 5000); }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  // Contact types: particle pairs (material a <= b), then particle–wall (wall, material), then
  // "all"; names as in the output files.
  std::size_t types() const { return names_.size(); }
  const std::string& type_name(std::size_t k) const { return names_[k]; }
  const CollisionSums& sums(std::size_t k) const { return sums_[k]; }
  const EnergyHistogram& histogram(std::size_t type, int quantity) const {
    return hist_[type * n_quantities + static_cast<std::size_t>(quantity)];
  }
  // The window: open once its start is known (s); its length up to `now` (s).
  bool window_open() const { return window_start_ >= 0; }
  double window_start() const { return window_start_; }
  double window_length(double now) const;

 private:
  std::size_t pair_type(std::size_t a, std::size_t b) const;
  std::size_t wall_type(std::size_t wall, std::size_t material) const;
  void add(std::size_t type, const CollisionSums& e, const std::array<double, n_quantities>& q);
  // Impacts per particle per second of a type of `frequency` (1/s): each particle of a pair has
  // an impact, a particle on a wall one; over every particle present.
  double impacts_per_particle(std::size_t type, double frequency, const Simulation& sim) const;

  CollisionLogSettings s_;
  std::vector<std::string> names_;
  std::vector<CollisionSums> sums_;
  std::vector<EnergyHistogram> hist_;
  SteadyStateDetector detector_;
  double window_start_ = -1;  // s; < 0 while the window is not open
  double last_time_ = 0;      // s, of the last sample
};

}  // namespace comminute::analysis
