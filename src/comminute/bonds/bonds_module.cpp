#include "comminute/bonds/bonds_module.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "comminute/bonds/bond_step.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
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
  indexed_ = false;
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
  BondState s = bonds_.state.get(b);
  if (cause == FailureCause::particle_removed) {  // what the bond held is lost with it
    sim.ledger.bond_dissipated += s.strain_energy;
    s.dissipated += s.strain_energy;
    s.strain_energy = 0;
    bonds_.state.set(b, s);
  }
  failures_.push_back({sim.time, bonds_.id_i[b], bonds_.id_j[b], at, s.dissipated, cause});
  gone_[b] = 1;
}

namespace {
// Bonds per range of the step's loop: the ranges and their sums do not depend on the thread
// count, so neither do the ledger's sums.
constexpr std::size_t kRange = 2048;
}  // namespace

std::size_t BondsModule::scratch_bytes() const {
  return gone_.capacity() +
         sizeof(Vec3) * (force_.capacity() + torque_i_.capacity() + torque_j_.capacity()) +
         sizeof(BondStepSums) * range_sums_.capacity() +
         sizeof(std::uint32_t) * (first_.capacity() + entry_.capacity()) +
         sizeof(std::uint64_t) * ids_at_index_.capacity() + defer_.capacity() +
         sizeof(std::uint32_t) * deferred_.capacity();
}

void BondsModule::index_by_particle(std::size_t n) {
  const std::size_t nb = bonds_.size();
  first_.assign(n + 1, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    ++first_[bonds_.slot_i[b] + 1];
    ++first_[bonds_.slot_j[b] + 1];
  }
  for (std::size_t k = 0; k < n; ++k) first_[k + 1] += first_[k];
  entry_.resize(2 * nb);
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t b = 0; b < nb; ++b) {
    const auto e = static_cast<std::uint32_t>(b << 1);
    entry_[next[bonds_.slot_i[b]]++] = e;
    entry_[next[bonds_.slot_j[b]]++] = e | 1u;
  }
  indexed_ = true;
  blocks_ = 0;  // the waiting ends are marked again (mark_deferred)
}

std::pair<std::size_t, std::size_t> BondsModule::block_ranges(std::size_t k, std::size_t blocks,
                                                              std::size_t ranges) {
  return {k * ranges / blocks, (k + 1) * ranges / blocks};
}

void BondsModule::mark_deferred(std::size_t blocks, std::size_t ranges) {
  const std::size_t nb = bonds_.size();
  constexpr std::uint32_t unowned = 0xFFFFFFFFu;
  std::vector<std::uint32_t> first_block(first_.empty() ? 0 : first_.size() - 1, unowned);
  defer_.assign(nb, 0);
  deferred_.clear();
  for (std::size_t k = 0; k < blocks; ++k) {
    const auto [r0, r1] = block_ranges(k, blocks, ranges);
    const auto blk = static_cast<std::uint32_t>(k);
    for (std::size_t b = r0 * kRange; b < std::min(r1 * kRange, nb); ++b) {
      std::uint8_t wait = 0;
      for (const std::uint32_t slot : {bonds_.slot_i[b], bonds_.slot_j[b]}) {
        if (first_block[slot] == unowned) first_block[slot] = blk;
        wait = static_cast<std::uint8_t>(wait >> 1 | (first_block[slot] != blk ? 2u : 0u));
      }
      defer_[b] = wait;
      if (wait) deferred_.push_back(static_cast<std::uint32_t>(b));
    }
  }
  blocks_ = blocks;
}

void BondsModule::add_to_particles(ParticleStore& p) const {
  const auto n = static_cast<std::int64_t>(first_.size() - 1);
#pragma omp parallel for schedule(static) if (bonds_.size() >= kParallelMin)
  for (std::int64_t ki = 0; ki < n; ++ki) {
    const auto k = static_cast<std::size_t>(ki);
    const std::uint32_t end = first_[k + 1];
    if (first_[k] == end) continue;
    Vec3 f = p.f[k], t = p.t[k];
    for (std::uint32_t e = first_[k]; e < end; ++e) {
      const std::uint32_t b = entry_[e] >> 1;
      if (entry_[e] & 1u) {
        f += force_[b];
        t += torque_j_[b];
      } else {
        f -= force_[b];
        t -= torque_i_[b];
      }
    }
    p.f[k] = f;
    p.t[k] = t;
  }
}

void BondsModule::apply(Simulation& sim) {
  ParticleStore& p = sim.particles;
  const std::size_t nb = bonds_.size();
  gone_.assign(nb, 0);
  // the slots were resolved against ids_at_index_: while the store holds the same ids in the
  // same slots, every bond's cached slots still hold its particles (no per-bond check)
  const bool unmoved = indexed_ && first_.size() == p.owned() + 1 &&
                       ids_at_index_.size() == p.owned() &&
                       std::equal(ids_at_index_.begin(), ids_at_index_.end(), p.id.begin());
  if (!unmoved) {
    for (std::size_t b : bonds_.locate(p)) {
      const std::uint32_t k =
          bonds_.slot_i[b] != BondList::none ? bonds_.slot_i[b] : bonds_.slot_j[b];
      fail(sim, b, FailureCause::particle_removed, k != BondList::none ? p.x[k] : Vec3{});
    }
    if (std::find(gone_.begin(), gone_.end(), std::uint8_t{1}) != gone_.end()) {
      bonds_.remove(gone_);  // their particles are gone: no slots to act on
      gone_.assign(bonds_.size(), 0);
    }
    index_by_particle(p.owned());
    ids_at_index_.assign(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(p.owned()));
  }
  // The bond laws run range by range, in blocks of consecutive ranges, one block per thread; the
  // loads reach each particle in bond order, so sums and results do not depend on the thread
  // count. The laws hand the loads straight to the particles: a particle loaded by bonds of
  // several blocks receives them directly only from the first of those blocks, and from the later
  // ones after the threads join, in bond order (mark_deferred). Only a stress measurement, which
  // reads each bond's force, takes all loads through the per-bond arrays (add_to_particles).
  const std::size_t n_bonds = bonds_.size();
  ContactStress* stress = sim.contacts().stress();
  const bool measured = stress && stress->armed();
  const bool serial = n_bonds < kParallelMin || max_threads() == 1;
  const bool direct = !measured;
  const std::size_t ranges = (n_bonds + kRange - 1) / kRange;
  const std::size_t blocks =
      serial ? 1 : std::max<std::size_t>(1, std::min<std::size_t>(max_threads(), ranges));
  if (direct && blocks_ != blocks) mark_deferred(blocks, ranges);
  // per-bond loads: for every bond when measured, else for the waiting bonds only
  const std::size_t n_loads = !direct ? n_bonds : blocks > 1 ? deferred_.size() : 0;
  for (std::vector<Vec3>* a : {&force_, &torque_i_, &torque_j_}) {
    a->resize(n_loads);
    if (n_loads == 0) a->shrink_to_fit();  // not used: freed
  }
  range_sums_.assign(ranges, {});
  BondStep st;
  st.x = p.x.data();
  st.v = p.v.data();
  st.w = p.w.data();
  st.radius = p.radius.data();
  st.slot_i = bonds_.slot_i.data();
  st.slot_j = bonds_.slot_j.data();
  st.state = &bonds_.state;
  st.flag = gone_.data();
  st.dt = sim.dt;
  st.force = force_.data();
  st.torque_i = torque_i_.data();
  st.torque_j = torque_j_.data();
  if (direct) {
    st.particle_force = p.f.data();
    st.particle_torque = p.t.data();
    if (blocks > 1) {
      st.defer = defer_.data();
      st.deferred = deferred_.data();
      st.n_deferred = deferred_.size();
    }
  }
  const BondLaw& law = *law_;
  const auto n_blocks = static_cast<std::int64_t>(blocks);
#pragma omp parallel for schedule(static) if (!serial)
  for (std::int64_t k = 0; k < n_blocks; ++k) {
    const auto [r0, r1] = block_ranges(static_cast<std::size_t>(k), blocks, ranges);
    for (std::size_t r = r0; r < r1; ++r) {
      const std::size_t begin = r * kRange;
      range_sums_[r] = law.update_range(st, begin, std::min(begin + kRange, n_bonds));
    }
  }
  if (!direct) add_to_particles(p);
  if (direct && blocks > 1) {  // the waiting loads, in bond order
    for (std::size_t k = 0; k < deferred_.size(); ++k) {
      const std::uint32_t b = deferred_[k];
      if (gone_[b] == 1) continue;  // its particle is gone: it carries nothing
      const std::uint32_t i = bonds_.slot_i[b], j = bonds_.slot_j[b];
      if (defer_[b] & 1u) {
        p.f[i] -= force_[k];
        p.t[i] -= torque_i_[k];
      }
      if (defer_[b] & 2u) {
        p.f[j] += force_[k];
        p.t[j] += torque_j_[k];
      }
    }
  }
  double elastic = 0;
  std::size_t failed = 0;
  for (const BondStepSums& r : range_sums_) {
    sim.ledger.bond_dissipated += r.released;
    elastic += r.elastic;
    failed += r.failed;
  }
  sim.ledger.bond_elastic = elastic;
  // a statistics module measuring this step's Love–Weber stress counts the bonds' forces too: a
  // bond transmits force between its particles like a contact, at its contact point
  if (measured) {
    for (std::size_t b = 0; b < n_bonds; ++b) {
      if (gone_[b]) continue;
      const std::uint32_t i = bonds_.slot_i[b], j = bonds_.slot_j[b];
      const Vec3 xc = bond_point(st, b);
      // the moment of the bond is a couple: no part in the symmetric stress
      stress->add(j, force_[b], xc - p.x[j]);
      stress->add(i, -force_[b], xc - p.x[i]);
    }
  }
  if (failed == 0) return;
  for (std::size_t b = 0; b < n_bonds; ++b) {
    if (gone_[b] != 2) continue;
    const FailureMode mode = bonds_.state.failed[b];
    fail(sim, b, mode == FailureMode::tensile ? FailureCause::tensile : FailureCause::shear,
         bond_point(st, b));
  }
  bonds_.remove(gone_);
  index_by_particle(p.owned());
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
  indexed_ = false;
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
  for (const BondRest& s : bonds_.state.rest) {
    r.mean_damage += s.damage;
    r.max_damage = std::max(r.max_damage, s.damage);
  }
  if (!bonds_.state.empty()) r.mean_damage /= static_cast<double>(bonds_.size());
  r.elastic = sim.ledger.bond_elastic;
  r.dissipated = sim.ledger.bond_dissipated;
  samples_.push_back(r);
  for (std::size_t b = 0; b < bonds_.size(); ++b)
    if (bonds_.state.rest[b].damage > 0)
      damage_rows_.push_back(
          {sim.time, bonds_.id_i[b], bonds_.id_j[b], bonds_.state.rest[b].damage});
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
