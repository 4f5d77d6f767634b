#include "comminute/engine/sampling_plane.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

bool SamplingPlaneSpec::within(const Vec3& x, const Vec3& v) const {
  if (extent == Extent::infinite) return true;
  const double d = dot(x - point, normal), vn = dot(v, normal);
  const Vec3 crossed = vn != 0 ? x - v * (d / vn) : x - d * normal;
  const Vec3 r = crossed - point;
  if (extent == Extent::disc) return norm2(r - dot(r, normal) * normal) <= radius * radius;
  return std::abs(dot(r, u)) <= half_u && std::abs(dot(r, cross(normal, u))) <= half_v;
}

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
  const ParticleRecorder record(p);
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    std::vector<double>& side = sim.particles.field(fields_[k]);
    PlaneCrossings& c = counts_[k];
    const SamplingPlaneSpec& plane = planes_[k];
    const Vec3 o = plane.point, n = plane.normal;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double now = dot(p.x[i] - o, n) > 0 ? 1.0 : -1.0;
      const bool crossed = side[i] * now == -1.0;
      side[i] = now;
      if (!crossed || !plane.within(p.x[i], p.v[i])) continue;
      const double mass = p.physical_mass(i);
      if (now == 1.0) {
        ++c.positive;
        c.mass_positive += mass;
      } else {
        ++c.negative;
        c.mass_negative += mass;
      }
      if (!plane.log) continue;
      log_.push_back(
          record(i, sim.time, sim.step_count, static_cast<std::uint32_t>(k), now == 1.0 ? 1 : -1));
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

std::vector<Table> SamplingPlaneModule::tables(const Simulation& sim) const {
  std::vector<Table> out{samples_.table("sampling_planes")};
  bool logged = false;
  for (const auto& s : planes_) logged = logged || s.log;
  if (!logged) return out;
  Table t("sampling_log", {{"time", "s"},
                           {"step", "-"},
                           {"plane", "-"},
                           {"direction", "-"},
                           {"id", "-"},
                           {"material", "-"},
                           {"mass", "kg"},
                           {"diameter", "m"},
                           {"generation", "-"}});
  for (const ParticleRecord& r : log_)
    t.add_row({r.time, r.step, planes_.at(r.site).name, static_cast<std::int64_t>(r.direction),
               r.id, sim.materials.material(r.material).name, r.mass, r.diameter, r.generation});
  out.push_back(std::move(t));
  return out;
}

void SamplingPlaneModule::save(Archive& a) const {
  a.put("sampling_planes/counts", counts_);
  a.put("sampling_planes/log", log_);
  samples_.save(a, "sampling_planes/samples");
}

void SamplingPlaneModule::load(const Archive& a) {
  counts_ = a.get<PlaneCrossings>("sampling_planes/counts");
  samples_.load(a, "sampling_planes/samples");
  log_ = a.get<ParticleRecord>("sampling_planes/log");
  for (const auto& r : log_)
    if (r.site >= planes_.size() || !planes_[r.site].log || !(r.mass > 0) ||
        (r.direction != 1 && r.direction != -1))
      throw Error(fmt::format(
          "checkpoint entry 'sampling_planes/log' holds a crossing of plane {} (the case has {}, "
          "logging: see [[sampling_planes]] log), a mass that is not positive or a direction "
          "other than +1 or -1",
          r.site, planes_.size()));
  if (counts_.size() != planes_.size())
    throw Error(
        fmt::format("checkpoint entry 'sampling_planes/counts' holds {} planes, the case {}",
                    counts_.size(), planes_.size()));
}

}  // namespace comminute
