#include "comminute/breakage/stressing_events.hpp"

#include <algorithm>

#include "comminute/breakage/parallel_filter.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/fracture/energy_share.hpp"

namespace comminute::breakage {

namespace {
constexpr std::size_t kAhead = 16;  // contacts between a particle's prefetch and its use

// Normal relative kinetic energy (J) of a contact still approaching: (1/2) mu u^2 with u the
// approach speed along `normal` (from the other body to this one; any length) of the relative
// velocity `dv` (this body's minus the other's), 0 when separating.
double approach_energy(const Vec3& normal, const Vec3& dv, double reduced_mass) {
  const double n2 = norm2(normal);
  if (!(n2 > 0)) return 0.0;
  const double u = -dot(dv, normal) / std::sqrt(n2);
  return u > 0 ? 0.5 * reduced_mass * u * u : 0.0;
}
}  // namespace

void StressingEvents::register_fields(ParticleStore& p) {
  f_in_event_ = p.add_field("breakage.in_event", 0.0);
  f_energy_ = p.add_field("breakage.event_energy", 0.0);  // J/kg
  f_force_ = p.add_field("breakage.event_force", 0.0);    // N
  f_baseline_ = p.add_field("breakage.baseline", 0.0);    // J/kg
  f_quiet_ = p.add_field("breakage.quiet_steps", 0.0);
  f_stressing_ = p.add_field("breakage.stressing_energy", 0.0);  // J/kg
}

void StressingEvents::configure(const Simulation& sim) {
  n_materials_ = sim.materials.size();
  share_.assign(n_materials_ * n_materials_, 0.5);
  for (std::size_t a = 0; a < n_materials_; ++a)
    for (std::size_t b = 0; b < n_materials_; ++b) {
      const Material& ma = sim.materials.material(static_cast<std::uint16_t>(a));
      const Material& mb = sim.materials.material(static_cast<std::uint16_t>(b));
      share_[a * n_materials_ + b] = fracture::energy_share(
          fracture::plane_strain_modulus(ma.youngs_modulus, ma.poisson_ratio),
          fracture::plane_strain_modulus(mb.youngs_modulus, mb.poisson_ratio));
    }
}

void StressingEvents::clear(ParticleStore& p, std::size_t s) const {
  p.field(f_in_event_)[s] = p.field(f_energy_)[s] = p.field(f_force_)[s] = 0;
  p.field(f_baseline_)[s] = p.field(f_quiet_)[s] = p.field(f_stressing_)[s] = 0;
}

void StressingEvents::gather_loads(const Simulation& sim) {
  const auto& p = sim.particles;
  const std::size_t n = p.size();
  make_resident(contact_load_, n);  // (it grows with the fragments: core/memory.hpp)
  contact_load_.resize(n);          // reset by the scatter below, each thread its own slots
  const auto& nl = sim.pairs();
  const ContactStateStore& pairs = sim.pair_state();
  const LoadingRecord& loading = *sim.contacts().loading();
  // the pairs in contact (in a bed of fragments a minority of the list, in no predictable order)
  std::vector<std::uint32_t>& touching = touching_;
  parallel_select(
      nl.size(), [&](std::size_t k) { return pairs.active[k] != 0; }, touching, select_parts_);
  const auto combine = [](ContactLoad x, const ContactLoad& y) {
    return ContactLoad{x.work + y.work, x.force + y.force, std::max(x.largest, y.largest),
                       x.approach + y.approach};
  };
  owner_scatter(
      touching.size(), [&](std::size_t m) { return nl.first[touching[m]]; }, contact_load_,
      ContactLoad{},
      [&](std::size_t m, auto& add) {
        // the second particles are scattered in memory: asked for kAhead contacts before use
        const std::uint32_t ja = nl.second[touching[std::min(m + kAhead, touching.size() - 1)]];
        __builtin_prefetch(&p.x[ja]);
        __builtin_prefetch(&p.v[ja]);
        __builtin_prefetch(&p.mass[ja]);
        __builtin_prefetch(&p.material[ja]);
        const std::uint32_t k = touching[m];
        const std::uint32_t i = nl.first[k], j = nl.second[k];
        const StateRef h = pairs.at(k);
        const std::size_t a = p.material[i], b = p.material[j];
        const double ab = share_[a * n_materials_ + b], ba = share_[b * n_materials_ + a];
        const double work = loading.loading_work(h);
        const double ke = approach_energy(p.x[i] - p.x[j], p.v[i] - p.v[j],
                                          p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]));
        const double f = loading.normal_force(h);
        add(i, ContactLoad{ab * work, f, f, ab * ke});
        add(j, ContactLoad{ba * work, f, f, ba * ke});
      },
      combine, load_queues_);
  // a ghost's contacts load its owner (periodic boundaries)
  for (std::size_t s = p.owned(); s < n; ++s) {
    ContactLoad& o = contact_load_[p.owner_of(s)];
    o.work += contact_load_[s].work;
    o.force += contact_load_[s].force;
    o.largest = std::max(o.largest, contact_load_[s].largest);
    o.approach += contact_load_[s].approach;
  }
  // the wall contacts, grouped by particle: each thread takes a range that starts and ends at a
  // particle's boundary, so every particle's loads are added by one thread in list order (the
  // serial loop's sums, bit for bit)
  const std::vector<WallContactRecord>& wc = sim.wall_contacts();
  const std::size_t nw = wc.size();
  const int nt = nw >= kParallelMin / 2 ? max_threads() : 1;
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    const auto nts = static_cast<std::size_t>(nt);
    auto boundary = [&](std::size_t u) {  // the first contact of a particle at or after u nw/nt
      std::size_t b = nw * u / nts;
      while (b > 0 && b < nw && wc[b].particle == wc[b - 1].particle) ++b;
      return b;
    };
    const std::size_t q0 = boundary(t), q1 = boundary(t + 1);
    std::vector<WallContact> found;
    for (std::size_t q = q0; q < q1; ++q) {
      const WallContactRecord& c = wc[q];
      const std::size_t a = p.material[c.particle], b = sim.walls[c.wall]->material;
      const StateRef h = sim.wall_state().at(c.candidate);
      const double e = share_[a * n_materials_ + b];
      ContactLoad& load = contact_load_[c.particle];
      load.work += e * loading.loading_work(h);
      const Wall& w = *sim.walls[c.wall];
      found.clear();
      w.contacts(p.x[c.particle], p.radius[c.particle], 0.0, found);
      for (const auto& fc : found)
        if (fc.feature == c.feature)
          load.approach +=
              e * approach_energy(fc.normal, p.v[c.particle] - w.kinematics.velocity_at(fc.point),
                                  p.mass[c.particle]);
      const double f = loading.normal_force(h);
      load.force += f;
      load.largest = std::max(load.largest, f);
    }
  }
}

void StressingEvents::assess(Simulation& sim, const BreakageMaterials& materials,
                             const BreakageFields& f, EventLog& log, const BrokeFn& on_break) {
  auto& p = sim.particles;
  const std::size_t n = p.owned();  // ghosts are assessed through their owners
  // Each particle's event reads and writes only that particle's fields (the criteria's included),
  // so the particles are shared out in blocks of slots; what reaches the log and the replacement
  // queue is collected per block and handed on in block order, i.e. in slot order as a serial
  // loop would: the result does not depend on the thread count. The blocks are handed out as the
  // threads come free: the breakable particles (unbroken parents, at the low slots) cost far more
  // than the fragments appended after them, so equal halves of the slots are not equal work.
  constexpr std::size_t kBlock = 2048;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const int nt = n >= kParallelMin ? max_threads() : 1;
  std::vector<AssessOutcome>& outcome = outcome_;
  outcome.resize(blocks);
  const auto nb = static_cast<std::ptrdiff_t>(blocks);
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
  for (std::ptrdiff_t b = 0; b < nb; ++b) {
    const auto i0 = static_cast<std::size_t>(b) * kBlock;
    AssessOutcome& o = outcome[static_cast<std::size_t>(b)];
    o.clear();
    assess_range(sim, materials, f, i0, std::min(n, i0 + kBlock), o);
  }
  for (const AssessOutcome& o : outcome) {
    for (std::uint64_t e = 0; e < o.ended; ++e) log.count_event();
    for (const EventRecord& r : o.logged) log.add(r);
    for (std::size_t b = 0; b < o.broken_slots.size(); ++b)
      on_break(o.broken_slots[b], o.broken_records[b]);
  }
}

void StressingEvents::assess_range(Simulation& sim, const BreakageMaterials& materials,
                                   const BreakageFields& f, std::size_t i0, std::size_t i1,
                                   AssessOutcome& out) const {
  auto& p = sim.particles;
  auto& in_event = p.field(f_in_event_);
  auto& energy = p.field(f_energy_);
  auto& force = p.field(f_force_);
  auto& baseline = p.field(f_baseline_);
  auto& quiet = p.field(f_quiet_);
  auto& stressing = p.field(f_stressing_);
  const auto& target = p.field(f.target);
  for (std::size_t i = i0; i < i1; ++i) {
    // no loaded contact, no event and a zero baseline (most fragments in flight): every branch
    // below would leave the particle as it is, so it is passed over reading three arrays
    if (contact_load_[i].work == 0 && in_event[i] == 0 && baseline[i] == 0) continue;
    const auto& mat = materials[p.material[i]];
    if (!mat || (p.flags[i] & (pflag::fixed | pflag::unbreakable | pflag::remove))) continue;
    // A growing fragment already carries its full mass and transmits real contact forces: it is
    // assessed at its final size (the overlaps growth creates are capped, see
    // FragmentGrowth::grow).
    const double d = 2 * std::max(p.radius[i], target[i]);
    const double s = contact_load_[i].work / p.mass[i];  // J/kg
    if (d < mat->min_breakable_size || p.field(f.generation)[i] >= max_generations_) {
      baseline[i] = s;
      continue;
    }
    const BreakageCriterion& crit = *mat->criterion;
    auto record = [&] {  // the event as it stands, for the log
      EventRecord r;
      r.time = sim.time;
      r.parent_id = p.id[i];
      r.material = p.material[i];
      r.generation = static_cast<std::uint32_t>(p.field(f.generation)[i]);
      r.diameter = d;
      r.mass = p.physical_mass(i);
      r.specific_energy = energy[i];
      r.stressing_energy = std::max(stressing[i], energy[i]);
      r.peak_force = force[i];
      r.strength = crit.strength(p, i, d);
      r.damage_before = crit.damage(p, i);
      return r;
    };
    auto end_event = [&](bool broke) {
      ++out.ended;
      if (log_all_ && !broke) out.logged.push_back(record());
      if (!broke) crit.survive(p, i, d, {energy[i], force[i]});
      in_event[i] = 0;
      energy[i] = force[i] = stressing[i] = 0;
      quiet[i] = 0;
    };
    if (s <= 0) {  // no loaded contact: any event is over
      if (in_event[i] != 0) end_event(false);
      baseline[i] = 0;
      continue;
    }
    if (in_event[i] == 0) {
      if (s <= baseline[i] * (1 + 1e-12)) {
        baseline[i] = s;  // contacts left or unloading: lower the baseline with S
        continue;
      }
      in_event[i] = 1;
      energy[i] = force[i] = stressing[i] = 0;
      quiet[i] = 0;
    }
    const double e = s - baseline[i];
    if (e > energy[i]) {
      energy[i] = e;
      quiet[i] = 0;
    } else {
      quiet[i] += 1;
    }
    stressing[i] = std::max(stressing[i], e + contact_load_[i].approach / p.mass[i]);
    force[i] = std::max(force[i], contact_load_[i].of(mat->force_measure));
    const StressingEvent ev{energy[i], force[i]};
    if (crit.breaks(p, i, d, ev)) {
      EventRecord r = record();
      r.broken = 1;
      out.broken_slots.push_back(i);
      out.broken_records.push_back(r);
      end_event(true);
      p.flags[i] |= pflag::unbreakable;  // until it is replaced at the end of the step
    } else if (quiet[i] >= end_steps_) {
      end_event(false);
      baseline[i] = s;
    }
  }
}

}  // namespace comminute::breakage
