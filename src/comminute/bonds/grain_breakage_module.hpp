#pragma once
// Breakage of bonded grains (observation stage, after the bonds module each step). The particles
// carry per-particle fields `grain` (0, 1, …; −1: not part of a grain) and `layer` (1 at the
// bottom), set by the cluster insertion. On every step in which a bond failed the module
// rebuilds the fragments (connected components over the intact bonds, fragments.hpp) and marks a
// grain broken the first time its largest fragment holds less than `broken_below` of its mass;
// the breakage mode is classified from the grain's failed bonds (breakage_mode.hpp). Optionally it
// follows the bed between two plane walls (a piston and a floor): height h, axial stress on the
// piston and the void ratio e = A h / V_s − 1 twice: V_s the sub-spheres' volume (the solid the
// DEM has) and V_s the grains' nominal volume (grain mass / material density). Clusters of few
// sub-spheres nest into each other's hollows, so the nominal void ratio of a bed of coarse
// clusters is far below that of real grains; the sub-sphere one behaves like a sphere bed's.
// Tables (docs/outputs.md): grain_breakage, breakage_layers, fragments, grains, bed.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/bonds/bonds_module.hpp"
#include "comminute/bonds/breakage_mode.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::bonds {

struct GrainBreakageOptions {
  double broken_below = 0.9;  // -, largest-fragment mass fraction under which a grain is broken
  std::string piston, floor;  // plane walls bounding the bed (empty: no bed table)
  double area = 0;            // m², the piston's area
};

struct GrainBreakageRow {
  double time = 0;
  std::uint64_t grain = 0, layer = 0;
  double largest_fraction = 0;
  BreakageMode mode = BreakageMode::central;
  std::uint8_t padding[7] = {};
};

struct LayerSample {
  double time = 0;
  std::uint64_t layer = 0, grains = 0, broken = 0;
};

struct BedSample {
  double time = 0, height = 0, stress = 0, void_ratio = 0, void_ratio_nominal = 0;
};

struct GrainFailure {
  std::uint64_t grain = 0;
  FailedBondGeometry geometry;
};

class GrainBreakageModule final : public Module, public SeriesSource {
 public:
  GrainBreakageModule(const BondsModule& bonds, GrainBreakageOptions options);
  std::string name() const override { return "grain_breakage"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void setup(Simulation& sim) override;
  void restored(Simulation& sim) override { setup(sim); }
  void post_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  std::size_t grains() const { return grain_mass_.size(); }
  const std::vector<GrainBreakageRow>& rows() const { return rows_; }
  const std::vector<std::uint8_t>& broken() const { return broken_; }
  std::uint64_t grain_layer(std::size_t g) const { return grain_layer_[g]; }
  // Largest fragment mass / grain mass of every grain now (fresh fragment labelling).
  std::vector<double> largest_fractions(const Simulation& sim) const;
  // The bed now (needs piston and floor); time set to sim.time.
  BedSample bed(const Simulation& sim) const;

 private:
  struct Fragments {
    std::vector<std::uint32_t> label;  // per slot (owned particles)
    std::vector<double> mass;          // per fragment
    std::vector<std::int64_t> grain;   // per fragment (−1: none)
    std::vector<std::uint64_t> spheres;
  };
  Fragments fragments(const Simulation& sim) const;
  // Counts the grains whose id is beyond those counted so far (all at setup; later the grains a
  // pour brings in), when particles were added since the last count.
  void count_new_grains(const Simulation& sim);

  const BondsModule& bonds_;
  GrainBreakageOptions options_;
  std::size_t grain_field_ = 0, layer_field_ = 0;
  std::vector<double> grain_mass_, grain_volume_;
  std::vector<std::uint64_t> grain_layer_;
  double solid_volume_ = 0, sphere_volume_ = 0;
  std::uint64_t counted_next_id_ = 0;  // the store's next id at the last count
  int piston_ = -1, floor_ = -1;
  // state (checkpointed)
  std::vector<std::uint8_t> broken_;
  std::uint64_t failures_seen_ = 0;
  std::vector<GrainFailure> failures_;
  std::vector<GrainBreakageRow> rows_;
  std::vector<LayerSample> layer_samples_;
  std::vector<BedSample> bed_samples_;
};

}  // namespace comminute::bonds
