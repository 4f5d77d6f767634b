#include "comminute/bonds/grain_breakage_module.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "comminute/bonds/fragments.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::bonds {

GrainBreakageModule::GrainBreakageModule(const BondsModule& bonds, GrainBreakageOptions options)
    : bonds_(bonds), options_(std::move(options)) {}

namespace {

std::unordered_map<std::uint64_t, std::uint32_t> slots_by_id(const ParticleStore& p) {
  std::unordered_map<std::uint64_t, std::uint32_t> m;
  m.reserve(p.owned());
  for (std::size_t i = 0; i < p.owned(); ++i) m.emplace(p.id[i], static_cast<std::uint32_t>(i));
  return m;
}

int wall_index(const Simulation& sim, const std::string& name) {
  for (std::size_t k = 0; k < sim.walls.size(); ++k)
    if (sim.walls[k]->name == name) return static_cast<int>(k);
  throw Error(fmt::format("[grains] no wall is named '{}'", name));
}

// A point of plane wall w: the foot of the perpendicular from x.
Vec3 foot_on(const Wall& w, const Vec3& x) {
  std::vector<WallContact> c;
  w.contacts(x, 0, 1e30, c);
  if (c.empty()) throw Error("[grains] the bed walls must be planes");
  return c.front().point;
}

}  // namespace

void GrainBreakageModule::setup(Simulation& sim) {
  const ParticleStore& p = sim.particles;
  grain_field_ = p.field_index("grain");
  layer_field_ = p.field_index("layer");
  grain_mass_.clear();
  grain_volume_.clear();
  grain_layer_.clear();
  solid_volume_ = 0;
  sphere_volume_ = 0;
  count_new_grains(sim);
  if (!options_.piston.empty()) {
    piston_ = wall_index(sim, options_.piston);
    floor_ = wall_index(sim, options_.floor);
  }
}

void GrainBreakageModule::count_new_grains(const Simulation& sim) {
  const ParticleStore& p = sim.particles;
  counted_next_id_ = p.next_id();
  const auto& g = p.field(grain_field_);
  const auto& l = p.field(layer_field_);
  const std::size_t known = grain_mass_.size();
  std::size_t n = known;
  for (std::size_t i = 0; i < p.owned(); ++i)
    if (g[i] >= 0) n = std::max(n, static_cast<std::size_t>(g[i]) + 1);
  if (n == known) return;
  grain_mass_.resize(n, 0);
  grain_volume_.resize(n, 0);
  grain_layer_.resize(n, 0);
  for (std::size_t i = 0; i < p.owned(); ++i) {
    if (g[i] < 0 || static_cast<std::size_t>(g[i]) < known) continue;
    const auto k = static_cast<std::size_t>(g[i]);
    const double v = p.mass[i] / sim.materials.material(p.material[i]).density;
    grain_mass_[k] += p.mass[i];
    grain_volume_[k] += v;
    grain_layer_[k] = static_cast<std::uint64_t>(l[i]);
    solid_volume_ += v;
    sphere_volume_ += 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3);
  }
  broken_.resize(n, 0);  // a restart keeps the loaded flags
}

GrainBreakageModule::Fragments GrainBreakageModule::fragments(const Simulation& sim) const {
  const ParticleStore& p = sim.particles;
  const auto slot = slots_by_id(p);
  const BondList& b = bonds_.bonds();
  std::vector<std::uint32_t> first, second;
  first.reserve(b.size());
  second.reserve(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = slot.find(b.id_i[k]), j = slot.find(b.id_j[k]);
    if (i == slot.end() || j == slot.end()) continue;
    first.push_back(i->second);
    second.push_back(j->second);
  }
  Fragments f;
  std::uint32_t count = 0;
  f.label = component_labels(p.owned(), first, second, count);
  f.mass.assign(count, 0);
  f.grain.assign(count, -1);
  f.spheres.assign(count, 0);
  const auto& g = p.field(grain_field_);
  for (std::size_t i = 0; i < p.owned(); ++i) {
    f.mass[f.label[i]] += p.mass[i];
    f.grain[f.label[i]] = g[i] >= 0 ? static_cast<std::int64_t>(g[i]) : -1;
    ++f.spheres[f.label[i]];
  }
  return f;
}

std::vector<double> GrainBreakageModule::largest_fractions(const Simulation& sim) const {
  const Fragments f = fragments(sim);
  std::vector<double> largest(grain_mass_.size(), 0);
  for (std::size_t k = 0; k < f.mass.size(); ++k)
    if (f.grain[k] >= 0 && static_cast<std::size_t>(f.grain[k]) < largest.size()) {
      const auto g = static_cast<std::size_t>(f.grain[k]);
      largest[g] = std::max(largest[g], f.mass[k] / grain_mass_[g]);
    }
  return largest;
}

void GrainBreakageModule::post_force(Simulation& sim) {
  if (sim.particles.next_id() != counted_next_id_) count_new_grains(sim);
  const auto& log = bonds_.failures();
  if (log.size() == failures_seen_) return;
  const ParticleStore& p = sim.particles;
  const auto slot = slots_by_id(p);
  const auto& g = p.field(grain_field_);
  for (std::size_t k = failures_seen_; k < log.size(); ++k) {
    const BondFailure& f = log[k];
    if (f.cause == FailureCause::particle_removed) continue;
    const auto i = slot.find(f.id_i), j = slot.find(f.id_j);
    if (i == slot.end() || j == slot.end()) continue;
    if (g[i->second] < 0 || g[i->second] != g[j->second]) continue;
    Vec3 d = p.x[j->second] - p.x[i->second];
    const double l = norm(d);
    d = l > 0 ? d / l : Vec3{1, 0, 0};
    failures_.push_back({static_cast<std::uint64_t>(g[i->second]), {f.position, d}});
  }
  failures_seen_ = log.size();
  const std::vector<double> largest = largest_fractions(sim);
  for (std::size_t k = 0; k < largest.size(); ++k) {
    if (broken_[k] || !(largest[k] < options_.broken_below)) continue;
    broken_[k] = 1;
    std::vector<Vec3> centres;
    double radius = 0;
    for (std::size_t i = 0; i < p.owned(); ++i)
      if (g[i] >= 0 && static_cast<std::size_t>(g[i]) == k) {
        centres.push_back(p.x[i]);
        radius = std::max(radius, p.radius[i]);
      }
    std::vector<FailedBondGeometry> failed;
    for (const GrainFailure& f : failures_)
      if (f.grain == k) failed.push_back(f.geometry);
    GrainBreakageRow r;
    r.time = sim.time;
    r.grain = k;
    r.layer = grain_layer_[k];
    r.largest_fraction = largest[k];
    r.mode = classify_breakage(centres, radius, failed);
    rows_.push_back(r);
  }
}

BedSample GrainBreakageModule::bed(const Simulation& sim) const {
  BedSample s;
  s.time = sim.time;
  if (piston_ < 0) return s;
  const Wall& piston = *sim.walls[static_cast<std::size_t>(piston_)];
  const Wall& floor = *sim.walls[static_cast<std::size_t>(floor_)];
  const Vec3 a = foot_on(floor, {});
  const Vec3 b = foot_on(piston, a);
  s.height = norm(b - a);
  s.stress = norm(piston.force) / options_.area;
  s.void_ratio = options_.area * s.height / sphere_volume_ - 1;
  s.void_ratio_nominal = options_.area * s.height / solid_volume_ - 1;
  return s;
}

void GrainBreakageModule::sample(const Simulation& sim) {
  if (sim.particles.next_id() != counted_next_id_) count_new_grains(sim);
  std::vector<std::uint64_t> grains, broken;
  for (std::size_t k = 0; k < grain_mass_.size(); ++k) {
    const std::size_t l = grain_layer_[k];
    if (grains.size() <= l) {
      grains.resize(l + 1, 0);
      broken.resize(l + 1, 0);
    }
    ++grains[l];
    broken[l] += broken_[k];
  }
  for (std::size_t l = 0; l < grains.size(); ++l)
    if (grains[l] > 0) layer_samples_.push_back({sim.time, l, grains[l], broken[l]});
  if (piston_ >= 0) bed_samples_.push_back(bed(sim));
}

void GrainBreakageModule::save(Archive& a) const {
  a.put("grain_breakage/broken", broken_);
  a.put_value("grain_breakage/failures_seen", failures_seen_);
  a.put("grain_breakage/failures", failures_);
  a.put("grain_breakage/rows", rows_);
  a.put("grain_breakage/layer_samples", layer_samples_);
  a.put("grain_breakage/bed_samples", bed_samples_);
}

void GrainBreakageModule::load(const Archive& a) {
  broken_ = a.get<std::uint8_t>("grain_breakage/broken");
  failures_seen_ = a.get_value<std::uint64_t>("grain_breakage/failures_seen");
  failures_ = a.get<GrainFailure>("grain_breakage/failures");
  rows_ = a.get<GrainBreakageRow>("grain_breakage/rows");
  layer_samples_ = a.get<LayerSample>("grain_breakage/layer_samples");
  bed_samples_ = a.get<BedSample>("grain_breakage/bed_samples");
}

std::vector<Table> GrainBreakageModule::tables(const Simulation& sim) const {
  Table events("grain_breakage", {{"time", "s"},
                                  {"grain", "-"},
                                  {"layer", "-"},
                                  {"largest_fragment_fraction", "-"},
                                  {"mode", "-"}});
  for (const GrainBreakageRow& r : rows_)
    events.add_row({r.time, r.grain, r.layer, r.largest_fraction, mode_name(r.mode)});
  Table layers("breakage_layers", {{"time", "s"},
                                   {"layer", "-"},
                                   {"grains", "-"},
                                   {"broken", "-"},
                                   {"breakage_probability", "-"}});
  for (const LayerSample& s : layer_samples_)
    layers.add_row({s.time, s.layer, s.grains, s.broken,
                    static_cast<double>(s.broken) / static_cast<double>(s.grains)});
  Table grains("grains", {{"grain", "-"},
                          {"layer", "-"},
                          {"mass", "kg"},
                          {"volume", "m3"},
                          {"equivalent_diameter", "m"}});
  for (std::size_t k = 0; k < grain_mass_.size(); ++k)
    grains.add_row({k, grain_layer_[k], grain_mass_[k], grain_volume_[k],
                    std::cbrt(6 * grain_volume_[k] / std::numbers::pi)});
  // fragments now: every fragment of a grain, with its size as the diameter of the sphere of
  // its solid volume (the grain's volume scaled by the fragment's mass share)
  Table frags("fragments", {{"time", "s"},
                            {"grain", "-"},
                            {"layer", "-"},
                            {"mass", "kg"},
                            {"mass_fraction", "-"},
                            {"sub_spheres", "-"},
                            {"equivalent_diameter", "m"}});
  if (sim.particles.has_field("grain") && !grain_mass_.empty()) {
    const Fragments f = fragments(sim);
    for (std::size_t k = 0; k < f.mass.size(); ++k) {
      if (f.grain[k] < 0) continue;
      const auto g = static_cast<std::size_t>(f.grain[k]);
      const double share = f.mass[k] / grain_mass_[g];
      frags.add_row({sim.time, g, grain_layer_[g], f.mass[k], share, f.spheres[k],
                     std::cbrt(6 * share * grain_volume_[g] / std::numbers::pi)});
    }
  }
  std::vector<Table> out{events, layers, grains, frags};
  if (piston_ >= 0) {
    Table bed("bed", {{"time", "s"},
                      {"height", "m"},
                      {"axial_stress", "Pa"},
                      {"void_ratio", "-"},
                      {"void_ratio_nominal", "-"}});
    for (const BedSample& s : bed_samples_)
      bed.add_row({s.time, s.height, s.stress, s.void_ratio, s.void_ratio_nominal});
    out.push_back(bed);
  }
  return out;
}

}  // namespace comminute::bonds
