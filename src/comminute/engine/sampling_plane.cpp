#include "comminute/engine/sampling_plane.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

namespace {
SampleRows crossing_columns(const std::vector<SamplingPlaneSpec>& planes) {
  std::vector<Column> cols{{"time", "s"}};
  std::vector<bool> counts{false};
  for (const auto& s : planes) {
    cols.push_back({s.name + "_crossings_positive", "-"});
    cols.push_back({s.name + "_crossings_negative", "-"});
    cols.push_back({s.name + "_mass_positive", "kg"});
    cols.push_back({s.name + "_mass_negative", "kg"});
    counts.insert(counts.end(), {true, true, false, false});
  }
  return SampleRows(std::move(cols), std::move(counts));
}
}  // namespace

SamplingPlaneModule::SamplingPlaneModule(std::vector<SamplingPlaneSpec> planes)
    : planes_(std::move(planes)), counts_(planes_.size()), samples_(crossing_columns(planes_)) {}

void SamplingPlaneModule::register_fields(ParticleStore& p) {
  fields_.clear();
  for (const auto& s : planes_) fields_.push_back(p.add_field("sampling." + s.name + ".side", 0.0));
}

void SamplingPlaneModule::setup(Simulation& sim) {
  if (fields_.size() != planes_.size()) register_fields(sim.particles);
  end_of_step(sim);  // records the side of the particles present at the start (no crossing)
}

void SamplingPlaneModule::end_of_step(Simulation& sim) {
  const auto& p = sim.particles;
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    std::vector<double>& side = sim.particles.field(fields_[k]);
    PlaneCrossings& c = counts_[k];
    const Vec3 o = planes_[k].point, n = planes_[k].normal;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double now = dot(p.x[i] - o, n) > 0 ? 1.0 : -1.0;
      if (side[i] == -1.0 && now == 1.0) {
        ++c.positive;
        c.mass_positive += p.physical_mass(i);
      } else if (side[i] == 1.0 && now == -1.0) {
        ++c.negative;
        c.mass_negative += p.physical_mass(i);
      }
      side[i] = now;
    }
  }
}

void SamplingPlaneModule::sample(const Simulation& sim) {
  std::vector<double> row;
  for (const auto& c : counts_)
    row.insert(row.end(), {static_cast<double>(c.positive), static_cast<double>(c.negative),
                           c.mass_positive, c.mass_negative});
  samples_.add(sim.time, row);
}

std::vector<Table> SamplingPlaneModule::tables(const Simulation&) const {
  return {samples_.table("sampling_planes")};
}

void SamplingPlaneModule::save(Archive& a) const {
  a.put("sampling_planes/counts", counts_);
  samples_.save(a, "sampling_planes/samples");
}

void SamplingPlaneModule::load(const Archive& a) {
  counts_ = a.get<PlaneCrossings>("sampling_planes/counts");
  samples_.load(a, "sampling_planes/samples");
  if (counts_.size() != planes_.size())
    throw Error(
        fmt::format("checkpoint entry 'sampling_planes/counts' holds {} planes, the case {}",
                    counts_.size(), planes_.size()));
}

}  // namespace comminute
