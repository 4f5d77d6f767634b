#pragma once
// Time-averaged statistics on a Cartesian or cylindrical grid ([grid_statistics]; docs/outputs.md):
// over a window of simulated time, every `every` steps each owned particle is binned by its
// centre and adds its mass, volume, momentum and Love–Weber moment (engine/contact_stress.hpp);
// every step in the window each contact that began adds one to the cells of its particles. Per
// cell the averages give
//   σ = (Σ M_i − Σ m_i v'_i ⊗ v'_i) / (N V_cell)     bulk stress: contact + kinetic part
//       (Love–Weber, Christoffersen et al. 1981 J. Appl. Mech. 48 eq. 2.9; kinetic part with v'
//        the fluctuation about the cell's mean velocity)
//   σ_p = Σ m_i (M_i/V_i) / Σ m_i                   mass-weighted particle stress (contact part)
// with N the number of samples, principal stresses, σm, τmax, solid fraction, mean velocity and
// the contact frequency per particle; and the specific contact frequency ṅ(σ) (1/(s·Pa)) per
// level of the particle pressure −tr σ_p/3 that the stress-based breakage rate integrates
// (pbm rate `stress`). A cylindrical grid may turn with a wall about its axis; its vectors and
// tensors are in (r, theta, axial) components. Under coarse graining ([coarse_graining],
// particles/coarse_graining.hpp) the contact frequencies are also given per primary particle:
// the coarse particle's frequency × k^frequency_exponent.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "comminute/analysis/stat_grid.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::analysis {

struct GridStatisticsOptions {
  std::string name = "grid_statistics";  // table, dataset and checkpoint name
  StatGridSpec grid;
  double start = 0;                                      // s, window start
  double end = std::numeric_limits<double>::infinity();  // s, window end
  std::uint64_t every = 1;                               // steps between samples
  int rotate_with = -1;                                  // wall index, or -1 (fixed)
  std::size_t spectrum_bins = 50;                        // stress bins of ṅ(σ)
  double spectrum_max = 0;                               // Pa; 0: the largest cell stress
  // contact frequency per primary particle / per coarse particle: k^frequency_exponent
  // ([coarse_graining]; 1 without)
  double primary_frequency_factor = 1;
  // output cadence; by default the files are written at the start and the end of the run only
  // (rewriting thousands of cells at the time-series cadence would cost more than the sampling)
  Cadence cadence{1e300, 0};
};

class GridStatistics final : public Module, public SeriesSource {
 public:
  explicit GridStatistics(GridStatisticsOptions options);
  std::string name() const override { return o_.name; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void declare_contact_state(ContactPipeline& pipeline) override;
  void setup(Simulation& sim) override;
  void pre_force(Simulation& sim) override;
  void post_force(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }

  Cadence output_cadence() const override { return o_.cadence; }
  void sample(const Simulation&) override {}  // the averages are kept as they accumulate
  std::vector<Table> tables(const Simulation& sim) const override;
  std::vector<Dataset> datasets(const Simulation& sim) const override;

  // Per-cell averages (for tests and the outputs).
  struct CellAverage {
    double particles = 0, solid_fraction = 0;
    Vec3 velocity;                 // m/s (grid components)
    SymTensor stress{};            // Pa, bulk: contact + kinetic
    SymTensor contact_stress{};    // Pa, bulk, contact part alone
    SymTensor particle_stress{};   // Pa, mass-weighted particle stress
    double contact_frequency = 0;  // 1/s per particle
  };
  CellAverage average(std::size_t cell) const;
  const StatGrid& grid() const { return grid_; }
  std::uint64_t samples() const { return samples_; }
  double window_time() const { return window_time_; }

 private:
  bool in_window(const Simulation& sim) const;
  double* cell(std::size_t c) { return &acc_[c * kFields]; }
  const double* cell(std::size_t c) const { return &acc_[c * kFields]; }
  // per cell: count, mass, volume, Σmv (3), Σmvv (6), ΣM (6), Σm M/V (6), contact starts
  static constexpr std::size_t kFields = 25;

  GridStatisticsOptions o_;
  StatGrid grid_;
  std::vector<double> acc_;
  std::uint64_t samples_ = 0, steps_ = 0;
  double window_time_ = 0;  // s
  bool sampling_ = false;   // this step is a sample
};

}  // namespace comminute::analysis
