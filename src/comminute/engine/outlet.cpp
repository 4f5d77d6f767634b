#include "comminute/engine/outlet.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

bool OutletSpec::captures(const Vec3& x) const {
  return half_space ? dot(x - point, normal) > 0 : region.contains(x, 0.0);
}

namespace {
SampleRows totals_columns(const std::vector<OutletSpec>& outlets) {
  std::vector<Column> cols{{"time", "s"}};
  std::vector<bool> counts{false};
  for (const auto& o : outlets) {
    cols.push_back({o.name + "_count", "-"});
    cols.push_back({o.name + "_mass", "kg"});
    counts.insert(counts.end(), {true, false});
  }
  return SampleRows(std::move(cols), std::move(counts));
}
}  // namespace

OutletModule::OutletModule(std::vector<OutletSpec> outlets)
    : outlets_(std::move(outlets)), totals_(totals_columns(outlets_)) {}

namespace {
// The fields "composition.0", "composition.1", ... that exist, in order.
std::vector<std::size_t> composition_fields_of(const ParticleStore& p) {
  std::vector<std::size_t> f;
  while (p.has_field("composition." + std::to_string(f.size())))
    f.push_back(p.field_index("composition." + std::to_string(f.size())));
  return f;
}
}  // namespace

void OutletModule::setup(Simulation& sim) {
  composition_ = composition_fields_of(sim.particles);
}

void OutletModule::end_of_step(Simulation& sim) {
  auto& p = sim.particles;
  const ParticleRecorder record(p);
  std::size_t marked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.flags[i] & pflag::remove) continue;
    for (std::size_t k = 0; k < outlets_.size(); ++k) {
      if (!outlets_[k].captures(p.x[i])) continue;
      log_.push_back(record(i, sim.time, sim.step_count, static_cast<std::uint32_t>(k)));
      for (std::size_t f : composition_) compositions_.push_back(p.field(f)[i]);
      // the energy that leaves with it: kinetic, and potential relative to the origin
      sim.ledger.removed += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]) -
                            p.mass[i] * dot(sim.gravity, p.x[i]);
      p.flags[i] |= pflag::remove;
      ++marked;
      break;
    }
  }
  if (marked == 0) return;
  p.compact();
  sim.particles_changed();
}

double OutletModule::removed_mass() const {
  double m = 0;
  for (const auto& r : log_) m += r.mass;
  return m;
}

void OutletModule::sample(const Simulation& sim) {
  std::vector<double> count(outlets_.size(), 0.0), mass(outlets_.size(), 0.0);
  for (const auto& r : log_) {
    count[r.site] += 1;
    mass[r.site] += r.mass;
  }
  std::vector<double> row;
  for (std::size_t k = 0; k < outlets_.size(); ++k) row.insert(row.end(), {count[k], mass[k]});
  totals_.add(sim.time, row);
}

std::vector<Table> OutletModule::tables(const Simulation& sim) const {
  std::vector<Column> cols{{"time", "s"},     {"step", "-"},      {"outlet", "-"},
                           {"id", "-"},       {"material", "-"},  {"mass", "kg"},
                           {"diameter", "m"}, {"generation", "-"}};
  for (std::size_t k = 0; k < composition_.size(); ++k)
    cols.push_back({"composition_" + std::to_string(k), "-"});
  Table removed("outlet_log", cols);
  for (std::size_t n = 0; n < log_.size(); ++n) {
    const ParticleRecord& r = log_[n];
    std::vector<Cell> row{r.time,
                          r.step,
                          outlets_.at(r.site).name,
                          r.id,
                          sim.materials.material(r.material).name,
                          r.mass,
                          r.diameter,
                          r.generation};
    for (std::size_t k = 0; k < composition_.size(); ++k)
      row.emplace_back(compositions_[n * composition_.size() + k]);
    removed.add_row(row);
  }
  return {removed, totals_.table("outlets")};
}

void OutletModule::save(Archive& a) const {
  a.put("outlets/log", log_);
  a.put("outlets/compositions", compositions_);
  totals_.save(a, "outlets/samples");
}

void OutletModule::load(const Archive& a) {
  log_ = a.get<ParticleRecord>("outlets/log");
  compositions_ = a.get<double>("outlets/compositions");
  totals_.load(a, "outlets/samples");
  for (const auto& r : log_)
    if (r.site >= outlets_.size() || !(r.mass > 0) || !(r.diameter > 0) || r.direction != 0)
      throw Error(
          fmt::format("checkpoint entry 'outlets/log' holds a row of outlet {} (the case "
                      "has {}), a mass/diameter that is not positive or a direction (a crossing)",
                      r.site, outlets_.size()));
}

void OutletModule::restored(Simulation& sim) {
  composition_ = composition_fields_of(sim.particles);
  if (compositions_.size() != log_.size() * composition_.size())
    throw Error(
        fmt::format("checkpoint entry 'outlets/compositions' holds {} values, not {} per "
                    "row of 'outlets/log'",
                    compositions_.size(), composition_.size()));
  for (const auto& r : log_)
    if (r.material >= sim.materials.size())
      throw Error(fmt::format("checkpoint entry 'outlets/log' names material {}, the case has {}",
                              r.material, sim.materials.size()));
}

}  // namespace comminute
