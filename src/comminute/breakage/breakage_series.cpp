#include "comminute/breakage/breakage_series.hpp"

#include <algorithm>

#include "comminute/breakage/breakage_module.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

Cadence BreakageSeries::output_cadence() const {
  return Cadence::interval_or_steps(interval_, 1000);
}

void BreakageSeries::sample(const Simulation& sim) {
  LedgerRow r{};
  r.time = sim.time;
  r.removed_total = sim.ledger.removed;
  r.breakage_removed = module_.removed_energy();
  r.created = module_.created_energy();
  r.particle_mass = sim.particles.total_mass();
  for (double m : module_.fines_mass()) r.fines_mass += m;
  r.momentum = sim.particles.total_momentum();
  r.fines_momentum = module_.fines_momentum();
  r.events = module_.events();
  r.breakages = module_.breakages();
  r.pending = module_.pending();
  r.particles = sim.particles.size();
  ledger_.push_back(r);
}

std::vector<Table> BreakageSeries::tables(const Simulation& sim) const {
  std::vector<Table> t;
  t.push_back(model_curves(sim));
  t.push_back(events());
  t.push_back(fragments());
  t.push_back(ledger());
  return t;
}

Table BreakageSeries::events() const {
  Table t("breakage_events", {{"time", "s"},
                              {"parent_id", "-"},
                              {"material", "-"},
                              {"generation", "-"},
                              {"diameter", "m"},
                              {"mass", "kg"},
                              {"specific_energy", "J/kg"},
                              {"stressing_energy", "J/kg"},
                              {"peak_force", "N"},
                              {"strength", "J/kg or N"},
                              {"strength_unit", "-"},
                              {"damage_before", "-"},
                              {"broken", "-"},
                              {"fragments", "-"},
                              {"fines_particles", "-"},
                              {"fines_mass", "kg"},
                              {"t10", "%"}});
  for (const auto& r : module_.log()) {
    const MaterialBreakage* m = module_.material(r.material);
    t.add_row({r.time, r.parent_id, r.material, r.generation, r.diameter, r.mass, r.specific_energy,
               r.stressing_energy, r.peak_force, r.strength,
               m ? std::string(m->criterion->strength_unit()) : std::string(), r.damage_before,
               r.broken, r.fragments, r.fines_particles, r.fines_mass, r.t10});
  }
  return t;
}

Table BreakageSeries::fragments() const {
  Table t("breakage_fragments", {{"time", "s"},
                                 {"parent_id", "-"},
                                 {"fragment_id", "-"},
                                 {"generation", "-"},
                                 {"diameter", "m"},
                                 {"mass", "kg"},
                                 {"fines", "-"}});
  for (const auto& f : module_.fragment_log())
    t.add_row({f.time, f.parent_id, f.fragment_id, f.generation, f.diameter, f.mass, f.fines});
  return t;
}

Table BreakageSeries::ledger() const {
  Table t("breakage_ledger", {{"time", "s"},
                              {"events", "-"},
                              {"breakages", "-"},
                              {"pending_fragments", "-"},
                              {"particles", "-"},
                              {"particle_mass", "kg"},
                              {"fines_mass", "kg"},
                              {"removed_energy_total", "J"},
                              {"removed_energy_breakage", "J"},
                              {"created_elastic_energy", "J"},
                              {"momentum_x", "kg m/s"},
                              {"momentum_y", "kg m/s"},
                              {"momentum_z", "kg m/s"},
                              {"fines_momentum_x", "kg m/s"},
                              {"fines_momentum_y", "kg m/s"},
                              {"fines_momentum_z", "kg m/s"}});
  for (const auto& r : ledger_)
    t.add_row({r.time, r.events, r.breakages, r.pending, r.particles, r.particle_mass, r.fines_mass,
               r.removed_total, r.breakage_removed, r.created, r.momentum.x, r.momentum.y,
               r.momentum.z, r.fines_momentum.x, r.fines_momentum.y, r.fines_momentum.z});
  return t;
}

// Model curves for the plots, per material at the mean diameter of its logged events of the
// first generation (all events when there are none): breakage probability of a fresh particle
// (-1 for force criteria) and t10 versus absorbed specific energy.
Table BreakageSeries::model_curves(const Simulation& sim) const {
  Table t("breakage_model", {{"material", "-"},
                             {"diameter", "m"},
                             {"specific_energy", "J/kg"},
                             {"probability", "-"},
                             {"t10", "%"}});
  const auto& log = module_.log();
  for (std::size_t m = 0; m < sim.materials.size(); ++m) {
    const MaterialBreakage* mat = module_.material(m);
    if (!mat) continue;
    double d = 0, e_max = 0;
    std::size_t n = 0;
    bool first_generation = false;
    for (const auto& r : log) first_generation |= r.material == m && r.generation == 0;
    for (const auto& r : log)
      if (r.material == m && (!first_generation || r.generation == 0)) {
        d += r.diameter;
        e_max = std::max({e_max, r.specific_energy, r.stressing_energy});
        ++n;
      }
    if (n == 0) continue;
    d /= static_cast<double>(n);
    const bool energy_criterion = mat->criterion->energy_based();
    for (int k = 0; k <= 200; ++k) {
      const double e = 1.5 * e_max * k / 200.0;
      const double prob = energy_criterion ? mat->criterion->probability(d, {e, 0.0}) : -1.0;
      double e50b = mat->criterion->t10_median_energy(d, e, mat->progeny->e50b_rule());
      if (e50b <= 0) e50b = mat->reference_energy;
      t.add_row({m, d, e, prob, mat->progeny->t10(e, e50b)});
    }
  }
  return t;
}

void BreakageSeries::save(Archive& a) const {
  a.put("breakage/ledger", ledger_);
}

void BreakageSeries::load(const Archive& a) {
  ledger_ = a.get<LedgerRow>("breakage/ledger");
}

}  // namespace comminute::breakage
