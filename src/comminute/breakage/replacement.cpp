#include "comminute/breakage/replacement.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <unordered_set>

#include "comminute/breakage/breakage_ledger.hpp"
#include "comminute/breakage/contact_at_rest.hpp"
#include "comminute/breakage/fragment_growth.hpp"
#include "comminute/breakage/parallel_filter.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/core/units.hpp"
#include "comminute/fracture/rayleigh_time.hpp"

namespace comminute::breakage {

namespace {
// Density scaling: s = (t_floor / t_R(d))^2 when the fragment's Rayleigh time t_R is below the
// floor, else 1, so that its t_R with density s rho equals the floor (t_R ~ sqrt(rho);
// docs/models.md "Time step").
double mass_scale(const Simulation& sim, const Replacement::Context& ctx, double d,
                  std::uint16_t material) {
  if (!(ctx.rayleigh_floor > 0) || ctx.floor_rule != FloorRule::density_scaling) return 1.0;
  const Material& m = sim.materials.material(material);
  const double t = fracture::rayleigh_time(d, m.density, m.shear_modulus(), m.poisson_ratio);
  return t < ctx.rayleigh_floor ? (ctx.rayleigh_floor / t) * (ctx.rayleigh_floor / t) : 1.0;
}

// The smallest fragment the floor lets a material keep (FloorRule::fines): t_R is proportional to
// the diameter (docs/models.md eq. R1), so d_f = t_floor / t_R(1 m). 0 when there is no floor.
double floor_size(const Simulation& sim, const Replacement::Context& ctx, std::uint16_t material) {
  if (!(ctx.rayleigh_floor > 0) || ctx.floor_rule != FloorRule::fines) return 0.0;
  const Material& m = sim.materials.material(material);
  return ctx.rayleigh_floor /
         fracture::rayleigh_time(1.0, m.density, m.shear_modulus(), m.poisson_ratio);
}
}  // namespace

void Replacement::end_of_step(Simulation& sim, const Context& ctx) {
  const bool due = interval_ <= 1 || sim.step_count % static_cast<std::uint64_t>(interval_) == 0;
  if (!broken_ids_.empty() && due) {
    auto& p = sim.particles;
    // Slots of the parents and the spheres around them (other parents included).
    std::unordered_map<std::uint64_t, std::size_t> slot_of;
    const std::unordered_set<std::uint64_t> wanted(broken_ids_.begin(), broken_ids_.end());
    // 0, or (once the outcomes below are laid out) 1 + the parent's outcome
    std::vector<std::uint32_t>& batch = batch_;
    make_resident(batch, p.size());  // (core/memory.hpp)
    batch.assign(p.size(), 0);
    // (the scans of the store and of the pair list run on all threads; their hits come back in
    // slot and pair order, so what follows is the same as after serial scans)
    for (const std::uint32_t i : parallel_filter(p.size(), [&](std::size_t s) {
           return (p.flags[s] & pflag::unbreakable) && wanted.count(p.id[s]) > 0;
         })) {
      slot_of[p.id[i]] = i;
      batch[i] = 1;
    }
    std::unordered_map<std::size_t, std::vector<Neighbour>> around;
    const auto& nl = sim.pairs();
    // 1 for a parent's slot of the list; a slot of the list may be a periodic ghost (no longer in
    // the store): its owner stands in. The scan of the list then reads one byte per slot.
    std::vector<std::uint8_t>& parent_slot = parent_slot_;
    make_resident(parent_slot, p.owned() + sim.ghost_count());
    parent_slot.resize(p.owned() + sim.ghost_count());
    const auto n_slots = static_cast<std::ptrdiff_t>(parent_slot.size());
    const bool threaded = parent_slot.size() >= kParallelMin;
#pragma omp parallel for schedule(static) if (threaded)
    for (std::ptrdiff_t s = 0; s < n_slots; ++s) {
      const auto u = static_cast<std::size_t>(s);
      parent_slot[u] = batch[u < p.owned() ? u : sim.slot_owner(u)] != 0 ? 1 : 0;
    }
    const std::vector<std::uint32_t>& hits = sim.pairs_flagged(parent_slot);
    // elastic energy that leaves with the parents' contacts: worked out on all threads, booked
    // in pair order
    std::vector<std::optional<double>> leaving(hits.size());
    const auto n_hits = static_cast<std::ptrdiff_t>(hits.size());
#pragma omp parallel for schedule(static) if (n_hits >= 256)
    for (std::ptrdiff_t h = 0; h < n_hits; ++h) {
      const std::uint32_t k = hits[static_cast<std::size_t>(h)];
      if (!sim.pair_state().active[k]) continue;
      const std::uint32_t si = nl.first[k], sj = nl.second[k];
      const std::size_t i = sim.slot_owner(si), j = sim.slot_owner(sj);
      const Vec3 dx = sim.slot_position(si) - sim.slot_position(sj);
      const double dist = norm(dx);
      const double ov = p.radius[i] + p.radius[j] - dist;
      if (ov > 0 && dist > 0)
        leaving[static_cast<std::size_t>(h)] =
            contact_at_rest(sim, ov, p.radius[i], p.mass[i], p.material[i], p.radius[j], p.mass[j],
                            p.material[j], dx / dist, ContactScratch(sim.pair_state(), k))
                .stored_energy;
    }
    for (std::size_t h = 0; h < hits.size(); ++h) {
      const std::uint32_t si = nl.first[hits[h]], sj = nl.second[hits[h]];
      const auto i = static_cast<std::uint32_t>(sim.slot_owner(si)),
                 j = static_cast<std::uint32_t>(sim.slot_owner(sj));
      if (batch[i] != 0) around[i].push_back({j, si, sj});
      if (batch[j] != 0) around[j].push_back({i, sj, si});
      if (leaving[h]) ctx.ledger.remove(sim, *leaving[h]);
    }
    std::vector<WallContact> found;
    for (const auto& c : sim.wall_contacts()) {
      if (batch[c.particle] == 0) continue;
      found.clear();
      sim.walls[c.wall]->contacts(p.x[c.particle], p.radius[c.particle], 0.0, found);
      for (const auto& f : found)
        if (f.feature == c.feature && f.overlap > 0) {
          const std::uint32_t i = c.particle;
          const double u = contact_at_rest(sim, f.overlap, p.radius[i], p.mass[i], p.material[i], 0,
                                           0, sim.walls[c.wall]->material, f.normal,
                                           ContactScratch(sim.wall_state(), c.candidate))
                               .stored_energy;
          ctx.ledger.remove(sim, u);
        }
    }
    // The parents in the order they broke; each worked out on its own (all threads), their
    // fragments given slots and ids in that order and written (all threads), their books kept in
    // that order (serial).
    std::vector<Outcome> outcomes;
    outcomes.reserve(broken_ids_.size());
    for (std::size_t b = 0; b < broken_ids_.size(); ++b) {
      const auto found_parent = slot_of.find(broken_ids_[b]);
      if (found_parent == slot_of.end()) continue;  // left through an outlet while it waited
      Outcome& o = outcomes.emplace_back();
      o.parent = found_parent->second;
      o.around = &around[o.parent];
      o.rec = broken_records_[b];
      batch[o.parent] = static_cast<std::uint32_t>(outcomes.size());
    }
    parallel_for_each(outcomes.size(), [&](std::size_t q) { draw(sim, ctx, outcomes[q]); });
    if (ctx.mass_rule)  // (the rule books its split per parent: serial)
      for (Outcome& o : outcomes) ctx.mass_rule->share(p, o.parent, o.radii, o.masses);
    parallel_for_each(outcomes.size(), [&](std::size_t q) { place(sim, ctx, outcomes[q]); });
    // Fragments into their parents' slots, so that nothing in the store, the pair list or the
    // contact state moves; when a parent left no fragment (all fines), its slot must go: then
    // the parents are removed and every fragment appended.
    const bool in_slot = std::all_of(outcomes.begin(), outcomes.end(),
                                     [](const Outcome& o) { return !o.placed.empty(); });
    // slots and ids as appending parent by parent would give them; the store is then written on
    // all threads, parent by parent, and the books kept in parent order
    std::size_t slot = p.size(), ids = 0;
    for (Outcome& o : outcomes) {
      if (p.flags[o.parent] & pflag::growing) ctx.growth.dropped();
      o.first_slot = slot;
      o.first_id = ids;
      slot += o.placed.size() - (in_slot ? 1 : 0);
      ids += o.placed.size();
    }
    p.extend(slot - p.size());
    const std::uint64_t first_id = p.take_ids(ids);
    // (each thread a contiguous run of parents: the fragments of neighbouring parents share cache
    // lines of the store, which threads taking parents in turn would hand back and forth)
    const auto n_outcomes = static_cast<std::ptrdiff_t>(outcomes.size());
#pragma omp parallel for schedule(static) if (n_outcomes >= 64)
    for (std::ptrdiff_t q = 0; q < n_outcomes; ++q) {
      Outcome& o = outcomes[static_cast<std::size_t>(q)];
      o.first_id += first_id;
      write(sim, ctx, o, in_slot);
    }
    ctx.log.make_room(outcomes.size(), ids);
    for (const Outcome& o : outcomes) book_fragments(sim, ctx, o);
    parallel_for_each(outcomes.size(), [&](std::size_t q) {
      Outcome& o = outcomes[q];
      for (const std::size_t s : o.slots) ctx.born(s, o.rng);
      o.created = created_energy(sim, outcomes, q, batch);
    });
    for (Outcome& o : outcomes) {
      ctx.ledger.create(sim, o.created);
      const Progeny& progeny = o.progeny;
      if (progeny.fines_mass > 0) {
        ctx.ledger.add_fines(p.material[o.parent], progeny.fines_mass, o.parent_v);
        ctx.ledger.remove(sim, o.fines_pe);
      }
      o.rec.fines_mass = progeny.fines_mass;
      ctx.ledger.remove(sim, o.ke_out - o.ke_in);
      ctx.log.add_breakage(o.rec);
    }
    if (!in_slot) p.compact();
    sim.particles_replaced(fragments_added_, renewed_);
    fragments_added_.clear();
    renewed_.clear();
    broken_ids_.clear();
    broken_records_.clear();
  }
}

void Replacement::draw(const Simulation& sim, const Context& ctx, Outcome& o) const {
  const auto& p = sim.particles;
  const std::size_t parent = o.parent;
  const MaterialBreakage& mat = *ctx.materials[p.material[parent]];
  // A fragment that breaks while still growing counts at its final size.
  o.r_parent = std::max(p.radius[parent], p.field(ctx.fields.target)[parent]);
  const double r_parent = o.r_parent;
  const double d = 2 * r_parent;
  const double mass = p.physical_mass(parent);  // kg; p.mass is the inertial mass (x mass scale)
  const double density = mass / units::sphere_volume(r_parent);
  // Progeny sizes (docs/models.md eq. P1-P4).
  // E50b: the median fracture energy of the particles that break at this stressing energy, or
  // the class median (progeny key e50b; docs/models.md eq. P1b)
  // E: the event's stressing energy, or the energy absorbed up to fracture (key sizing_energy)
  const double e =
      mat.sizing_energy == SizingEnergy::stressing ? o.rec.stressing_energy : o.rec.specific_energy;
  double e50b = mat.criterion->t10_median_energy(d, e, mat.progeny->e50b_rule());
  if (e50b <= 0) e50b = mat.reference_energy;
  o.rec.t10 = mat.progeny->t10(e, e50b);
  const ProgenyDistribution dist = mat.progeny->distribution(d, o.rec.t10);
  const double min_size = std::max({mat.min_fragment_size, mat.min_fragment_ratio * d,
                                    floor_size(sim, ctx, p.material[parent])});
  o.rng = Rng(sim.seed, rng_stream::breakage, p.id[parent]);
  o.progeny = draw_progeny(dist, mass, density, min_size, mat.fines, o.rng);
  for (const auto& f : o.progeny.fragments) {
    o.scales.push_back(mass_scale(sim, ctx, f.diameter, p.material[parent]));
    o.radii.push_back(0.5 * f.diameter);
    o.masses.push_back(f.mass);
  }
}

void Replacement::place(const Simulation& sim, const Context& ctx, Outcome& o) const {
  const auto& p = sim.particles;
  const std::size_t parent = o.parent;
  // Inertial masses: the physical ones times each fragment's density scale.
  for (std::size_t k = 0; k < o.radii.size(); ++k) {
    o.masses[k] *= o.scales[k];
    const double df = o.progeny.fragments[k].diameter;
    o.inertia.push_back(0.4 * o.masses[k] * 0.25 * df * df);
  }
  std::vector<Sphere> neighbours;
  for (const Neighbour& nb : *o.around)
    neighbours.push_back(
        {sim.pair_frame(nb.parent_seen, nb.seen, p.x[nb.slot]), p.radius[nb.slot]});
  WallOverlap walls = [&sim](const Vec3& x, double r) {
    double worst = -r;
    std::vector<WallContact> found;
    for (const auto& w : sim.walls) {
      found.clear();
      w->contacts(x, r, 0.0, found);
      for (const auto& c : found) worst = std::max(worst, c.overlap);
    }
    return worst;
  };
  Rng rng(sim.seed, rng_stream::placement, p.id[parent]);
  o.placed =
      placement_->place({p.x[parent], o.r_parent}, o.radii, o.masses, neighbours, walls, rng);
  std::vector<Vec3> xs;
  for (const auto& s : o.placed) xs.push_back(s.x);
  const MaterialBreakage& mat = *ctx.materials[p.material[parent]];
  const double inertial_mass = p.mass[parent];
  const double released = mat.release_fraction * o.rec.specific_energy * inertial_mass;
  o.vel = fragment_velocities(p.x[parent], p.v[parent], p.w[parent], p.inertia[parent],
                              inertial_mass, xs, o.masses, o.inertia, released, mat.fragment_spin);
  // Energy bookkeeping: kinetic energy of the parent out, of the fragments in.
  o.ke_out =
      0.5 * inertial_mass * norm2(p.v[parent]) + 0.5 * p.inertia[parent] * norm2(p.w[parent]);
  for (std::size_t k = 0; k < o.placed.size(); ++k)
    o.ke_in += 0.5 * o.masses[k] * norm2(o.vel.v[k]) + 0.5 * o.inertia[k] * norm2(o.vel.w[k]);
  o.parent_v = p.v[parent];
  o.fines_pe = -p.mass_scale(parent) * o.progeny.fines_mass * dot(sim.gravity, p.x[parent]);
}

void Replacement::write(Simulation& sim, const Context& ctx, Outcome& o, bool in_slot) const {
  auto& p = sim.particles;
  const std::size_t parent = o.parent;
  const std::uint16_t material = p.material[parent];
  const Vec3 parent_x = p.x[parent];
  o.parent_id = p.id[parent];
  o.generation = static_cast<std::uint32_t>(p.field(ctx.fields.generation)[parent]) + 1;
  std::vector<double> inherited(p.field_names().size());  // the parent's fields
  for (std::size_t q = 0; q < inherited.size(); ++q) inherited[q] = p.field(q)[parent];
  // the fragment that takes the parent's slot: the one with the most room inside the parent at
  // its final size, so that growing it is least likely to call for a neighbour-list rebuild
  o.own = o.placed.size();
  double room = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; in_slot && k < o.placed.size(); ++k) {
    const double r = o.r_parent - norm(o.placed[k].x - parent_x) - o.radii[k];
    if (r > room) {
      room = r;
      o.own = k;
    }
  }
  if (!in_slot) p.flags[parent] |= pflag::remove;
  std::size_t next = o.first_slot;
  for (std::size_t k = 0; k < o.placed.size(); ++k) {
    const Fragment& f = o.progeny.fragments[k];
    ParticleInit init;
    init.x = o.placed[k].x;
    init.v = o.vel.v[k];
    init.w = o.vel.w[k];
    init.radius = o.placed[k].r;
    init.material = material;
    init.flags = f.fines ? pflag::unbreakable : 0;
    const bool growing = o.placed[k].r < o.radii[k];
    if (growing) init.flags |= pflag::growing;
    const std::size_t s = k == o.own ? parent : next++;
    p.put(s, init, o.masses[k], o.first_id + k);
    o.slots.push_back(s);
    p.inertia[s] = o.inertia[k];  // of the full-size sphere from the start
    // fields of the parent (composition and the like are inherited)
    for (std::size_t q = 0; q < inherited.size(); ++q) p.field(q)[s] = inherited[q];
    p.field(ctx.fields.generation)[s] = o.generation;
    p.field(ctx.fields.parent_id)[s] = static_cast<double>(o.parent_id);
    p.field(ctx.fields.target)[s] = growing ? o.radii[k] : 0.0;
    if (ctx.rayleigh_floor > 0 && ctx.floor_rule == FloorRule::density_scaling)
      p.field(ctx.fields.mass_scale)[s] = o.scales[k];
    if (growing) ++o.growing;
    if (f.fines)
      ++o.rec.fines_particles;
    else
      ++o.rec.fragments;
  }
}

void Replacement::book_fragments(const Simulation& sim, const Context& ctx, const Outcome& o) {
  for (std::size_t k = 0; k < o.placed.size(); ++k) {
    const Fragment& f = o.progeny.fragments[k];
    const std::uint64_t id = o.first_id + k;
    if (k == o.own) renewed_.push_back(static_cast<std::uint32_t>(o.slots[k]));
    fragments_added_.push_back({id, o.radii[k]});
    ctx.log.add_fragment(
        {sim.time, o.parent_id, id, f.diameter, o.masses[k] / o.scales[k], o.generation, f.fines});
  }
  for (std::size_t k = 0; k < o.growing; ++k) ctx.growth.started();
}

double Replacement::created_energy(const Simulation& sim, const std::vector<Outcome>& outcomes,
                                   std::size_t q, const std::vector<std::uint32_t>& batch) const {
  const auto& p = sim.particles;
  const Outcome& o = outcomes[q];
  const std::uint16_t material = p.material[o.parent];
  double created = 0;
  std::vector<WallContact> found;
  for (std::size_t ka = 0; ka < o.slots.size(); ++ka) {
    const std::size_t a = o.slots[ka];
    for (std::size_t kb = ka + 1; kb < o.slots.size(); ++kb) {
      const std::size_t b = o.slots[kb];
      created += overlap_energy(sim, p.radius[a] + p.radius[b] - norm(p.x[a] - p.x[b]), p.radius[a],
                                material, p.radius[b], material);
    }
    for (const Neighbour& nb : *o.around) {
      auto with = [&](std::size_t j) {  // j, or one of its fragments, seen from the parent
        const Vec3 xj = sim.pair_frame(nb.parent_seen, nb.seen, p.x[j]);
        created += overlap_energy(sim, p.radius[a] + p.radius[j] - norm(p.x[a] - xj), p.radius[a],
                                  material, p.radius[j], p.material[j]);
      };
      const std::uint32_t j = nb.slot;
      if (batch[j] == 0) {
        if (!(p.flags[j] & pflag::remove)) with(j);
        continue;
      }
      // a neighbour that broke in this batch: its fragments are the neighbours now
      const Outcome& other = outcomes[batch[j] - 1];
      if (batch[j] - 1 < q)
        for (const std::size_t g : other.slots) with(g);
    }
    for (const auto& w : sim.walls) {
      found.clear();
      w->contacts(p.x[a], p.radius[a], 0.0, found);
      for (const auto& c : found)
        created += overlap_energy(sim, c.overlap, p.radius[a], material, 0, w->material);
    }
  }
  return created;
}

}  // namespace comminute::breakage
