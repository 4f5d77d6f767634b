#pragma once
// Sampling planes: count the particles that cross a plane without removing them (the flow
// through a grate, a discharge opening, a section of a chute). Each plane keeps, per particle, the
// side its centre was on at the end of the previous step (a per-particle field
// "sampling.<name>.side": +1 on the side the normal points to, −1 on the other, 0 not yet seen,
// so it follows sorting, insertion, removal and breakage — fragments inherit their parent's
// side). At the end of every step a change from −1 to +1 is a crossing in the positive
// direction (along the normal), from +1 to −1 one in the negative direction; a particle seen for
// the first time (inserted, or at the start) only has its side recorded. Centres exactly on the
// plane count as the negative side. The plane is infinite.
// Table (docs/outputs.md): sampling_planes.csv, cumulative crossings and mass per direction.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/engine/module.hpp"
#include "comminute/engine/sample_rows.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

struct SamplingPlaneSpec {
  std::string name;
  Vec3 point, normal;  // normal unit: the positive direction of crossing
};

struct PlaneCrossings {
  std::uint64_t positive = 0, negative = 0;     // crossings along / against the normal
  double mass_positive = 0, mass_negative = 0;  // kg
};

class SamplingPlaneModule final : public Module, public SeriesSource {
 public:
  explicit SamplingPlaneModule(std::vector<SamplingPlaneSpec> planes);
  std::string name() const override { return "sampling_planes"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void setup(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  // Registers the per-particle side fields; call once when the case is built (before a
  // checkpoint is loaded, which holds them).
  void register_fields(ParticleStore& p);
  const std::vector<PlaneCrossings>& crossings() const { return counts_; }

 private:
  std::vector<SamplingPlaneSpec> planes_;
  std::vector<std::size_t> fields_;
  std::vector<PlaneCrossings> counts_;
  SampleRows samples_;  // per sample: time, then 4 numbers per plane
};

}  // namespace comminute
