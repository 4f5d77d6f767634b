#include "comminute/breakage/breakage_module.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/core/units.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/engine/time_step_policy.hpp"
#include "comminute/fracture/energy_share.hpp"

namespace comminute::breakage {

BreakageModule::BreakageModule(std::vector<std::optional<MaterialBreakage>> per_material,
                               BreakageOptions opt)
    : materials_(std::move(per_material)), opt_(std::move(opt)) {
  if (!opt_.placement_model)
    opt_.placement_model = std::make_shared<InsideParentPlacement>(opt_.placement);
}

BreakageModule::~BreakageModule() = default;

void BreakageModule::register_fields(ParticleStore& p) {
  for (auto& m : materials_)
    if (m) m->criterion->attach(p);
  f_init_ = p.add_field("breakage.initialized", 0.0);  // 1 once strength is drawn
  f_generation_ = p.add_field("breakage.generation", 0.0);
  f_target_ = p.add_field("breakage.target_radius", 0.0);  // m, final radius while growing
  f_in_event_ = p.add_field("breakage.in_event", 0.0);
  f_energy_ = p.add_field("breakage.event_energy", 0.0);  // J/kg
  f_force_ = p.add_field("breakage.event_force", 0.0);    // N
  f_baseline_ = p.add_field("breakage.baseline", 0.0);    // J/kg
  f_quiet_ = p.add_field("breakage.quiet_steps", 0.0);
}

void BreakageModule::setup(Simulation& sim) {
  strength_rng_ = Rng(sim.seed, rng_stream::breakage);
  placement_rng_ = Rng(sim.seed, rng_stream::placement);
  configure(sim);
  auto& p = sim.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.field(f_init_)[i] == 0) initialize_particle(sim, i);
}

void BreakageModule::configure(Simulation& sim) {
  auto& p = sim.particles;
  register_fields(p);
  n_materials_ = sim.materials.size();
  materials_.resize(std::max(materials_.size(), n_materials_));
  share_.assign(n_materials_ * n_materials_, 0.5);
  for (std::size_t a = 0; a < n_materials_; ++a)
    for (std::size_t b = 0; b < n_materials_; ++b) {
      const Material& ma = sim.materials.material(static_cast<std::uint16_t>(a));
      const Material& mb = sim.materials.material(static_cast<std::uint16_t>(b));
      share_[a * n_materials_ + b] = fracture::energy_share(
          fracture::plane_strain_modulus(ma.youngs_modulus, ma.poisson_ratio),
          fracture::plane_strain_modulus(mb.youngs_modulus, mb.poisson_ratio));
    }
  fines_mass_.resize(n_materials_, 0.0);
  pending_ = 0;
  for (std::size_t i = 0; i < p.size(); ++i) pending_ += (p.flags[i] & pflag::growing) ? 1 : 0;
}

void BreakageModule::initialize_particle(Simulation& sim, std::size_t i) {
  auto& p = sim.particles;
  p.field(f_init_)[i] = 1;
  const auto& m = materials_[p.material[i]];
  if (!m) return;
  const double target = p.field(f_target_)[i];
  m->criterion->initialize(p, i, 2 * (target > 0 ? target : p.radius[i]), strength_rng_);
}

namespace {
// The contact model evaluated at rest between sphere i (radius, mass, material) and a sphere
// (r_j > 0) or a wall (r_j = 0) at `overlap` along `normal`, on a copy of the contact's state
// (fresh by default): nothing slips or advances. Gives the forces and energies a contact holds in
// that state.
ContactForces contact_at_rest(const Simulation& sim, double overlap, double r_i, double m_i,
                              std::uint16_t a, double r_j, double m_j, std::uint16_t b,
                              const Vec3& normal = {0, 0, 1},
                              const ContactScratch& state = ContactScratch{}) {
  ContactKinematics ck;
  ck.normal = normal;
  ck.overlap = overlap;
  ck.effective_radius = r_j > 0 ? r_i * r_j / (r_i + r_j) : r_i;
  ck.effective_mass = m_j > 0 ? m_i * m_j / (m_i + m_j) : m_i;
  ck.dt = 0;
  ContactForces out;
  sim.contacts().evaluate(ck, sim.materials.pair(a, b), state.ref(), out);
  return out;
}

// Normal elastic energy (J) of a fresh contact with overlap `overlap` (0 when not touching).
double overlap_energy(const Simulation& sim, double overlap, double r_i, double m_i,
                      std::uint16_t a, double r_j, double m_j, std::uint16_t b) {
  if (overlap <= 0) return 0.0;
  return contact_at_rest(sim, overlap, r_i, m_i, a, r_j, m_j, b).normal_elastic_energy;
}
}  // namespace

void BreakageModule::add_energy(Simulation& sim, double joules) {
  created_ += joules;
  removed_ -= joules;
  sim.ledger.removed -= joules;
}

void BreakageModule::grow(Simulation& sim) {
  auto& p = sim.particles;
  const std::size_t n = p.size();
  const double eps = opt_.growth_overlap_ratio;
  std::vector<double> limit(n, 0.0);
  const auto& target = p.field(f_target_);
  for (std::size_t i = 0; i < n; ++i)
    if (p.flags[i] & pflag::growing) limit[i] = target[i];
  const auto& nl = sim.pairs();
  parallel_scatter(
      nl.size(), limit, std::numeric_limits<double>::infinity(),
      [&](std::size_t k, std::vector<double>& lim) {
        const std::uint32_t i = nl.first[k], j = nl.second[k];
        const bool gi = p.flags[i] & pflag::growing, gj = p.flags[j] & pflag::growing;
        if (!gi && !gj) return;
        if (gi && gj) {  // two growing spheres share the room up to the allowed overlap
          const double room = norm(p.x[i] - p.x[j]) - p.radius[i] - p.radius[j] +
                              eps * std::min(p.radius[i], p.radius[j]);
          lim[i] = std::min(lim[i], p.radius[i] + 0.5 * room);
          lim[j] = std::min(lim[j], p.radius[j] + 0.5 * room);
        } else if (gi) {
          lim[i] = std::min(lim[i], radius_allowed(p.x[i], target[i], {p.x[j], p.radius[j]}, eps));
        } else {
          lim[j] = std::min(lim[j], radius_allowed(p.x[j], target[j], {p.x[i], p.radius[i]}, eps));
        }
      },
      [](double a, double b) { return std::min(a, b); });
  const std::vector<double> r_before = p.radius;
  // Growth at fixed positions raises the overlaps of the growing spheres: that elastic energy
  // comes from nowhere, so it is booked (as negative removed energy) to keep the balance closed.
  struct GrowthTally {
    double wall_energy = 0;     // J, created in wall contacts
    std::size_t completed = 0;  // fragments that reached full size
    bool rebuild = false;       // some fragment used up its reach margin
  };
  std::vector<GrowthTally> tally(1);
  parallel_scatter(
      n, tally, GrowthTally{},
      [&](std::size_t i, std::vector<GrowthTally>& acc) {
        // blocked by a neighbour already: no growth this step (spares the wall look-ups)
        if (!(p.flags[i] & pflag::growing) || limit[i] <= p.radius[i]) return;
        thread_local std::vector<WallContact> found;
        for (const auto& w : sim.walls) {
          found.clear();
          w->contacts(p.x[i], p.radius[i], target[i], found);
          for (const auto& c : found)  // distance to the wall = r - overlap; keep overlap <= eps r
            limit[i] = std::min(limit[i], (p.radius[i] - c.overlap) / (1.0 - eps));
        }
        double r_new = std::min({target[i], p.radius[i] + opt_.growth_step * target[i],
                                 std::max(p.radius[i], limit[i])});
        // the pair list covers unlisted spheres only up to the reach margin: grow within it,
        // and have the list rebuilt once it is used up
        const double margin = std::max(0.0, sim.reach_margin(i));
        if (r_new - p.radius[i] >= margin) {
          r_new = p.radius[i] + margin;
          acc[0].rebuild = true;
        }
        if (r_new >= target[i]) {
          r_new = target[i];
          p.flags[i] &= ~pflag::growing;
          p.field(f_target_)[i] = 0;
          ++acc[0].completed;
        }
        p.radius[i] = r_new;
        if (r_new == r_before[i]) return;
        for (const auto& w : sim.walls) {
          found.clear();
          w->contacts(p.x[i], r_new, 0.0, found);
          for (const auto& c : found)
            acc[0].wall_energy +=
                overlap_energy(sim, c.overlap, r_new, p.mass[i], p.material[i], 0, 0, w->material) -
                overlap_energy(sim, c.overlap - (r_new - r_before[i]), r_before[i], p.mass[i],
                               p.material[i], 0, 0, w->material);
        }
      },
      [](GrowthTally a, const GrowthTally& b) {
        return GrowthTally{a.wall_energy + b.wall_energy, a.completed + b.completed,
                           a.rebuild || b.rebuild};
      });
  pending_ -= tally[0].completed;
  std::vector<double> pair_energy(1, 0.0);  // J, summed per thread
  parallel_scatter(
      nl.size(), pair_energy, 0.0,
      [&](std::size_t k, std::vector<double>& sum) {
        const std::uint32_t i = nl.first[k], j = nl.second[k];
        if (p.radius[i] == r_before[i] && p.radius[j] == r_before[j]) return;  // nothing grew
        const double dist = norm(p.x[i] - p.x[j]);
        const double before = r_before[i] + r_before[j] - dist,
                     after = p.radius[i] + p.radius[j] - dist;
        if (after <= 0) return;
        sum[0] += overlap_energy(sim, after, p.radius[i], p.mass[i], p.material[i], p.radius[j],
                                 p.mass[j], p.material[j]) -
                  overlap_energy(sim, before, r_before[i], p.mass[i], p.material[i], r_before[j],
                                 p.mass[j], p.material[j]);
      },
      [](double a, double b) { return a + b; });
  add_energy(sim, pair_energy[0] + tally[0].wall_energy);
  if (tally[0].rebuild) sim.particles_changed();
}

void BreakageModule::post_force(Simulation& sim) {
  if (pending_ > 0) grow(sim);
  update_events(sim);
}

void BreakageModule::update_events(Simulation& sim) {
  auto& p = sim.particles;
  const std::size_t n = p.size();
  contact_load_.assign(n, ContactLoad{});
  const auto& nl = sim.pairs();
  const ContactStateStore& pairs = sim.pair_state();
  const LoadingRecord& loading = *sim.contacts().loading();
  parallel_scatter(
      nl.size(), contact_load_, ContactLoad{},
      [&](std::size_t k, std::vector<ContactLoad>& acc) {
        if (!pairs.active[k]) return;
        const std::uint32_t i = nl.first[k], j = nl.second[k];
        const StateRef h = pairs.at(k);
        const std::size_t a = p.material[i], b = p.material[j];
        acc[i].work += share_[a * n_materials_ + b] * loading.loading_work(h);
        acc[j].work += share_[b * n_materials_ + a] * loading.loading_work(h);
        acc[i].force += loading.normal_force(h);
        acc[j].force += loading.normal_force(h);
      },
      [](ContactLoad x, const ContactLoad& y) {
        return ContactLoad{x.work + y.work, x.force + y.force};
      });
  for (const auto& c : sim.wall_contacts()) {
    const std::size_t a = p.material[c.particle], b = sim.walls[c.wall]->material;
    const StateRef h = sim.wall_state().at(c.candidate);
    contact_load_[c.particle].work += share_[a * n_materials_ + b] * loading.loading_work(h);
    contact_load_[c.particle].force += loading.normal_force(h);
  }
  auto& in_event = p.field(f_in_event_);
  auto& energy = p.field(f_energy_);
  auto& force = p.field(f_force_);
  auto& baseline = p.field(f_baseline_);
  auto& quiet = p.field(f_quiet_);
  const auto& target = p.field(f_target_);
  for (std::size_t i = 0; i < n; ++i)  // particles inserted by other modules draw strength now
    if (p.field(f_init_)[i] == 0) initialize_particle(sim, i);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& mat = materials_[p.material[i]];
    if (!mat || (p.flags[i] & (pflag::fixed | pflag::unbreakable | pflag::remove))) continue;
    // A growing fragment already carries its full mass and transmits real contact forces: it is
    // assessed at its final size (the overlaps growth creates are capped, see grow()).
    const double d = 2 * std::max(p.radius[i], target[i]);
    const double s = contact_load_[i].work / p.mass[i];  // J/kg
    if (d < mat->min_breakable_size) {
      baseline[i] = s;
      continue;
    }
    const BreakageCriterion& crit = *mat->criterion;
    auto record = [&] {  // the event as it stands, for the log
      EventRecord r;
      r.time = sim.time;
      r.parent_id = p.id[i];
      r.material = p.material[i];
      r.generation = static_cast<std::uint32_t>(p.field(f_generation_)[i]);
      r.diameter = d;
      r.mass = p.mass[i];
      r.specific_energy = energy[i];
      r.peak_force = force[i];
      r.strength = crit.strength(p, i, d);
      r.damage_before = crit.damage(p, i);
      return r;
    };
    auto end_event = [&](bool broke) {
      ++events_;
      if (opt_.log_all_events && !broke) log_.push_back(record());
      if (!broke) crit.survive(p, i, d, {energy[i], force[i]});
      in_event[i] = 0;
      energy[i] = force[i] = 0;
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
      energy[i] = force[i] = 0;
      quiet[i] = 0;
    }
    const double e = s - baseline[i];
    if (e > energy[i]) {
      energy[i] = e;
      quiet[i] = 0;
    } else {
      quiet[i] += 1;
    }
    force[i] = std::max(force[i], contact_load_[i].force);
    const StressingEvent ev{energy[i], force[i]};
    if (crit.breaks(p, i, d, ev)) {
      EventRecord r = record();
      r.broken = 1;
      broken_ids_.push_back(p.id[i]);
      broken_records_.push_back(r);
      end_event(true);
      p.flags[i] |= pflag::unbreakable;  // until it is replaced at the end of the step
    } else if (quiet[i] >= opt_.event_end_steps) {
      end_event(false);
      baseline[i] = s;
    }
  }
}

void BreakageModule::end_of_step(Simulation& sim) {
  const bool due = opt_.replacement_interval <= 1 ||
                   sim.step_count % static_cast<std::uint64_t>(opt_.replacement_interval) == 0;
  if (!broken_ids_.empty() && due) {
    auto& p = sim.particles;
    // Slots of the parents and the spheres around them (other parents included).
    std::unordered_map<std::uint64_t, std::size_t> slot_of;
    const std::unordered_set<std::uint64_t> wanted(broken_ids_.begin(), broken_ids_.end());
    std::vector<std::uint8_t> is_parent(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i)
      if ((p.flags[i] & pflag::unbreakable) && wanted.count(p.id[i])) {
        slot_of[p.id[i]] = i;
        is_parent[i] = 1;
      }
    std::unordered_map<std::size_t, std::vector<std::uint32_t>> around;
    const auto& nl = sim.pairs();
    for (std::size_t k = 0; k < nl.size(); ++k) {
      const std::uint32_t i = nl.first[k], j = nl.second[k];
      const bool bi = is_parent[i] != 0, bj = is_parent[j] != 0;
      if (!bi && !bj) continue;
      if (bi) around[i].push_back(j);
      if (bj) around[j].push_back(i);
      if (sim.pair_state().active[k]) {  // elastic energy that leaves with the parent's contacts
        const Vec3 dx = p.x[i] - p.x[j];
        const double dist = norm(dx);
        const double ov = p.radius[i] + p.radius[j] - dist;
        if (ov > 0 && dist > 0) {
          const double u = contact_at_rest(sim, ov, p.radius[i], p.mass[i], p.material[i],
                                           p.radius[j], p.mass[j], p.material[j], dx / dist,
                                           ContactScratch(sim.pair_state(), k))
                               .stored_energy;
          removed_ += u;
          sim.ledger.removed += u;
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
          removed_ += u;
          sim.ledger.removed += u;
        }
    }
    for (std::size_t b = 0; b < broken_ids_.size(); ++b) {
      const std::size_t i = slot_of.at(broken_ids_[b]);
      replace(sim, i, around[i], broken_records_[b]);
    }
    p.compact();
    sim.particles_replaced(fragments_added_);
    fragments_added_.clear();
    fragment_slots_.clear();
    broken_ids_.clear();
    broken_records_.clear();
  }
}

void BreakageModule::replace(Simulation& sim, std::size_t parent,
                             const std::vector<std::uint32_t>& around, const EventRecord& rec_in) {
  auto& p = sim.particles;
  std::vector<Sphere> neighbours;
  for (std::uint32_t j : around) neighbours.push_back({p.x[j], p.radius[j]});
  const MaterialBreakage& mat = *materials_[p.material[parent]];
  EventRecord rec = rec_in;
  // A fragment that breaks while still growing counts at its final size.
  const double r_parent = std::max(p.radius[parent], p.field(f_target_)[parent]);
  if (p.flags[parent] & pflag::growing) --pending_;
  const double d = 2 * r_parent;
  const double mass = p.mass[parent];
  const double density = mass / units::sphere_volume(r_parent);
  // Progeny sizes (docs/models.md eq. P1-P4).
  double e50b = mat.criterion->median_fracture_energy(d);
  if (e50b <= 0) e50b = mat.reference_energy;
  rec.t10 = mat.progeny->t10(rec.specific_energy, e50b);
  const ProgenyDistribution dist = mat.progeny->distribution(d, rec.t10);
  const double min_size = std::max(mat.min_fragment_size, mat.min_fragment_ratio * d);
  const Progeny progeny = draw_progeny(dist, mass, density, min_size, mat.fines, strength_rng_);
  // Placement inside the parent.
  std::vector<double> radii, masses, inertia;
  for (const auto& f : progeny.fragments) {
    radii.push_back(0.5 * f.diameter);
    masses.push_back(f.mass);
    inertia.push_back(0.4 * f.mass * 0.25 * f.diameter * f.diameter);
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
  const auto placed =
      opt_.placement_model->place(ps, radii, masses, neighbours, walls, placement_rng_);
  std::vector<Vec3> xs;
  for (const auto& s : placed) xs.push_back(s.x);
  const double released = mat.release_fraction * rec.specific_energy * mass;
  const auto vel = fragment_velocities(p.x[parent], p.v[parent], p.w[parent], p.inertia[parent], xs,
                                       masses, inertia, released);
  // Energy bookkeeping: kinetic energy of the parent out, of the fragments in; fines booked as
  // mass leave with their kinetic and gravitational potential energy.
  double ke_out = 0.5 * mass * norm2(p.v[parent]) + 0.5 * p.inertia[parent] * norm2(p.w[parent]);
  double ke_in = 0;
  const Vec3 xp = p.x[parent], vp = p.v[parent];
  const std::uint16_t material = p.material[parent];
  const std::uint32_t generation = static_cast<std::uint32_t>(p.field(f_generation_)[parent]) + 1;
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
    fragments_added_.push_back({p.add_with_mass(init, f.mass), radii[k]});
    const std::size_t s = p.size() - 1;
    p.inertia[s] = inertia[k];  // of the full-size sphere from the start
    for (std::size_t q = 0; q < parent_fields.size(); ++q) p.field(q)[s] = parent_fields[q];
    p.field(f_generation_)[s] = generation;
    p.field(f_target_)[s] = growing ? radii[k] : 0.0;
    p.field(f_in_event_)[s] = p.field(f_energy_)[s] = p.field(f_force_)[s] = 0;
    p.field(f_baseline_)[s] = p.field(f_quiet_)[s] = 0;
    p.field(f_init_)[s] = 0;
    initialize_particle(sim, s);  // every fragment draws its own strength for its size
    if (growing) ++pending_;
    ke_in += 0.5 * f.mass * norm2(vel.v[k]) + 0.5 * inertia[k] * norm2(vel.w[k]);
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
    auto with = [&](std::size_t j) {
      created += overlap_energy(sim, p.radius[a] + p.radius[j] - norm(p.x[a] - p.x[j]), p.radius[a],
                                p.mass[a], material, p.radius[j], p.mass[j], p.material[j]);
    };
    for (std::uint32_t j : around) {
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
  add_energy(sim, created);
  fragment_slots_[p.id[parent]] = {first, p.size()};
  if (progeny.fines_mass > 0) {
    fines_mass_[material] += progeny.fines_mass;
    fines_momentum_ += progeny.fines_mass * vp;
    const double pe = -progeny.fines_mass * dot(sim.gravity, xp);
    removed_ += pe;
    sim.ledger.removed += pe;
  }
  rec.fines_mass = progeny.fines_mass;
  removed_ += ke_out - ke_in;
  sim.ledger.removed += ke_out - ke_in;
  ++breakages_;
  log_.push_back(rec);
}

void BreakageModule::save(Archive& a) const {
  const auto s1 = strength_rng_.state(), s2 = placement_rng_.state();
  a.put("breakage/strength_rng", std::vector<std::uint64_t>(s1.begin(), s1.end()));
  a.put("breakage/placement_rng", std::vector<std::uint64_t>(s2.begin(), s2.end()));
  a.put("breakage/log", log_);
  a.put("breakage/fines_mass", fines_mass_);
  a.put_value("breakage/fines_momentum", fines_momentum_);
  a.put("breakage/counters", std::vector<std::uint64_t>{breakages_, events_});
  a.put_value("breakage/removed", removed_);
  a.put_value("breakage/created", created_);
  series_.save(a);
}

void BreakageModule::load(const Archive& a) {
  auto to_state = [&a](const std::string& entry) {
    const auto v = a.get<std::uint64_t>(entry);
    Rng::State s{};
    if (v.size() != s.size())
      throw Error(fmt::format("checkpoint entry '{}' holds {} words, a generator state {}", entry,
                              v.size(), s.size()));
    std::copy_n(v.begin(), s.size(), s.begin());
    return s;
  };
  strength_rng_.set_state(to_state("breakage/strength_rng"));
  placement_rng_.set_state(to_state("breakage/placement_rng"));
  log_ = a.get<EventRecord>("breakage/log");
  fines_mass_ = a.get<double>("breakage/fines_mass");
  fines_momentum_ = a.get_value<Vec3>("breakage/fines_momentum");
  const auto c = a.get<std::uint64_t>("breakage/counters");
  if (c.size() != 2) throw Error("checkpoint entry 'breakage/counters' has a wrong size");
  breakages_ = c.at(0);
  events_ = c.at(1);
  removed_ = a.get_value<double>("breakage/removed");
  created_ = a.get_value<double>("breakage/created");
  series_.load(a);
}

void BreakageModule::announce_sizes(std::vector<ParticleSize>& sizes, const Simulation& sim) const {
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    if (!materials_[k]) continue;
    const double d =
        std::max(materials_[k]->min_fragment_size,
                 materials_[k]->min_fragment_ratio * materials_[k]->min_breakable_size);
    const auto m = static_cast<std::uint16_t>(k);
    sizes.push_back({0.5 * d, m,
                     fmt::format("the smallest fragment ({:.4g} m) material '{}' can produce", d,
                                 sim.materials.material(m).name),
                     true});
  }
}

void BreakageModule::restored(Simulation& sim) {
  configure(sim);  // modules are not set up again after a checkpoint
}

}  // namespace comminute::breakage
