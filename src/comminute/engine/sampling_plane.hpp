#pragma once
// Sampling planes: count the particles that cross a plane without removing them (the flow
// through a grate, a discharge opening, a section of a chute). Each plane keeps, per particle, the
// side its centre was on at the end of the previous step (a per-particle field
// "sampling.<name>.side": +1 on the side the normal points to, −1 on the other, 0 not yet seen,
// so it follows sorting, insertion, removal and breakage — fragments inherit their parent's
// side). At the end of every step a change from −1 to +1 is a crossing in the positive
// direction (along the normal), from +1 to −1 one in the negative direction; a particle seen for
// the first time (inserted, or at the start) only has its side recorded. Centres exactly on the
// plane count as the negative side.
// A plane may be bounded (a disc, or a rectangle): a change of side counts only when the point
// where the centre crossed the plane lies within the bound. That point is the centre at the end
// of the step taken back along its velocity to the plane, x - v d / (v . n) (d the signed
// distance; exact for a straight path within the step), or its projection when v . n = 0.
// Tables (docs/outputs.md): sampling_planes.csv, cumulative crossings and mass per direction;
// sampling_log.csv, one row per counted crossing of a plane with `log` (a ParticleRecord: time,
// plane, direction, id, material, mass, diameter, generation).
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/engine/module.hpp"
#include "comminute/engine/particle_record.hpp"
#include "comminute/engine/sample_rows.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

struct SamplingPlaneSpec {
  enum class Extent { infinite, disc, rectangle };
  std::string name;
  Vec3 point, normal;  // normal unit: the positive direction of crossing
  Extent extent = Extent::infinite;
  double radius = 0;              // m, disc about `point`
  Vec3 u{};                       // unit, in the plane: the rectangle's first side
  double half_u = 0, half_v = 0;  // m, half sides along u and normal x u
  bool log = false;               // log each counted crossing
  // True when a centre at x (end of the step) with velocity v crossed within the bound.
  bool within(const Vec3& x, const Vec3& v) const;
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
  // The counted crossings of the planes with `log`, in order (`site`: the plane; `direction`).
  const std::vector<ParticleRecord>& log() const { return log_; }

 private:
  std::vector<SamplingPlaneSpec> planes_;
  std::vector<std::size_t> fields_;
  std::vector<PlaneCrossings> counts_;
  std::vector<ParticleRecord> log_;
  SampleRows samples_;  // per sample: time, then 4 numbers per plane
};

}  // namespace comminute
