#include "comminute/bonds/bonds_module.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "comminute/core/error.hpp"
#include "comminute/engine/contact_stress.hpp"
#include "comminute/engine/parallel_threshold.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::bonds {

BondsModule::BondsModule(std::unique_ptr<BondLaw> law, BondOptions options)
    : law_(std::move(law)), options_(std::move(options)) {}

void BondsModule::setup(Simulation& sim) {
  rng_ = Rng(sim.seed, rng_stream::bonds);
}

void BondsModule::post_force(Simulation& sim) {
  if (!created_ && sim.time >= options_.create_at - 0.5 * sim.dt) create_bonds(sim);
  if (created_) apply(sim);
}

void BondsModule::create_bonds(Simulation& sim) {
  created_ = true;
  const ParticleStore& p = sim.particles;
  const NeighborList& pairs = sim.pairs();
  if (options_.gap_tolerance > sim.options.skin)
    throw SimulationError(fmt::format(
        "[bonds] gap_tolerance = {} m exceeds the neighbour skin {} m: pairs that far apart are "
        "not listed; raise [simulation] skin or lower gap_tolerance",
        options_.gap_tolerance, sim.options.skin));
  auto selected = [&](std::size_t i) {
    return options_.materials.empty() ||
           std::find(options_.materials.begin(), options_.materials.end(), p.material[i]) !=
               options_.materials.end();
  };
  const std::vector<double>* grain = nullptr;
  if (options_.within_grain) {
    if (!p.has_field("grain"))
      throw SimulationError(
          "[bonds] within_grain = true needs particles with a grain field (an [[insert]] of "
          "type \"clusters\")");
    grain = &p.field(p.field_index("grain"));
  }
  // candidates in id order, so that the bonds and their random strengths do not depend on slots
  std::vector<std::tuple<std::uint64_t, std::uint64_t, std::uint32_t, std::uint32_t>> found;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    std::uint32_t i = pairs.first[k], j = pairs.second[k];
    if (i >= p.owned() || j >= p.owned()) continue;  // a periodic image: not bonded
    if (!selected(i) || !selected(j)) continue;
    if (grain && ((*grain)[i] < 0 || (*grain)[i] != (*grain)[j])) continue;
    const double gap = norm(p.x[j] - p.x[i]) - p.radius[i] - p.radius[j];
    if (gap > options_.gap_tolerance) continue;
    if (p.id[j] < p.id[i]) std::swap(i, j);
    found.emplace_back(p.id[i], p.id[j], i, j);
  }
  std::sort(found.begin(), found.end());
  // pairs bonded already (a pour bonds its grains when it inserts them) are not bonded twice
  std::vector<std::pair<std::uint64_t, std::uint64_t>> bonded;
  for (std::size_t b = 0; b < bonds_.size(); ++b)
    bonded.emplace_back(std::min(bonds_.id_i[b], bonds_.id_j[b]),
                        std::max(bonds_.id_i[b], bonds_.id_j[b]));
  std::sort(bonded.begin(), bonded.end());
  bonds_.reserve(bonds_.size() + found.size());  // made once: no spare capacity
  for (const auto& [a, b, i, j] : found)
    if (!std::binary_search(bonded.begin(), bonded.end(), std::pair{a, b})) make_bond(sim, i, j);
}

void BondsModule::fail(Simulation& sim, std::size_t b, FailureCause cause, const Vec3& at) {
  BondState& s = bonds_.state[b];
  if (cause == FailureCause::particle_removed) {  // what the bond held is lost with it
    sim.ledger.bond_dissipated += s.strain_energy;
    s.dissipated += s.strain_energy;
    s.strain_energy = 0;
  }
  failures_.push_back({sim.time, bonds_.id_i[b], bonds_.id_j[b], at, s.dissipated, cause});
  gone_[b] = 1;
}

void BondsModule::apply(Simulation& sim) {
  ParticleStore& p = sim.particles;
  gone_.assign(bonds_.size(), 0);
  for (std::size_t b : bonds_.locate(p)) {
    const std::uint32_t k =
        bonds_.slot_i[b] != BondList::none ? bonds_.slot_i[b] : bonds_.slot_j[b];
    fail(sim, b, FailureCause::particle_removed, k != BondList::none ? p.x[k] : Vec3{});
  }
  // First the bonds' laws, each bond on its own (in parallel threads for many bonds), then their
  // forces onto the particles in bond order, so that sums and results do not depend on threads.
  const std::size_t nb = bonds_.size();
  loads_.resize(nb);
  points_.resize(nb);
  released_.resize(nb);
  const double dt = sim.dt;
  const auto n_bonds = static_cast<std::int64_t>(nb);
#pragma omp parallel for schedule(static) if (nb >= kParallelMin)
  for (std::int64_t bi = 0; bi < n_bonds; ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    if (gone_[b]) continue;
    const std::uint32_t i = bonds_.slot_i[b], j = bonds_.slot_j[b];
    BondState& s = bonds_.state[b];
    const Vec3 d = p.x[j] - p.x[i];
    BondMotion m;
    m.length = norm(d);
    m.normal = m.length > 0 ? d / m.length : s.normal;
    // the contact point: the middle of the gap (or overlap) between the two surfaces
    const Vec3 xc =
        p.x[i] + (p.radius[i] + 0.5 * (m.length - p.radius[i] - p.radius[j])) * m.normal;
    // velocities are at the half step, so v dt is this step's displacement
    const Vec3 vc = p.v[j] + cross(p.w[j], xc - p.x[j]) - p.v[i] - cross(p.w[i], xc - p.x[i]);
    m.slip_increment = (vc - dot(vc, m.normal) * m.normal) * dt;
    m.rotation_increment = (p.w[j] - p.w[i]) * dt;
    const double before = s.dissipated;
    loads_[b] = law_->update(s, m);
    points_[b] = xc;
    released_[b] = s.dissipated - before;
  }
  double elastic = 0;
  // a statistics module measuring this step's Love–Weber stress counts the bonds' forces too: a
  // bond transmits force between its particles like a contact, at its contact point
  ContactStress* stress = sim.contacts().stress();
  if (stress && !stress->armed()) stress = nullptr;
  for (std::size_t b = 0; b < nb; ++b) {
    if (gone_[b]) continue;
    const std::uint32_t i = bonds_.slot_i[b], j = bonds_.slot_j[b];
    const BondState& s = bonds_.state[b];
    const BondLoad& load = loads_[b];
    const Vec3& xc = points_[b];
    sim.ledger.bond_dissipated += released_[b];
    if (s.failed != FailureMode::none) {
      fail(sim, b, s.failed == FailureMode::tensile ? FailureCause::tensile : FailureCause::shear,
           xc);
      continue;
    }
    p.f[j] += load.force;
    p.f[i] -= load.force;
    p.t[j] += cross(xc - p.x[j], load.force) + load.moment;
    p.t[i] -= cross(xc - p.x[i], load.force) + load.moment;
    if (stress) {  // the moment load.moment is a couple: no part in the symmetric stress
      stress->add(j, load.force, xc - p.x[j]);
      stress->add(i, -load.force, xc - p.x[i]);
    }
    elastic += s.strain_energy;
  }
  sim.ledger.bond_elastic = elastic;
  if (std::find(gone_.begin(), gone_.end(), std::uint8_t{1}) != gone_.end()) bonds_.remove(gone_);
}

void BondsModule::save(Archive& a) const {
  bonds_.save(a, "bonds/list/");
  a.put_value("bonds/rng", rng_.state());
  a.put_value("bonds/created", static_cast<std::uint8_t>(created_));
  a.put("bonds/failures", failures_);
  a.put("bonds/samples", samples_);
  a.put("bonds/damage_rows", damage_rows_);
}

void BondsModule::load(const Archive& a) {
  bonds_.load(a, "bonds/list/");
  rng_.set_state(a.get_value<Rng::State>("bonds/rng"));
  created_ = a.get_value<std::uint8_t>("bonds/created") != 0;
  failures_ = a.get<BondFailure>("bonds/failures");
  samples_ = a.get<BondSample>("bonds/samples");
  damage_rows_ = a.get<BondDamageRow>("bonds/damage_rows");
}

void BondsModule::sample(const Simulation& sim) {
  BondSample r;
  r.time = sim.time;
  r.intact = bonds_.size();
  for (const BondFailure& f : failures_) {
    if (f.cause == FailureCause::tensile) ++r.tensile;
    if (f.cause == FailureCause::shear) ++r.shear;
    if (f.cause == FailureCause::particle_removed) ++r.removed;
  }
  for (const BondState& s : bonds_.state) {
    r.mean_damage += s.damage;
    r.max_damage = std::max(r.max_damage, s.damage);
  }
  if (!bonds_.state.empty()) r.mean_damage /= static_cast<double>(bonds_.size());
  r.elastic = sim.ledger.bond_elastic;
  r.dissipated = sim.ledger.bond_dissipated;
  samples_.push_back(r);
  for (std::size_t b = 0; b < bonds_.size(); ++b)
    if (bonds_.state[b].damage > 0)
      damage_rows_.push_back({sim.time, bonds_.id_i[b], bonds_.id_j[b], bonds_.state[b].damage});
}

std::vector<Table> BondsModule::tables(const Simulation&) const {
  Table summary("bonds", {{"time", "s"},
                          {"bonds", "-"},
                          {"failed_tensile", "-"},
                          {"failed_shear", "-"},
                          {"removed_with_particle", "-"},
                          {"mean_damage", "-"},
                          {"max_damage", "-"},
                          {"elastic_bonds", "J"},
                          {"dissipated_bonds", "J"}});
  for (const BondSample& r : samples_)
    summary.add_row({r.time, r.intact, r.tensile, r.shear, r.removed, r.mean_damage, r.max_damage,
                     r.elastic, r.dissipated});
  Table failures("bond_failures", {{"time", "s"},
                                   {"particle_i", "-"},
                                   {"particle_j", "-"},
                                   {"x", "m"},
                                   {"y", "m"},
                                   {"z", "m"},
                                   {"mode", "-"},
                                   {"energy", "J"}});
  for (const BondFailure& f : failures_)
    failures.add_row({f.time, f.id_i, f.id_j, f.position.x, f.position.y, f.position.z,
                      cause_name(f.cause), f.energy});
  Table damage("bond_damage",
               {{"time", "s"}, {"particle_i", "-"}, {"particle_j", "-"}, {"damage", "-"}});
  for (const BondDamageRow& r : damage_rows_) damage.add_row({r.time, r.id_i, r.id_j, r.damage});
  return {summary, failures, damage};
}

}  // namespace comminute::bonds
