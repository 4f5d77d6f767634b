#include "comminute/breakage/texture/texture_module.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "comminute/breakage/texture/texture_sampler.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage::texture {

TextureModule::TextureModule(std::shared_ptr<const TextureVolume> volume, TextureOptions opt,
                             std::uint64_t seed)
    : volume_(std::move(volume)),
      opt_(std::move(opt)),
      rng_(seed, rng_stream::texture),
      pool_(volume_->phases().size()),
      inheritance_(opt_.resolution.empty()
                       ? 1
                       : std::max<std::size_t>(
                             1, *std::max_element(opt_.resolution.begin(), opt_.resolution.end()))),
      rows_({{"time", "s"},
             {"textured_particles", "-"},
             {"pool_bytes", "B"},
             {"packed_bytes", "B"},
             {"bytes_per_particle", "B"},
             {"mean_resolution", "-"},
             {"sampled", "-"},
             {"inherited", "-"}},
            {false, true, true, true, false, false, true, true}) {}

void TextureModule::register_fields(ParticleStore& p) {
  owner_ = p.add_field("texture.owner", 0.0);
  composition_.clear();
  for (std::size_t k = 0; k < volume_->phases().size(); ++k)
    composition_.push_back(p.add_field("composition." + std::to_string(k), k == 0 ? 1.0 : 0.0));
}

bool TextureModule::textured(const ParticleStore& p, std::size_t i) const {
  return p.material[i] < opt_.resolution.size() && opt_.resolution[p.material[i]] > 0;
}

void TextureModule::set_composition(ParticleStore& p, std::size_t i, const Cube& c) const {
  const auto counts = phase_counts(c, composition_.size());
  for (std::size_t k = 0; k < composition_.size(); ++k)
    p.field(composition_[k])[i] =
        static_cast<double>(counts[k]) / static_cast<double>(c.labels.size());
}

namespace {
// Final radius of particle i (a growing fragment's target).
double final_radius(const ParticleStore& p, std::size_t i) {
  if (!p.has_field("breakage.target_radius")) return p.radius[i];
  return std::max(p.radius[i], p.field(p.field_index("breakage.target_radius"))[i]);
}
}  // namespace

void TextureModule::sample_new(Simulation& sim, std::size_t i) {
  auto& p = sim.particles;
  const double r = final_radius(p, i);
  const Cube c = sampler_.sample(*volume_, opt_.resolution[p.material[i]], r, rng_);
  pool_.put(p.id[i], c);
  p.field(owner_)[i] = static_cast<double>(p.id[i]);
  set_composition(p, i, c);
  ++sampled_;
  if (!opt_.density_from_phases) return;
  double rho = 0;  // sum_k phi_k rho_k (docs/models.md eq. T4)
  for (std::size_t k = 0; k < composition_.size(); ++k)
    rho += p.field(composition_[k])[i] * volume_->phases()[k].density;
  const double m_new = p.mass_scale(i) * rho * 4.0 / 3.0 * M_PI * r * r * r;  // inertial
  const double m_old = p.mass[i];
  if (!(m_old > 0)) return;
  const double scale = m_new / m_old;
  // The particle's kinetic and potential energy change with its mass: booked as energy added.
  const double de =
      (scale - 1) * (0.5 * m_old * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]) -
                     m_old * dot(sim.gravity, p.x[i]));
  if (sim.step_count > 0) sim.ledger.removed -= de;
  p.mass[i] = m_new;
  p.inertia[i] *= scale;
}

void TextureModule::update(Simulation& sim) {
  auto& p = sim.particles;
  // Particles are given a texture only when they are new (inserted, or fragments: new ids), and
  // textures are dropped only when particles leave: with the same ids issued and the same count
  // as at the last pass, every textured particle still owns its texture and nothing is stale.
  if (p.next_id() == seen_next_id_ && p.owned() == seen_owned_) return;
  std::map<std::uint64_t, std::vector<std::size_t>> fragments;  // by parent id: deterministic
  std::vector<std::size_t> fresh;
  alive_.clear();  // ids of the textured particles (one pass over the particles)
  for (std::size_t i = 0; i < p.owned(); ++i) {
    if (!textured(p, i)) continue;
    alive_.push_back(p.id[i]);
    const auto owner = static_cast<std::uint64_t>(p.field(owner_)[i]);
    if (owner == p.id[i]) continue;
    if (owner == 0)
      fresh.push_back(i);
    else
      fragments[owner].push_back(i);
  }
  for (auto& [parent, slots] : fragments) {
    std::sort(slots.begin(), slots.end(),
              [&p](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
    if (!pool_.has(parent)) {  // no texture to inherit (cannot happen in a run): sample afresh
      for (std::size_t s : slots) sample_new(sim, s);
      continue;
    }
    std::vector<Cube> cubes;
    const auto done = pending_.find(parent);  // split when the parent broke (share())
    if (done != pending_.end() && done->second.size() == slots.size()) {
      cubes = std::move(done->second);
    } else {
      std::vector<double> volumes;
      for (std::size_t s : slots) volumes.push_back(std::pow(final_radius(p, s), 3));
      cubes = inheritance_.split(pool_.get(parent), volumes, composition_.size()).cubes;
    }
    if (done != pending_.end()) pending_.erase(done);
    for (std::size_t k = 0; k < slots.size(); ++k) {
      const std::size_t s = slots[k];
      pool_.put(p.id[s], cubes[k]);
      p.field(owner_)[s] = static_cast<double>(p.id[s]);
      set_composition(p, s, cubes[k]);
      ++inherited_;
    }
    pool_.erase(parent);
  }
  for (std::size_t i : fresh) sample_new(sim, i);
  // Textures of particles that left the run (outlets, fines): dropped.
  // Every textured particle now owns one texture, so a larger pool holds stale ones.
  if (pool_.size() > alive_.size()) {
    std::sort(alive_.begin(), alive_.end());
    for (std::uint64_t id : pool_.owners())
      if (!std::binary_search(alive_.begin(), alive_.end(), id)) pool_.erase(id);
  }
  seen_next_id_ = p.next_id();
  seen_owned_ = p.owned();
}

void TextureModule::share(const ParticleStore& p, std::size_t parent,
                          const std::vector<double>& radii, std::vector<double>& masses) {
  const std::uint64_t id = p.id[parent];
  if (!opt_.density_from_phases || !pool_.has(id) || radii.empty()) return;
  std::vector<double> volumes;
  for (double r : radii) volumes.push_back(r * r * r);
  auto split = inheritance_.split(pool_.get(id), volumes, composition_.size());
  double total = 0, weight = 0;
  std::vector<double> w(radii.size());
  for (std::size_t j = 0; j < radii.size(); ++j) {
    const auto counts = phase_counts(split.cubes[j], composition_.size());
    double rho = 0;  // docs/models.md eq. T4
    for (std::size_t k = 0; k < counts.size(); ++k)
      rho += static_cast<double>(counts[k]) * volume_->phases()[k].density;
    w[j] = volumes[j] * rho / static_cast<double>(split.cubes[j].labels.size());
    weight += w[j];
    total += masses[j];
  }
  if (weight > 0)
    for (std::size_t j = 0; j < radii.size(); ++j) masses[j] = total * w[j] / weight;
  pending_[id] = std::move(split.cubes);
}

void TextureModule::setup(Simulation& sim) {
  register_fields(sim.particles);
  if (opt_.resolution.size() < sim.materials.size())
    opt_.resolution.resize(sim.materials.size(), 0);
  update(sim);
}

Cadence TextureModule::output_cadence() const {
  return Cadence::interval_or_steps(opt_.output_interval, 1000);
}

void TextureModule::sample(const Simulation& sim) {
  const double n = static_cast<double>(pool_.size());
  double res = 0;
  for (std::uint64_t id : pool_.owners()) res += static_cast<double>(pool_.resolution(id));
  rows_.add(sim.time,
            {n, static_cast<double>(pool_.bytes()), static_cast<double>(pool_.live_bytes()),
             n > 0 ? static_cast<double>(pool_.bytes()) / n : 0.0, n > 0 ? res / n : 0.0,
             static_cast<double>(sampled_), static_cast<double>(inherited_)});
}

std::vector<Table> TextureModule::tables(const Simulation&) const {
  return {rows_.table("texture")};
}

void TextureModule::save(Archive& a) const {
  pool_.save(a, "texture/pool/");
  const auto& s = rng_.state();
  a.put("texture/rng", std::vector<std::uint64_t>(s.begin(), s.end()));
  a.put("texture/counts", std::vector<std::uint64_t>{sampled_, inherited_});
  rows_.save(a, "texture/rows");
}

void TextureModule::load(const Archive& a) {
  pool_.load(a, "texture/pool/");
  const auto s = a.get<std::uint64_t>("texture/rng");
  if (s.size() != 4) throw Error("checkpoint entry 'texture/rng' has a wrong size");
  rng_.set_state({s[0], s[1], s[2], s[3]});
  const auto c = a.get<std::uint64_t>("texture/counts");
  if (c.size() != 2) throw Error("checkpoint entry 'texture/counts' has a wrong size");
  sampled_ = c[0];
  inherited_ = c[1];
  rows_.load(a, "texture/rows");
  seen_next_id_ = 0;  // the particles were read back too: the next update looks at them all
}

}  // namespace comminute::breakage::texture
