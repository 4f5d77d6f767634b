#include "comminute/bonds/grain_pour.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/bonds/bonds_module.hpp"
#include "comminute/bonds/grain_placement.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"
#include "comminute/engine/insertion.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::bonds {

GrainPourModule::GrainPourModule(GrainPourSpec spec, std::uint64_t seed)
    : spec_(std::move(spec)), rng_(seed, rng_stream::grain_pour + 16 * spec_.stream) {
  if (spec_.templates.empty()) throw Error(spec_.label + ": a pour needs a grain template");
  for (const GrainTemplate& t : spec_.templates) {
    // the sub-spheres carry the grain's mass: density scaled by shape volume / sphere volume (as
    // a fill does, io/case/cluster_case.cpp)
    const double n = static_cast<double>(t.centres.size());
    const double rho = spec_.density * t.volume / (n * units::sphere_volume(t.radius));
    const double m = rho * units::sphere_volume(t.radius);  // what ParticleStore::add gives
    double grain = 0;
    for (std::size_t k = 0; k < t.centres.size(); ++k) grain += m;
    sphere_density_.push_back(rho);
    sphere_mass_.push_back(m);
    grain_mass_.push_back(grain);
  }
}

void GrainPourModule::find_bonds(Simulation& sim) {
  bonds_ = nullptr;
  for (const auto& m : sim.modules)
    if (auto* b = dynamic_cast<BondsModule*>(m.get())) bonds_ = b;
  if (!bonds_)
    throw SimulationError(spec_.label +
                          ": poured grains need a bonds module ([bonds] with within_grain = true)");
  const ParticleStore& p = sim.particles;
  grain_field_ = p.field_index("grain");
  layer_field_ = p.field_index("layer");
  batch_field_ = p.field_index("batch");
}

void GrainPourModule::setup(Simulation& sim) {
  find_bonds(sim);
  next_time_ = spec_.start;
  double next = 0;  // grain ids continue those of earlier grains
  for (double g : sim.particles.field(grain_field_)) next = std::max(next, g + 1);
  first_grain_ = static_cast<std::uint64_t>(next);
}

void GrainPourModule::restored(Simulation& sim) {
  find_bonds(sim);
}

bool GrainPourModule::done() const {
  return (spec_.count > 0 && poured() >= spec_.count) ||
         (spec_.mass > 0 && poured_mass_ >= spec_.mass);
}

std::uint64_t GrainPourModule::place(Simulation& sim, std::uint64_t n) {
  ParticleStore& p = sim.particles;
  Vec3 lo, hi;
  spec_.region.bounds(lo, hi);
  double largest = 0;
  for (const GrainTemplate& t : spec_.templates) largest = std::max(largest, t.radius);
  // the particles that can touch the region, on a grid of the largest diameter among them
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < p.owned(); ++i) {
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && p.x[i][a] + p.radius[i] > lo[a] - 2 * largest &&
           p.x[i][a] - p.radius[i] < hi[a] + 2 * largest;
    if (in) near.push_back(i);
  }
  for (auto i : near) largest = std::max(largest, p.radius[i]);
  SphereGrid grid(2 * largest);
  for (auto i : near) grid.add(p.x[i], p.radius[i]);
  std::vector<const Wall*> walls;
  for (const auto& w : sim.walls) walls.push_back(w.get());
  const double window = (spec_.end - spec_.start) / spec_.layers;
  const auto layer = static_cast<std::uint64_t>(
      spec_.layers == 1
          ? 1
          // the same 1e-9 slack as the count due: a round at k windows falls in window k + 1
          : std::min<double>(spec_.layers,
                             1 + std::floor((sim.time - spec_.start) / window + 1e-9)));
  GrainPose pose;
  std::vector<std::array<std::uint32_t, 2>> pairs;
  std::uint64_t placed = 0;
  for (; placed < n && !done(); ++placed) {
    const std::size_t ti = poured() % spec_.templates.size();
    const GrainTemplate& t = spec_.templates[ti];
    if (!try_place_grain(t, spec_.region, spec_.region, grid, walls, spec_.attempts, rng_, pose))
      break;
    Vec3 v = spec_.velocity;
    if (spec_.velocity_spread > 0)
      for (int a = 0; a < 3; ++a) v[a] += spec_.velocity_spread * rng_.uniform(-1.0, 1.0);
    if (placed == 0) ++batches_;
    const std::uint64_t grain = first_grain_ + poured();
    const auto first = static_cast<std::uint32_t>(p.size());
    for (const Vec3& x : pose.spheres) {
      ParticleInit init;
      init.x = x;
      init.v = v;
      init.radius = t.radius;
      init.density = sphere_density_[ti];
      init.material = spec_.material;
      p.add(init);
      p.field(grain_field_).back() = static_cast<double>(grain);
      p.field(layer_field_).back() = static_cast<double>(layer);
      p.field(batch_field_).back() = static_cast<double>(batches_);
      grid.add(x, t.radius);
    }
    pairs.clear();
    for (const auto& [a, b] : t.bonds) pairs.push_back({first + a, first + b});
    bonds_->bond_pairs(sim, pairs);
    grains_.push_back({sim.time, grain, batches_, layer, ti, pose.centre, pose.rotation});
    poured_mass_ += grain_mass_[ti];
  }
  if (placed > 0) sim.particles_changed();
  return placed;
}

void GrainPourModule::pre_force(Simulation& sim) {
  if (done() || sim.time < next_time_ || sim.time > spec_.end + spec_.interval) return;
  next_time_ += spec_.interval;
  const std::uint64_t due = pour_due(spec_.rate, spec_.start, spec_.end, sim.time, spec_.count);
  if (due <= poured()) return;
  place(sim, due - poured());
  if (poured() < due && !done() && !warned_full_) {
    fmt::print(stderr,
               "warning: {}: no room for more grains at t = {:.4g} s ({} of {} poured); the "
               "rest follows as space frees up\n",
               spec_.label, sim.time, poured(), due);
    warned_full_ = true;
  }
}

void GrainPourModule::save(Archive& a) const {
  a.put_value(name() + "/rng", rng_.state());
  a.put_value(name() + "/first_grain", first_grain_);
  a.put_value(name() + "/batches", batches_);
  a.put_value(name() + "/next_time", next_time_);
  a.put_value(name() + "/poured_mass", poured_mass_);
  a.put(name() + "/grains", grains_);
}

void GrainPourModule::load(const Archive& a) {
  rng_.set_state(a.get_value<Rng::State>(name() + "/rng"));
  first_grain_ = a.get_value<std::uint64_t>(name() + "/first_grain");
  batches_ = a.get_value<std::uint64_t>(name() + "/batches");
  next_time_ = a.get_value<double>(name() + "/next_time");
  poured_mass_ = a.get_value<double>(name() + "/poured_mass");
  grains_ = a.get<PouredGrain>(name() + "/grains");
  if (!std::isfinite(next_time_) || !(poured_mass_ >= 0))
    throw Error(
        fmt::format("checkpoint entries '{}/next_time' and 'poured_mass' are not a time "
                    "and a mass",
                    name()));
  for (const PouredGrain& g : grains_)
    if (g.templ >= spec_.templates.size() || g.batch > batches_)
      throw Error(
          fmt::format("checkpoint entry '{}/grains' holds a grain of template {} or "
                      "batch {} this pour does not have",
                      name(), g.templ, g.batch));
}

std::vector<Table> GrainPourModule::tables(const Simulation&) const {
  Table t(fmt::format("poured_grains_{}", spec_.stream), {{"time", "s"},
                                                          {"grain", "-"},
                                                          {"batch", "-"},
                                                          {"layer", "-"},
                                                          {"template", "-"},
                                                          {"x", "m"},
                                                          {"y", "m"},
                                                          {"z", "m"},
                                                          {"q_w", "-"},
                                                          {"q_x", "-"},
                                                          {"q_y", "-"},
                                                          {"q_z", "-"}});
  for (const PouredGrain& g : grains_)
    t.add_row({g.time, g.grain, g.batch, g.layer, g.templ, g.centre.x, g.centre.y, g.centre.z,
               g.rotation[0], g.rotation[1], g.rotation[2], g.rotation[3]});
  return {t};
}

}  // namespace comminute::bonds
