#pragma once
// Statistics of a packed bed under load ([bed_statistics]; docs/outputs.md): every `every` steps,
// from the contact forces of that step (engine/contact_stress.hpp),
//   - the coordination number of load-bearing particle contacts (normal force > threshold):
//     Z = 2 C / N, and the mechanical one without rattlers (< 2 such contacts),
//     Zm = (2C − N1)/(N − N0 − N1) (Thornton 2000, Géotechnique 50 eq. 4);
//   - the Love–Weber stress of each particle, σ_i = (1/V_i) Σ_c f_c ⊗ l_c (Christoffersen,
//     Mehrabadi & Nemat-Nasser 1981, J. Appl. Mech. 48 eq. 2.9), as particle fields
//     bed.stress_xx … bed.stress_yz [Pa] and bed.load_bearing [-] in the particle snapshots;
//   - per layer (equal slices of the bed's current height along the region's axis) the bulk
//     stress Σ_i V_i σ_i / V_layer;
//   - the void ratio e = A·h/V_s − 1 (A the region's cross-section, h the height of the highest
//     particle top above the region's bottom, V_s the particles' volume) and the axial stress
//     (Love–Weber over the bed, and from the load wall's force / A), so e vs log σ is the
//     normal compression line;
//   - the force chains: the load-bearing contacts as line segments with their forces (VTK).
// The region is a StatGrid of one cell (a box, its axis z; or a cylinder).
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/analysis/stat_grid.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::analysis {

struct BedStatisticsOptions {
  std::string name = "bed_statistics";
  StatGridSpec region;     // the bed's region (one cell)
  std::size_t layers = 1;  // equal slices of the bed's height
  double threshold = 0;    // N, load-bearing normal force
  std::uint64_t every = 1000;
  int load_wall = -1;  // wall index whose force gives the axial stress, or -1
  bool force_chains = true;
};

class BedStatistics final : public Module, public SeriesSource {
 public:
  explicit BedStatistics(BedStatisticsOptions options);
  std::string name() const override { return o_.name; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void declare_contact_state(ContactPipeline& pipeline) override;
  void setup(Simulation& sim) override;
  void restored(Simulation& sim) override;
  // The particle fields bed.stress_* and bed.load_bearing (before a checkpoint is read).
  void register_fields(ParticleStore& p);
  void pre_force(Simulation& sim) override;
  void post_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }

  Cadence output_cadence() const override;
  void sample(const Simulation&) override {}  // rows are measured in post_force
  std::vector<Table> tables(const Simulation& sim) const override;
  std::vector<Dataset> datasets(const Simulation& sim) const override;

  struct Row {
    double time;
    double particles, contacts, coordination, mechanical_coordination;
    double void_ratio, bed_height, axial_stress, wall_axial_stress, mean_stress;
  };
  struct LayerRow {
    double time, layer, particles;
    SymTensor stress;  // Pa, in the region's (grid) components
  };
  const std::vector<Row>& rows() const { return rows_; }
  const std::vector<LayerRow>& layer_rows() const { return layers_; }
  // The load-bearing contacts of the last measurement.
  const std::vector<ContactRecord>& chains() const { return chains_; }

  // Coordination of a contact network: C contacts among N particles whose contact counts are
  // `counts` (Z = 2C/N and Thornton's mechanical Zm).
  static std::pair<double, double> coordination(const std::vector<std::uint32_t>& counts);

 private:
  double cross_section() const;

  BedStatisticsOptions o_;
  StatGrid region_;
  bool sampling_ = false;
  std::vector<std::size_t> fields_;  // stress xx..yz, load_bearing
  std::vector<Row> rows_;
  std::vector<LayerRow> layers_;
  std::vector<ContactRecord> chains_;
  std::vector<std::array<double, 2>> chain_ids_;  // particle ids (wall: -1 - wall index)
  std::uint64_t chain_step_ = 0;
};

}  // namespace comminute::analysis
