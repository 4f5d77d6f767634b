#include "comminute/engine/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/integrator.hpp"

namespace comminute {

Simulation::Simulation() = default;
Simulation::~Simulation() = default;

void Simulation::assemble_contacts() {
  if (contacts_.assembled()) return;
  if (!law) throw Error("simulation has no contact law");
  std::stable_sort(modules.begin(), modules.end(), [](const auto& a, const auto& b) {
    return static_cast<int>(a->stage()) < static_cast<int>(b->stage());
  });
  if (materials.has_dynamic_friction()) law->use_dynamic_friction();
  const ContactStateStore& layout =
      contacts_.assemble(*law, rolling.get(), cohesion.get(), modules);
  pair_state_ = layout.same_layout();
  wall_state_ = layout.same_layout();
}

void Simulation::setup() {
  if (!(dt > 0)) throw Error("simulation time step is not set");
  assemble_contacts();
  flush_denormals_to_zero();
  if (ghosts_.active()) ghosts_.attach(particles);
  for (auto& m : modules) m->setup(*this);
  is_setup_ = true;
  tracker_.invalidate();
  compute_forces();
  particles.drop_ghosts();
}

void Simulation::run(std::uint64_t n) {
  for (std::uint64_t s = 0; s < n; ++s) step();
}

void Simulation::step() {
  if (!is_setup_) setup();
  if (step_control) dt = step_control->decide(particles, materials);
  const auto drift = VelocityVerlet::kick_drift(
      particles, dt, gravity, tracker_.displacement_reference(), pair_loop_.ranges());
  tracker_.moved(particles, drift.from_build2, drift.step2, options.skin);
  forces_cleared_ = true;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    walls[k]->advance(dt);
    tracker_.wall_moved(k, walls[k]->travel(dt));
  }
  time += dt;
  for (auto& m : modules) m->pre_force(*this);
  compute_forces();
  for (auto& m : modules) m->post_force(*this);
  if (ContactStress* cs = contacts_.stress()) cs->disarm();
  particles.drop_ghosts();
  const bool bad = VelocityVerlet::kick(particles, dt, pair_loop_.ranges()) || !drift.finite;
  ++step_count;
  if (bad) report_non_finite();
  for (auto& m : modules) m->end_of_step(*this);
}

void Simulation::report_non_finite() const {
  const auto& p = particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!is_finite(p.x[i]) || !is_finite(p.v[i]) || !is_finite(p.w[i]))
      throw SimulationError(fmt::format(
          "particle id {} has a non-finite position/velocity at t = {:.9g} s (step {}): x = ({}, "
          "{}, {}), v = ({}, {}, {}); the time step {:.3g} s may be too large or an input is "
          "invalid",
          p.id[i], time, step_count, p.x[i].x, p.x[i].y, p.x[i].z, p.v[i].x, p.v[i].y, p.v[i].z,
          dt));
  throw SimulationError(fmt::format("non-finite particle state at t = {:.9g} s", time));
}

void Simulation::particles_replaced(const std::vector<NewFragment>& fragments,
                                    const std::vector<std::uint32_t>& renewed) {
  tracker_.appended(fragments.size() - renewed.size());
  if (ghosts_.active()) {  // the ghosts are planned anew from the fragments at a rebuild
    particles_changed();
    return;
  }
  if (tracker_.replace(particles, walls, options.skin, fragments, renewed, pair_state_,
                       wall_state_))
    forces_cleared_ = false;
  else
    particles_changed();
}

double Simulation::reach_margin(std::size_t i) const {
  return tracker_.reach_margin(particles, i, options.skin);
}

std::size_t Simulation::slot_owner(std::size_t slot) const {
  const bool ghost = slot >= n_owned_ && slot - n_owned_ < ghosts_.size();
  return ghost ? ghosts_.owner(slot - n_owned_) : slot;
}

Vec3 Simulation::slot_position(std::size_t slot) const {
  return ghosts_.position(particles, slot, n_owned_);
}

Vec3 Simulation::to_owner_frame(std::size_t slot, const Vec3& x) const {
  return ghosts_.to_owner_frame(slot, n_owned_, x);
}

Vec3 Simulation::pair_frame(std::size_t from, std::size_t seen, const Vec3& x) const {
  return ghosts_.to_owner_frame(from, n_owned_, ghosts_.from_owner_frame(seen, n_owned_, x));
}

void Simulation::rekey_wrapped_wall_contacts() {
  // a touching wall contact of a wrapped particle is now seen from the particle's new copy: its
  // spring turns with it (sector) and a wall standing for its images re-keys the feature
  const auto& moved = ghosts_.wrapped();
  if (moved.empty()) return;
  tracker_.rekey_wall_contacts(wall_state_, [&](WallContactRecord& c, std::size_t q) {
    const auto it = std::lower_bound(
        moved.begin(), moved.end(), c.id,
        [](const GhostExchange::Wrapped& w, std::uint64_t id) { return w.id < id; });
    if (it == moved.end() || it->id != c.id) return;
    c.feature = walls[c.wall]->feature_after_wrap(c.feature, it->shift);
    if (ghosts_.map.is_sector())
      wall_state_.map_vectors(q, [&](const Vec3& v) { return ghosts_.map.vector(v, it->shift); });
  });
}

void Simulation::compute_forces() {
  const std::vector<std::uint64_t>* labels = nullptr;
  if (ghosts_.active()) {
    if (tracker_.due(particles, options)) {  // wrap and plan the ghosts anew (docs/models.md)
      tracker_.prepare(particles, options);
      ghosts_.wrap(particles);
      rekey_wrapped_wall_contacts();
      ghosts_.plan(particles, options.skin);
    }
    ghosts_.append(particles);
    labels = &ghosts_.labels(particles);
  }
  n_owned_ = particles.owned();
  const bool rebuilt = tracker_.update(particles, walls, options, pair_state_, wall_state_, labels);
  if (rebuilt && ghosts_.active()) ghosts_.turn_carried(tracker_.pairs().carried(), pair_state_);
  if (rebuilt) tracker_.pairs().release_carry();  // spent: not resident until the next rebuild
  if (!forces_cleared_)  // set-up, or particles inserted/removed after the drift
    VelocityVerlet::start_forces(particles, gravity, pair_loop_.ranges());
  forces_cleared_ = false;
  for (auto& w : walls) {
    w->force = {};
    w->torque = {};
  }
  elastic_energy_ = 0;
  ended_contacts_.clear();
  ContactStress* stress = contacts_.stress();
  if (stress) stress->begin(particles.size());
  const PrunedPairs* near = tracker_.near_pairs(particles, options, pair_state_.active);
  pair_loop_.run(particles, materials, tracker_.pairs(), near, contacts_, pair_state_, dt, ledger,
                 elastic_energy_, ended_contacts_);
  const WallCandidates& candidates = tracker_.wall_candidates();
  wall_loop_.run(particles, materials, walls, candidates.records(), candidates.elements(),
                 contacts_, wall_state_, dt, ledger, elastic_energy_, wall_contacts_,
                 ended_contacts_, pair_loop_.ranges());
  if (ghosts_.active()) ghosts_.fold(particles);
  if (stress && ghosts_.active())
    stress->fold(particles.owned(), particles.ghost_owner, [this](std::size_t g, const Vec3& v) {
      return ghosts_.map.inverse_vector(v, ghosts_.image(g));
    });
}

Observables Simulation::observe() const {
  Observables o;
  const auto& p = particles;
  o.time = time;
  o.step = step_count;
  o.dt = dt;
  o.particles = p.size();
  for (auto t : pair_state_.active) o.contacts += t;
  o.wall_contacts = wall_contacts_.size();
  for (std::size_t i = 0; i < p.size(); ++i) {
    o.kinetic_translational += 0.5 * p.mass[i] * norm2(p.v[i]);
    o.kinetic_rotational += 0.5 * p.inertia[i] * norm2(p.w[i]);
    o.potential_gravity -= p.mass[i] * dot(gravity, p.x[i]);
  }
  o.elastic = elastic_energy_;
  o.ledger = ledger;
  return o;
}

void Simulation::save(Archive& a) const {
  const auto& p = particles;
  a.put("particles/x", p.x);
  a.put("particles/v", p.v);
  a.put("particles/w", p.w);
  a.put("particles/f", p.f);
  a.put("particles/t", p.t);
  a.put("particles/radius", p.radius);
  a.put("particles/mass", p.mass);
  a.put("particles/inertia", p.inertia);
  a.put("particles/id", p.id);
  a.put("particles/material", p.material);
  a.put("particles/flags", p.flags);
  a.put_value("particles/next_id", p.next_id());
  if (ghosts_.active()) ghosts_.save(a);
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    a.put("fields/" + p.field_names()[k], p.field(k));
  tracker_.save(a);
  pair_state_.save(a, "pairs/state/");
  wall_state_.save(a, "walls/state/");
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const std::string pre = fmt::format("walls/{}/", k);
    walls[k]->save(a, pre);
    a.put(pre + "kinematics", std::vector<Kinematics>{walls[k]->kinematics});
  }
  a.put_value("sim/time", time);
  a.put_value("sim/step", step_count);
  a.put_value("sim/dt", dt);
  a.put_value("sim/skin", options.skin);
  a.put_value("sim/ledger", ledger);
  a.put_value("sim/elastic", elastic_energy_);
  a.put_value("sim/forces_cleared", static_cast<std::uint8_t>(forces_cleared_));
  for (const auto& m : modules) m->save(a);
}

// A checkpoint's particle arrays: one entry per particle in each, materials of this case,
// finite positive sizes, unique ids below the next id.
namespace {
void validate_loaded_particles(const ParticleStore& p, std::size_t n_materials) {
  const std::size_t n = p.x.size();
  auto bad = [](const char* entry, const std::string& what) {
    throw Error(fmt::format("checkpoint entry 'particles/{}' {}", entry, what));
  };
  const std::pair<const char*, std::size_t> sizes[] = {{"v", p.v.size()},
                                                       {"w", p.w.size()},
                                                       {"f", p.f.size()},
                                                       {"t", p.t.size()},
                                                       {"radius", p.radius.size()},
                                                       {"mass", p.mass.size()},
                                                       {"inertia", p.inertia.size()},
                                                       {"id", p.id.size()},
                                                       {"material", p.material.size()},
                                                       {"flags", p.flags.size()}};
  for (const auto& [name, size] : sizes)
    if (size != n) bad(name, fmt::format("holds {} particles, 'particles/x' {}", size, n));
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    if (p.field(k).size() != n)
      throw Error(fmt::format("checkpoint entry 'fields/{}' holds {} particles, not {}",
                              p.field_names()[k], p.field(k).size(), n));
  std::vector<std::uint64_t> ids(p.id);
  std::sort(ids.begin(), ids.end());
  if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) bad("id", "repeats an id");
  if (!ids.empty() && ids.back() >= p.next_id()) bad("id", "holds an id beyond 'next_id'");
  for (std::size_t i = 0; i < n; ++i) {
    if (p.material[i] >= n_materials)
      bad("material", fmt::format("particle {}: material {} is not one of the case's {}", i,
                                  p.material[i], n_materials));
    if (!(std::isfinite(p.radius[i]) && p.radius[i] > 0 && std::isfinite(p.mass[i]) &&
          p.mass[i] > 0 && std::isfinite(p.inertia[i]) && p.inertia[i] > 0))
      bad("radius", fmt::format("particle {}: radius, mass or inertia not finite and positive", i));
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(p.x[i][c]) || !std::isfinite(p.v[i][c]) || !std::isfinite(p.w[i][c]))
        bad("x", fmt::format("particle {}: position or velocity is not finite", i));
  }
}
}  // namespace

void Simulation::load(const Archive& a) {
  assemble_contacts();
  auto& p = particles;
  p.x = a.get<Vec3>("particles/x");
  p.v = a.get<Vec3>("particles/v");
  p.w = a.get<Vec3>("particles/w");
  p.f = a.get<Vec3>("particles/f");
  p.t = a.get<Vec3>("particles/t");
  p.radius = a.get<double>("particles/radius");
  p.mass = a.get<double>("particles/mass");
  p.inertia = a.get<double>("particles/inertia");
  p.id = a.get<std::uint64_t>("particles/id");
  p.material = a.get<std::uint16_t>("particles/material");
  p.flags = a.get<std::uint32_t>("particles/flags");
  p.set_next_id(a.get_value<std::uint64_t>("particles/next_id"));
  p.ghost_owner.clear();
  if (ghosts_.active()) ghosts_.attach(p);  // its image labels are fields
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    p.field(k) = a.get<double>("fields/" + p.field_names()[k]);
  validate_loaded_particles(p, materials.size());
  options.skin = a.get_value<double>("sim/skin");  // before the tracker: its reach index uses it
  if (!std::isfinite(options.skin) || options.skin < 0)
    throw Error(fmt::format("checkpoint entry 'sim/skin' = {} is not a distance", options.skin));
  // one entry per wall once the lists were built (empty before the first build)
  const std::size_t travel = a.get<double>("walls/travel").size();
  if (travel != walls.size() && !(travel == 0 && a.get_value<std::uint8_t>("sim/need_rebuild")))
    throw Error(fmt::format("checkpoint entry 'walls/travel' holds {} walls, the case {}", travel,
                            walls.size()));
  if (ghosts_.active()) ghosts_.load(a, p.size());
  n_owned_ = p.size();
  tracker_.load(a, p, options.skin, ghosts_.size());
  pair_state_.load(a, "pairs/state/", tracker_.pairs().size());
  wall_state_.load(a, "walls/state/", tracker_.wall_candidates().records().size());
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const std::string pre = fmt::format("walls/{}/", k);
    const auto geometry = a.get<Vec3>(pre + "geometry");
    const auto kinematics = a.get<Kinematics>(pre + "kinematics");
    bool finite = geometry.size() == 3 && kinematics.size() == 1;
    for (const Vec3& g : geometry) finite = finite && std::isfinite(norm2(g));
    for (const Kinematics& kin : kinematics)
      finite = finite &&
               std::isfinite(norm2(kin.velocity) + norm2(kin.angular_velocity) + norm2(kin.center));
    if (!finite)
      throw Error(
          fmt::format("checkpoint entries '{}geometry' and '{}kinematics' do not hold a "
                      "finite wall (3 points and one motion)",
                      pre, pre));
    walls[k]->load(a, pre);
    walls[k]->kinematics = kinematics.at(0);
  }
  time = a.get_value<double>("sim/time");
  step_count = a.get_value<std::uint64_t>("sim/step");
  dt = a.get_value<double>("sim/dt");
  if (!std::isfinite(time) || time < 0)
    throw Error(fmt::format("checkpoint entry 'sim/time' = {} is not a time", time));
  if (!std::isfinite(dt) || dt <= 0)
    throw Error(fmt::format("checkpoint entry 'sim/dt' = {} is not a positive time step", dt));
  ledger = a.get_value<EnergyLedger>("sim/ledger");
  flush_denormals_to_zero();
  elastic_energy_ = a.get_value<double>("sim/elastic");
  for (auto& m : modules) m->load(a);
  for (auto& m : modules) m->restored(*this);
  // a module may have inserted or removed particles after the last force computation
  forces_cleared_ = a.get_value<std::uint8_t>("sim/forces_cleared") != 0;
  // Forces were saved with the particles, so the next step continues exactly; modules restored
  // their own state in load() and are not set up again (a fill would insert twice).
  is_setup_ = true;
}

}  // namespace comminute
