#include "comminute/analysis/size_distribution_observer.hpp"

#include <algorithm>

#include "comminute/engine/simulation.hpp"

namespace comminute::analysis {

SizeDistributionObserver::SizeDistributionObserver(const breakage::BreakageModule* breakage,
                                                   SieveOptions sieves, double interval)
    : breakage_(breakage), options_(std::move(sieves)), interval_(interval) {}

namespace {
std::vector<double> final_diameters(const ParticleStore& p) {
  std::vector<double> d(p.size());
  const bool has_target = p.has_field("breakage.target_radius");
  const std::vector<double>* target =
      has_target ? &p.field(p.field_index("breakage.target_radius")) : nullptr;
  for (std::size_t i = 0; i < p.size(); ++i)
    d[i] = 2 * std::max(p.radius[i], target ? (*target)[i] : 0.0);
  return d;
}
}  // namespace

void SizeDistributionObserver::setup(Simulation& sim) {
  if (!sieves_.empty()) return;  // restart: keep the sieves of the run
  if (!options_.sieves.empty()) {
    sieves_ = options_.sieves;
    std::sort(sieves_.rbegin(), sieves_.rend());
  } else {
    double top = 0;
    for (double r : sim.particles.radius) top = std::max(top, 2 * r);
    sieves_ = sqrt2_series(top > 0 ? top : 1e-3, options_.bottom);
  }
}

Cadence SizeDistributionObserver::output_cadence() const {
  return Cadence::interval_or_steps(interval_, 2000);
}

void SizeDistributionObserver::sample(const Simulation& sim) {
  const auto& p = sim.particles;
  const std::size_t nm = sim.materials.size();
  const auto passing = mass_passing(p, final_diameters(p), sieves_, nm, breakage_->fines_mass());
  std::vector<double> total(nm, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) total[p.material[i]] += p.physical_mass(i);
  for (std::size_t m = 0; m < nm; ++m) {
    total[m] += m < breakage_->fines_mass().size() ? breakage_->fines_mass()[m] : 0.0;
    if (total[m] <= 0) continue;
    for (std::size_t s = 0; s < sieves_.size(); ++s)
      rows_.push_back({sim.time, static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(s),
                       passing[m][s], total[m]});
  }
}

std::vector<Table> SizeDistributionObserver::tables(const Simulation& sim) const {
  Table t("size_distribution", {{"time", "s"},
                                {"material", "-"},
                                {"sieve", "m"},
                                {"mass_passing", "kg"},
                                {"fraction_passing", "-"}});
  for (const auto& r : rows_)
    t.add_row({r.time, sim.materials.material(static_cast<std::uint16_t>(r.material)).name,
               sieves_[r.sieve], r.passing, r.passing / r.total});
  return {t};
}

void SizeDistributionObserver::save(Archive& a) const {
  a.put("size_distribution/sieves", sieves_);
  a.put("size_distribution/rows", rows_);
}

void SizeDistributionObserver::load(const Archive& a) {
  sieves_ = a.get<double>("size_distribution/sieves");
  rows_ = a.get<Row>("size_distribution/rows");
}

}  // namespace comminute::analysis
