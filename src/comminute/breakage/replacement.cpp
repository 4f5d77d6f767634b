#include "comminute/breakage/replacement.hpp"

#include <algorithm>
#include <unordered_set>

#include "comminute/breakage/breakage_ledger.hpp"
#include "comminute/breakage/contact_at_rest.hpp"
#include "comminute/breakage/fragment_growth.hpp"
#include "comminute/breakage/parallel_filter.hpp"
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
    std::vector<std::uint8_t> is_parent(p.size(), 0);
    // (the scans of the store and of the pair list run on all threads; their hits come back in
    // slot and pair order, so what follows is the same as after serial scans)
    for (const std::uint32_t i : parallel_filter(p.size(), [&](std::size_t s) {
           return (p.flags[s] & pflag::unbreakable) && wanted.count(p.id[s]) > 0;
         })) {
      slot_of[p.id[i]] = i;
      is_parent[i] = 1;
    }
    std::unordered_map<std::size_t, std::vector<Neighbour>> around;
    const auto& nl = sim.pairs();
    // a slot of the list may be a periodic ghost (no longer in the store): its owner stands in
    const auto touches_parent = [&](std::size_t k) {
      return is_parent[sim.slot_owner(nl.first[k])] != 0 ||
             is_parent[sim.slot_owner(nl.second[k])] != 0;
    };
    for (const std::uint32_t k : parallel_filter(nl.size(), touches_parent)) {
      const std::uint32_t si = nl.first[k], sj = nl.second[k];
      const auto i = static_cast<std::uint32_t>(sim.slot_owner(si)),
                 j = static_cast<std::uint32_t>(sim.slot_owner(sj));
      const bool bi = is_parent[i] != 0, bj = is_parent[j] != 0;
      if (bi) around[i].push_back({j, si, sj});
      if (bj) around[j].push_back({i, sj, si});
      if (sim.pair_state().active[k]) {  // elastic energy that leaves with the parent's contacts
        const Vec3 dx = sim.slot_position(si) - sim.slot_position(sj);
        const double dist = norm(dx);
        const double ov = p.radius[i] + p.radius[j] - dist;
        if (ov > 0 && dist > 0) {
          const double u = contact_at_rest(sim, ov, p.radius[i], p.mass[i], p.material[i],
                                           p.radius[j], p.mass[j], p.material[j], dx / dist,
                                           ContactScratch(sim.pair_state(), k))
                               .stored_energy;
          ctx.ledger.remove(sim, u);
        }
      }
    }
    std::vector<WallContact> found;
    for (const auto& c : sim.wall_contacts()) {
      if (!is_parent[c.particle]) continue;
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
    for (std::size_t b = 0; b < broken_ids_.size(); ++b) {
      const auto found_parent = slot_of.find(broken_ids_[b]);
      if (found_parent == slot_of.end()) continue;  // left through an outlet while it waited
      const std::size_t i = found_parent->second;
      replace(sim, ctx, i, around[i], broken_records_[b]);
    }
    p.compact();
    sim.particles_replaced(fragments_added_);
    fragments_added_.clear();
    fragment_slots_.clear();
    broken_ids_.clear();
    broken_records_.clear();
  }
}

void Replacement::replace(Simulation& sim, const Context& ctx, std::size_t parent,
                          const std::vector<Neighbour>& around, const EventRecord& rec_in) {
  auto& p = sim.particles;
  std::vector<Sphere> neighbours;
  for (const Neighbour& nb : around)
    neighbours.push_back(
        {sim.pair_frame(nb.parent_seen, nb.seen, p.x[nb.slot]), p.radius[nb.slot]});
  const MaterialBreakage& mat = *ctx.materials[p.material[parent]];
  EventRecord rec = rec_in;
  // A fragment that breaks while still growing counts at its final size.
  const double r_parent = std::max(p.radius[parent], p.field(ctx.fields.target)[parent]);
  if (p.flags[parent] & pflag::growing) ctx.growth.dropped();
  const double d = 2 * r_parent;
  const double mass = p.physical_mass(parent);  // kg; p.mass is the inertial mass (x mass scale)
  const double inertial_mass = p.mass[parent];
  const double density = mass / units::sphere_volume(r_parent);
  // Progeny sizes (docs/models.md eq. P1-P4).
  // E50b: the median fracture energy of the particles that break at this stressing energy, or
  // the class median (progeny key e50b; docs/models.md eq. P1b)
  // E: the event's stressing energy, or the energy absorbed up to fracture (key sizing_energy)
  const double e =
      mat.sizing_energy == SizingEnergy::stressing ? rec.stressing_energy : rec.specific_energy;
  double e50b = mat.criterion->t10_median_energy(d, e, mat.progeny->e50b_rule());
  if (e50b <= 0) e50b = mat.reference_energy;
  rec.t10 = mat.progeny->t10(e, e50b);
  const ProgenyDistribution dist = mat.progeny->distribution(d, rec.t10);
  const double min_size = std::max({mat.min_fragment_size, mat.min_fragment_ratio * d,
                                    floor_size(sim, ctx, p.material[parent])});
  const Progeny progeny = draw_progeny(dist, mass, density, min_size, mat.fines, ctx.strength_rng);
  // Placement inside the parent.
  // Inertial masses: the physical ones times each fragment's density scale (1 unless its
  // Rayleigh time is below the floor).
  std::vector<double> radii, masses, inertia, scales;
  for (const auto& f : progeny.fragments) {
    scales.push_back(mass_scale(sim, ctx, f.diameter, p.material[parent]));
    radii.push_back(0.5 * f.diameter);
    masses.push_back(f.mass);
  }
  if (ctx.mass_rule) ctx.mass_rule->share(p, parent, radii, masses);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    masses[k] *= scales[k];  // inertial
    const double df = progeny.fragments[k].diameter;
    inertia.push_back(0.4 * masses[k] * 0.25 * df * df);
  }
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
  const Sphere ps{p.x[parent], r_parent};
  const auto placed = placement_->place(ps, radii, masses, neighbours, walls, ctx.placement_rng);
  std::vector<Vec3> xs;
  for (const auto& s : placed) xs.push_back(s.x);
  const double released = mat.release_fraction * rec.specific_energy * inertial_mass;
  const auto vel = fragment_velocities(p.x[parent], p.v[parent], p.w[parent], p.inertia[parent], xs,
                                       masses, inertia, released);
  // Energy bookkeeping: kinetic energy of the parent out, of the fragments in; fines booked as
  // mass leave with their kinetic and gravitational potential energy.
  double ke_out =
      0.5 * inertial_mass * norm2(p.v[parent]) + 0.5 * p.inertia[parent] * norm2(p.w[parent]);
  const double parent_scale = p.mass_scale(parent);
  double ke_in = 0;
  const Vec3 xp = p.x[parent], vp = p.v[parent];
  const std::uint16_t material = p.material[parent];
  const std::uint32_t generation =
      static_cast<std::uint32_t>(p.field(ctx.fields.generation)[parent]) + 1;
  // Fields of the parent (composition and the like are inherited).
  std::vector<double> parent_fields;
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    parent_fields.push_back(p.field(k)[parent]);
  p.flags[parent] |= pflag::remove;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const Fragment& f = progeny.fragments[k];
    ParticleInit init;
    init.x = placed[k].x;
    init.v = vel.v[k];
    init.w = vel.w[k];
    init.radius = placed[k].r;
    init.material = material;
    init.flags = f.fines ? pflag::unbreakable : 0;
    const bool growing = placed[k].r < radii[k];
    if (growing) init.flags |= pflag::growing;
    const std::uint64_t id = p.add_with_mass(init, masses[k]);
    fragments_added_.push_back({id, radii[k]});
    ctx.log.add_fragment(
        {sim.time, p.id[parent], id, f.diameter, masses[k] / scales[k], generation, f.fines});
    const std::size_t s = p.size() - 1;
    p.inertia[s] = inertia[k];  // of the full-size sphere from the start
    for (std::size_t q = 0; q < parent_fields.size(); ++q) p.field(q)[s] = parent_fields[q];
    p.field(ctx.fields.generation)[s] = generation;
    p.field(ctx.fields.parent_id)[s] = static_cast<double>(p.id[parent]);
    p.field(ctx.fields.target)[s] = growing ? radii[k] : 0.0;
    if (ctx.rayleigh_floor > 0 && ctx.floor_rule == FloorRule::density_scaling)
      p.field(ctx.fields.mass_scale)[s] = scales[k];
    ctx.born(s);  // every fragment draws its own strength for its size
    if (growing) ctx.growth.started();
    ke_in += 0.5 * masses[k] * norm2(vel.v[k]) + 0.5 * inertia[k] * norm2(vel.w[k]);
    if (f.fines)
      ++rec.fines_particles;
    else
      ++rec.fragments;
  }
  // Elastic energy of the starting overlaps (siblings, neighbours, walls, each <= eps min r).
  const std::size_t first = p.size() - placed.size();
  double created = 0;
  std::vector<WallContact> found;
  for (std::size_t a = first; a < p.size(); ++a) {
    for (std::size_t b = a + 1; b < p.size(); ++b)
      created += overlap_energy(sim, p.radius[a] + p.radius[b] - norm(p.x[a] - p.x[b]), p.radius[a],
                                p.mass[a], material, p.radius[b], p.mass[b], material);
    for (const Neighbour& nb : around) {
      auto with = [&](std::size_t j) {  // j, or one of its fragments, seen from the parent
        const Vec3 xj = sim.pair_frame(nb.parent_seen, nb.seen, p.x[j]);
        created += overlap_energy(sim, p.radius[a] + p.radius[j] - norm(p.x[a] - xj), p.radius[a],
                                  p.mass[a], material, p.radius[j], p.mass[j], p.material[j]);
      };
      const std::uint32_t j = nb.slot;
      if (!(p.flags[j] & pflag::remove)) {
        with(j);
        continue;
      }
      // a neighbour replaced earlier in this step: its fragments are the neighbours now
      const auto it = fragment_slots_.find(p.id[j]);
      if (it != fragment_slots_.end())
        for (std::size_t g = it->second.first; g < it->second.second; ++g) with(g);
    }
    for (const auto& w : sim.walls) {
      found.clear();
      w->contacts(p.x[a], p.radius[a], 0.0, found);
      for (const auto& c : found)
        created +=
            overlap_energy(sim, c.overlap, p.radius[a], p.mass[a], material, 0, 0, w->material);
    }
  }
  ctx.ledger.create(sim, created);
  fragment_slots_[p.id[parent]] = {first, p.size()};
  if (progeny.fines_mass > 0) {
    ctx.ledger.add_fines(material, progeny.fines_mass, vp);
    const double pe = -parent_scale * progeny.fines_mass * dot(sim.gravity, xp);  // inertial
    ctx.ledger.remove(sim, pe);
  }
  rec.fines_mass = progeny.fines_mass;
  ctx.ledger.remove(sim, ke_out - ke_in);
  ctx.log.add_breakage(rec);
}

}  // namespace comminute::breakage
