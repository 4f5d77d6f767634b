#include "comminute/analysis/collision_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::analysis {

const std::array<const char*, CollisionLogModule::n_quantities> CollisionLogModule::quantity_names =
    {"impact_energy_reduced_mass", "impact_energy_average_mass", "dissipated_normal",
     "dissipated_tangential", "dissipated"};

CollisionLogModule::CollisionLogModule(CollisionLogSettings s)
    : s_(std::move(s)), detector_(s_.rule) {
  const std::size_t nm = s_.materials.size();
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = a; b < nm; ++b) names_.push_back(s_.materials[a] + "-" + s_.materials[b]);
  for (std::size_t w = 0; w < s_.walls.size(); ++w)
    for (std::size_t m = 0; m < nm; ++m) names_.push_back(s_.materials[m] + "-wall_" + s_.walls[w]);
  names_.push_back("all");
  sums_.assign(names_.size(), {});
  hist_.assign(names_.size() * n_quantities,
               EnergyHistogram(s_.energy_min, s_.energy_max, s_.bins));
  if (!s_.detect) window_start_ = s_.start;
}

std::size_t CollisionLogModule::pair_type(std::size_t a, std::size_t b) const {
  if (a > b) std::swap(a, b);
  const std::size_t nm = s_.materials.size();
  return a * nm - a * (a - 1) / 2 + (b - a);  // rows a' < a hold nm - a' types each
}

std::size_t CollisionLogModule::wall_type(std::size_t wall, std::size_t material) const {
  const std::size_t nm = s_.materials.size();
  return nm * (nm + 1) / 2 + wall * nm + material;
}

void CollisionLogModule::declare_contact_state(ContactPipeline& pipeline) {
  pipeline.require_collision_record();
}

double CollisionLogModule::window_length(double now) const {
  if (!window_open()) return 0;
  return std::max(0.0, std::min(now, s_.end) - window_start_);
}

void CollisionLogModule::add(std::size_t type, const CollisionSums& e,
                             const std::array<double, n_quantities>& q) {
  CollisionSums& t = sums_[type];
  t.events_total += e.events_total;
  if (e.events == 0) return;
  t.events += 1;
  t.impact_reduced += e.impact_reduced;
  t.impact_average += e.impact_average;
  t.dissipated_normal += e.dissipated_normal;
  t.dissipated_tangential += e.dissipated_tangential;
  t.duration += e.duration;
  t.max_overlap += e.max_overlap;
  t.max_normal_force += e.max_normal_force;
  t.diameter_1 += e.diameter_1;
  t.diameter_2 += e.diameter_2;
  for (int k = 0; k < n_quantities; ++k)
    hist_[type * n_quantities + static_cast<std::size_t>(k)].add(q[static_cast<std::size_t>(k)]);
}

void CollisionLogModule::post_force(Simulation& sim) {
  const auto& ended = sim.ended_contacts();
  if (ended.empty()) return;
  const auto& p = sim.particles;
  const bool in_window = window_open() && sim.time > window_start_ && sim.time <= s_.end;
  for (const EndedContact& c : ended) {
    const double mi = p.mass[c.i], di = 2 * p.radius[c.i];
    const std::size_t mat_i = p.material[c.i];
    CollisionSums e;
    e.events_total = 1;
    e.events = in_window ? 1 : 0;
    double reduced = mi, average = mi;  // a wall: infinite mass, the particle's is both
    std::size_t type = 0;
    if (c.wall) {
      type = wall_type(c.j, mat_i);
      e.diameter_1 = di;
    } else {
      const double mj = p.mass[c.j], dj = 2 * p.radius[c.j];
      const std::size_t mat_j = p.material[c.j];
      type = pair_type(mat_i, mat_j);
      reduced = mi * mj / (mi + mj);
      average = 0.5 * (mi + mj);
      // diameter_1 of the first material of the type's name (same material: the smaller)
      const bool i_first = mat_i < mat_j || (mat_i == mat_j && di <= dj);
      e.diameter_1 = i_first ? di : dj;
      e.diameter_2 = i_first ? dj : di;
    }
    const CollisionTotals& r = c.totals;
    const double v2 = r.impact_speed * r.impact_speed;
    // impact energy 1/2 m* v_n^2 at first touch (Landau & Lifshitz, Mechanics, 1976, sec. 13)
    e.impact_reduced = 0.5 * reduced * v2;
    e.impact_average = 0.5 * average * v2;
    e.dissipated_normal = r.dissipated_normal;
    e.dissipated_tangential = r.dissipated_tangential;
    e.duration = r.duration;
    e.max_overlap = r.max_overlap;
    e.max_normal_force = r.max_normal_force;
    // the mass-specific impact energy E / m* = 1/2 v_n^2 (J/kg), Capece's E_m
    const std::array<double, n_quantities> q{e.impact_reduced,
                                             e.impact_average,
                                             e.dissipated_normal,
                                             e.dissipated_tangential,
                                             e.dissipated_normal + e.dissipated_tangential,
                                             0.5 * v2};
    add(type, e, q);
    add(names_.size() - 1, e, q);
  }
}

void CollisionLogModule::end_of_step(Simulation& sim) {
  if (!s_.detect || window_open()) return;
  const auto& p = sim.particles;
  double kinetic = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    kinetic += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]);
  if (const auto t = detector_.add(sim.time, sim.ledger.wall_work, kinetic)) window_start_ = *t;
}

void CollisionLogModule::sample(const Simulation& sim) {
  last_time_ = sim.time;
}

double CollisionLogModule::impacts_per_particle(std::size_t type, double frequency,
                                                const Simulation& sim) const {
  const double n = static_cast<double>(sim.particles.owned());
  if (n == 0) return 0;
  const std::size_t nm = s_.materials.size();
  if (type + 1 == names_.size()) {  // all: the sum over the types
    double f = 0;
    const double window = window_length(sim.time);
    for (std::size_t k = 0; k + 1 < names_.size(); ++k)
      f += impacts_per_particle(k, window > 0 ? sums_[k].events / window : 0.0, sim);
    return f;
  }
  // each particle of a pair has an impact, a particle on a wall one
  const bool wall = type >= nm * (nm + 1) / 2;
  return (wall ? 1.0 : 2.0) * frequency / n;
}

std::vector<Table> CollisionLogModule::tables(const Simulation& sim) const {
  const double window = window_length(sim.time);
  const double per_s = window > 0 ? 1.0 / window : 0.0;
  Table summary("collisions", {{"contact_type", "-"},
                               {"events_total", "-"},
                               {"events", "-"},
                               {"window_start", "s"},
                               {"window_length", "s"},
                               {"frequency", "1/s"},
                               {"mean_impact_energy_reduced_mass", "J"},
                               {"mean_impact_energy_average_mass", "J"},
                               {"mean_dissipated_normal", "J"},
                               {"mean_dissipated_tangential", "J"},
                               {"dissipation_rate", "W"},
                               {"mean_duration", "s"},
                               {"mean_max_overlap", "m"},
                               {"mean_max_normal_force", "N"},
                               {"mean_diameter_1", "m"},
                               {"mean_diameter_2", "m"},
                               {"events_below_energy_min", "-"},
                               {"events_above_energy_max", "-"},
                               {"impacts_per_particle", "1/s"}});
  Table cumulative("collision_distributions", {{"contact_type", "-"},
                                               {"quantity", "-"},
                                               {"energy", "J"},
                                               {"cumulative_fraction", "-"},
                                               {"cumulative_frequency", "1/s"}});
  std::vector<Table> out;
  const int spectrum_q = static_cast<int>(s_.spectrum);
  for (std::size_t k = 0; k < names_.size(); ++k) {
    const CollisionSums& t = sums_[k];
    if (t.events_total == 0 && k + 1 < names_.size()) continue;
    const double n = t.events, mean = n > 0 ? 1.0 / n : 0.0;
    const EnergyHistogram& hs = histogram(k, spectrum_q);
    summary.add_row(
        {names_[k], static_cast<std::uint64_t>(t.events_total), static_cast<std::uint64_t>(n),
         window_open() ? window_start_ : 0.0, window, n * per_s, t.impact_reduced * mean,
         t.impact_average * mean, t.dissipated_normal * mean, t.dissipated_tangential * mean,
         (t.dissipated_normal + t.dissipated_tangential) * per_s, t.duration * mean,
         t.max_overlap * mean, t.max_normal_force * mean, t.diameter_1 * mean, t.diameter_2 * mean,
         hs.below(), hs.above(), impacts_per_particle(k, n * per_s, sim)});
    for (int q = 0; q < n_quantities - 1; ++q) {  // energies in J (not the specific one)
      const EnergyHistogram& h = histogram(k, q);
      for (int b = 0; b <= h.bins(); ++b) {
        const double f = h.cumulative(b);
        cumulative.add_row(
            {names_[k], quantity_names[static_cast<std::size_t>(q)], h.edge(b), f, f * n * per_s});
      }
    }
    Table spectrum("collision_spectrum_" + names_[k],
                   {{"energy_J", "", true}, {"frequency_per_s", "", true}});
    for (int b = 0; b < hs.bins(); ++b)
      spectrum.add_row({hs.bin_energy(b), static_cast<double>(hs.count(b)) * per_s});
    out.push_back(std::move(spectrum));
    Table specific("collision_specific_energy_" + names_[k],
                   {{"specific_energy_J_per_kg", "", true}, {"probability", "", true}});
    const EnergyHistogram& hm = histogram(k, n_quantities - 1);
    std::uint64_t binned = 0;
    for (int b = 0; b < hm.bins(); ++b) binned += hm.count(b);
    for (int b = 0; b < hm.bins(); ++b)
      specific.add_row(
          {hm.bin_energy(b),
           binned > 0 ? static_cast<double>(hm.count(b)) / static_cast<double>(binned) : 0.0});
    out.push_back(std::move(specific));
  }
  out.insert(out.begin(), std::move(cumulative));
  out.insert(out.begin(), std::move(summary));
  return out;
}

void CollisionLogModule::save(Archive& a) const {
  a.put("collisions/sums", sums_);
  a.put_value("collisions/window_start", window_start_);
  for (std::size_t k = 0; k < hist_.size(); ++k)
    hist_[k].save(a, fmt::format("collisions/histogram/{}/", k));
  detector_.save(a, "collisions/steady_state/");
}

void CollisionLogModule::load(const Archive& a) {
  auto sums = a.get<CollisionSums>("collisions/sums");
  if (sums.size() != sums_.size())
    throw Error(
        fmt::format("checkpoint entry 'collisions/sums' holds {} contact types, the case {}",
                    sums.size(), sums_.size()));
  sums_ = std::move(sums);
  window_start_ = a.get_value<double>("collisions/window_start");
  if (!std::isfinite(window_start_))
    throw Error("checkpoint entry 'collisions/window_start' is not a time");
  for (std::size_t k = 0; k < hist_.size(); ++k)
    hist_[k].load(a, fmt::format("collisions/histogram/{}/", k));
  detector_.load(a, "collisions/steady_state/");
}

}  // namespace comminute::analysis
