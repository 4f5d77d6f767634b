#pragma once
// Outlets: regions or half-spaces that take particles out of the run and log each one — the
// product stream of a mill, a hopper's discharge, a screen's undersize. At the end of every step a
// particle whose centre lies inside an outlet's region (or beyond its plane, on the side the
// plane's normal points to) is removed through the particle store's one removal path
// (pflag::remove, ParticleStore::compact(), Simulation::particles_changed()), and one row is
// appended to the log (a ParticleRecord, `site` = the outlet): time, step, outlet, id, material,
// mass, diameter, generation (and the composition when the run has per-particle fields
// "composition.<k>"). Its kinetic and gravitational potential energy are booked as removed energy
// (EnergyLedger::removed), so the run's energy balance stays closed. Tables (docs/outputs.md):
// outlet_log.csv (one row per removed particle, every row once) and outlets.csv (cumulative count
// and mass per outlet at each sample).
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/engine/module.hpp"
#include "comminute/engine/particle_record.hpp"
#include "comminute/engine/sample_rows.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/geometry/region.hpp"

namespace comminute {

struct OutletSpec {
  std::string name;
  bool half_space = false;  // true: beyond a plane; false: inside `region`
  Region region;            // centre inside (Region::contains with radius 0)
  Vec3 point, normal;       // half space: removes where (x − point)·normal > 0; normal unit
  bool captures(const Vec3& x) const;
};

class OutletModule final : public Module, public SeriesSource {
 public:
  explicit OutletModule(std::vector<OutletSpec> outlets);
  std::string name() const override { return "outlets"; }
  // After breakage and every other physics module of the step: the observation stage, first.
  ModuleStage stage() const override { return ModuleStage::observation; }
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  void setup(Simulation& sim) override;
  void restored(Simulation& sim) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  const std::vector<OutletSpec>& outlets() const { return outlets_; }
  // Every removed particle, in the order of removal (`site`: the outlet; `direction` 0).
  const std::vector<ParticleRecord>& log() const { return log_; }
  // Composition of the removed particles when the run has per-particle fields "composition.<k>"
  // (mineral phases): composition_fields() values per row of log(), in the order of the fields.
  const std::vector<double>& compositions() const { return compositions_; }
  std::size_t composition_fields() const { return composition_.size(); }
  double removed_mass() const;  // kg, all outlets

 private:
  std::vector<OutletSpec> outlets_;
  std::vector<ParticleRecord> log_;
  std::vector<std::size_t> composition_;  // field indices of composition.0, composition.1, ...
  std::vector<double> compositions_;      // per removed particle, one value per composition field
  SampleRows totals_;                     // per sample: time, then count and mass per outlet
};

}  // namespace comminute
