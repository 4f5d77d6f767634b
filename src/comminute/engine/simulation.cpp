#include "comminute/engine/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"

namespace comminute {

namespace {
// Below this many particles (pairs: twice as many) loops run serially: an OpenMP region costs
// microseconds, more than the work of a small system.
constexpr std::size_t kParallelMin = 4096;
}  // namespace

Simulation::Simulation() = default;
Simulation::~Simulation() = default;

void Simulation::assemble_contacts() {
  if (contacts_.assembled()) return;
  if (!law) throw Error("simulation has no contact law");
  for (auto& m : modules) m->declare_contact_state(contacts_);
  const ContactStateStore& layout = contacts_.assemble(*law, rolling.get(), cohesion.get());
  pair_state_ = layout.same_layout();
  wall_state_ = layout.same_layout();
}

void Simulation::setup() {
  if (!(dt > 0)) throw Error("simulation time step is not set");
  assemble_contacts();
  flush_denormals_to_zero();
  for (auto& m : modules) m->setup(*this);
  is_setup_ = true;
  need_rebuild_ = true;
  compute_forces();
}

double Simulation::rayleigh_time() const {
  double tr = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Material& m = materials.material(particles.material[i]);
    const double rho = particles.mass[i] / (4.0 / 3.0 * M_PI * std::pow(particles.radius[i], 3));
    const double t = M_PI * particles.radius[i] * std::sqrt(rho / m.shear_modulus()) /
                     (0.1631 * m.poisson_ratio + 0.8766);
    tr = std::min(tr, t);
  }
  return tr;
}

void Simulation::run(std::uint64_t n) {
  for (std::uint64_t s = 0; s < n; ++s) step();
}

void Simulation::kick_drift() {
  // first half kick, drift, and the start of the force accumulation (gravity) in one pass
  auto& p = particles;
  const std::size_t n = p.size();
  const bool track = x_at_build_.size() == n;
  const double h = 0.5 * dt;
  const Vec3 g = gravity;
  double worst = 0;
#pragma omp parallel for schedule(static) reduction(max : worst) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
      p.x[i] += dt * p.v[i];
    }
    p.f[i] = p.mass[i] * g;
    p.t[i] = {};
    if (track) worst = std::max(worst, norm2(p.x[i] - x_at_build_[i]));
  }
  max_disp2_ = track ? worst : std::numeric_limits<double>::infinity();
  forces_cleared_ = true;
}

bool Simulation::kick() {
  // second half kick; reports whether any particle state became non-finite
  auto& p = particles;
  const std::size_t n = p.size();
  const double h = 0.5 * dt;
  bool bad = false;
#pragma omp parallel for schedule(static) reduction(|| : bad) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p.flags[i] & pflag::fixed)) {
      p.v[i] += (h / p.mass[i]) * p.f[i];
      p.w[i] += (h / p.inertia[i]) * p.t[i];
    }
    bad = bad || !is_finite(p.x[i]) || !is_finite(p.v[i]) || !is_finite(p.w[i]);
  }
  return bad;
}

void Simulation::step() {
  if (!is_setup_) setup();
  kick_drift();
  for (std::size_t k = 0; k < walls.size(); ++k) {
    walls[k]->advance(dt);
    wall_travel_[k] += norm(walls[k]->kinematics.velocity) * dt;
  }
  time += dt;
  for (auto& m : modules) m->pre_force(*this);
  compute_forces();
  for (auto& m : modules) m->post_force(*this);
  const bool bad = kick();
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

void Simulation::rebuild() {
  auto& p = particles;
  if (options.skin <= 0 && !p.empty()) {
    double mean = 0;
    for (double r : p.radius) mean += 2 * r;
    options.skin = 0.2 * mean / static_cast<double>(p.size());
  }
  const bool sort_now = options.sort_every > 0 && rebuilds_ % options.sort_every == 0;
  if (sort_now && !p.empty()) {
    const double rmax = *std::max_element(p.radius.begin(), p.radius.end());
    auto order = NeighborList::cell_order(p, 2 * rmax + options.skin);
    p.permute(order);
  }
  nlist_.build(p, options.skin, pair_state_.active);
  const auto& carried = nlist_.carried();
  pair_state_.carry(carried.from, carried.to, carried.reversed, nlist_.size());
  x_at_build_ = p.x;
  r_at_build_ = p.radius;
  reach_tracked_.clear();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.flags[i] & pflag::growing) reach_tracked_.push_back(static_cast<std::uint32_t>(i));
  build_wall_candidates();
  need_rebuild_ = false;
  ++rebuilds_;
}

void Simulation::add_wall_candidates(std::uint32_t i, std::uint32_t w, const Vec3& x, double r,
                                     std::vector<WallContact>& found,
                                     std::vector<WallContactRecord>& into) const {
  found.clear();
  const bool near = walls[w]->contacts(x, r, options.skin, found) > 0;
  if (!near && !wall_full_scan_[w]) return;
  // one candidate per (particle, wall, feature); a full-scan wall keeps one per particle
  if (found.empty()) found.push_back({{}, {}, -1, 0});
  for (const auto& c : found)
    into.push_back({i, w, c.feature, NeighborList::none, particles.id[i]});
}

void Simulation::build_wall_candidates() {
  // the touching wall contacts, by (id, wall, feature), with their index in the old list
  std::vector<WallContactRecord> old;
  for (std::size_t q = 0; q < wall_candidates_.size(); ++q)
    if (wall_state_.active[q]) {
      old.push_back(wall_candidates_[q]);
      old.back().candidate = static_cast<std::uint32_t>(q);
    }
  auto key_less = [](const WallContactRecord& a, const WallContactRecord& b) {
    return std::tie(a.id, a.wall, a.feature) < std::tie(b.id, b.wall, b.feature);
  };
  std::sort(old.begin(), old.end(), key_less);
  std::vector<WallContactRecord> fresh;  // `candidate`: the old index whose state it continues
  wall_full_scan_.assign(walls.size(), 0);
  wall_travel_.assign(walls.size(), 0.0);
  std::vector<WallContact> found;
  const auto& p = particles;
  for (std::uint32_t w = 0; w < walls.size(); ++w) {
    wall_full_scan_[w] =
        walls[w]->surface_moves() && norm2(walls[w]->kinematics.angular_velocity) > 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      const std::size_t from = fresh.size();
      add_wall_candidates(i, w, p.x[i], p.radius[i], found, fresh);
      for (std::size_t k = from; k < fresh.size(); ++k) {
        WallContactRecord& r = fresh[k];
        auto it = std::lower_bound(old.begin(), old.end(), r, key_less);
        if (it != old.end() && !key_less(r, *it)) r.candidate = it->candidate;
      }
    }
  }
  // by particle (then wall, feature): lets the force loop split the list between threads
  std::stable_sort(fresh.begin(), fresh.end(),
                   [](const WallContactRecord& a, const WallContactRecord& b) {
                     return a.particle < b.particle;
                   });
  std::vector<std::uint32_t> state_from(fresh.size());
  for (std::size_t q = 0; q < fresh.size(); ++q) state_from[q] = fresh[q].candidate;
  wall_state_.gather(state_from);
  wall_candidates_.swap(fresh);
}

void Simulation::particles_replaced(const std::vector<NewFragment>& fragments) {
  if (need_rebuild_ || options.skin <= 0 || !nlist_.can_update_in_place()) {
    particles_changed();
    return;
  }
  auto& p = particles;
  const std::vector<std::uint32_t> to_new = nlist_.slots_after_removal(p);
  const std::size_t n_kept = static_cast<std::size_t>(std::count_if(
      to_new.begin(), to_new.end(), [](std::uint32_t s) { return s != NeighborList::none; }));
  std::unordered_map<std::uint64_t, double> final_radius;  // by fragment id
  for (const auto& f : fragments) final_radius[f.id] = f.final_radius;
  bool known = !to_new.empty() && p.size() - n_kept == fragments.size();
  for (std::size_t s = n_kept; known && s < p.size(); ++s) known = final_radius.count(p.id[s]) > 0;
  if (!known) {  // something else was inserted or moved: rebuild
    particles_changed();
    return;
  }
  std::vector<Vec3> x_build(p.size());
  std::vector<double> r_build(p.size());
  for (std::size_t old = 0; old < to_new.size(); ++old)
    if (to_new[old] != NeighborList::none) {
      x_build[to_new[old]] = x_at_build_[old];
      r_build[to_new[old]] = r_at_build_[old];
    }
  std::vector<std::uint32_t> tracked;
  for (std::uint32_t s : reach_tracked_)
    if (to_new[s] != NeighborList::none) tracked.push_back(to_new[s]);
  // a fragment's reach sphere at "build" is where it is now at its final size: growth up to that
  // size then never invalidates the list
  for (std::size_t s = n_kept; s < p.size(); ++s) {
    x_build[s] = p.x[s];
    r_build[s] = std::max(p.radius[s], final_radius[p.id[s]]);
    tracked.push_back(static_cast<std::uint32_t>(s));
  }
  x_at_build_.swap(x_build);
  r_at_build_.swap(r_build);
  reach_tracked_.swap(tracked);
  nlist_.update_in_place(p, to_new, x_at_build_, r_at_build_);
  pair_state_.gather(nlist_.kept_from());
  // wall candidates: kept ones remapped, each fragment's found at its reach sphere
  std::vector<WallContactRecord> kept;
  std::vector<std::uint32_t> state_from;
  for (std::size_t q = 0; q < wall_candidates_.size(); ++q) {
    const WallContactRecord& c = wall_candidates_[q];
    const std::uint32_t s = c.particle < to_new.size() ? to_new[c.particle] : NeighborList::none;
    if (s == NeighborList::none) continue;
    WallContactRecord r = c;
    r.particle = s;
    kept.push_back(r);
    state_from.push_back(static_cast<std::uint32_t>(q));
  }
  std::vector<WallContact> found;
  for (std::size_t s = n_kept; s < p.size(); ++s)
    for (std::uint32_t w = 0; w < walls.size(); ++w)
      add_wall_candidates(static_cast<std::uint32_t>(s), w, x_at_build_[s], r_at_build_[s], found,
                          kept);
  state_from.resize(kept.size(), NeighborList::none);
  wall_candidates_.swap(kept);
  wall_state_.gather(state_from);
  forces_cleared_ = false;
}

double Simulation::reach_change(std::size_t i) const {
  return norm(particles.x[i] - x_at_build_[i]) + particles.radius[i] - r_at_build_[i];
}

double Simulation::reach_margin(std::size_t i) const {
  if (need_rebuild_ || i >= x_at_build_.size()) return 0;
  return 0.5 * options.skin - reach_change(i);
}

void Simulation::compute_forces() {
  if (!need_rebuild_) {
    double travel = 0;
    for (double t : wall_travel_) travel = std::max(travel, t);
    // |x - x_build| for every particle; plus the change of radius for the tracked ones
    double reach = std::sqrt(max_disp2_);
    for (std::uint32_t s : reach_tracked_) reach = std::max(reach, reach_change(s));
    const double limit = 0.5 * options.skin;
    if (reach > limit || travel > limit) need_rebuild_ = true;
  }
  if (need_rebuild_) rebuild();
  auto& p = particles;
  const std::size_t n = p.size();
  if (!forces_cleared_) {  // set-up, or particles inserted/removed after kick_drift()
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      p.f[i] = p.mass[i] * gravity;
      p.t[i] = {};
    }
  }
  forces_cleared_ = false;
  for (auto& w : walls) {
    w->force = {};
    w->torque = {};
  }
  elastic_energy_ = 0;
  particle_particle_forces();
  particle_wall_forces();
}

namespace {
struct ThreadTally {
  double damping = 0, friction = 0, elastic = 0, wall_work = 0;
  void add(const ContactForces& out) {
    damping += out.damping_dissipation;
    friction += out.friction_dissipation;
    elastic += out.stored_energy;
  }
};

// Splits [0, n) into nt ranges of about equal total weight; weight(k) is the cost of item k.
template <class Weight>
std::vector<std::size_t> balanced_split(std::size_t n, int nt, Weight weight) {
  std::vector<std::size_t> at(static_cast<std::size_t>(nt) + 1, n);
  at[0] = 0;
  if (nt == 1) return at;
  double total = 0;
  for (std::size_t k = 0; k < n; ++k) total += weight(k);
  double sum = 0;
  int t = 1;
  for (std::size_t k = 0; k < n && t < nt; ++k) {
    sum += weight(k);
    while (t < nt && sum >= total * t / nt) at[static_cast<std::size_t>(t++)] = k + 1;
  }
  return at;
}
}  // namespace

void Simulation::particle_particle_forces() {
  // Each thread owns a contiguous range of particle slots and the pairs they own (pairs are
  // grouped by owner), split so that the threads get equal numbers of pairs. A thread writes the
  // forces of its own particles directly; a pair whose other particle belongs to another thread
  // queues that particle's share, added after the loop in thread order. No atomics, no
  // per-thread copies of the force arrays, and the same thread count gives the same sums.
  auto& p = particles;
  const std::size_t n = p.size();
  const std::size_t npairs = nlist_.size();
  const int nt = npairs >= 2 * kParallelMin ? max_threads() : 1;
  const auto& rows = nlist_.rows();
  // balance by cost: a touching pair (contact law) costs several times a distance check
  auto& state = pair_state_;
  const auto& touching = state.active;
  const auto split =
      balanced_split(npairs, nt, [&](std::size_t k) { return 1.0 + 6.0 * touching[k]; });
  std::vector<std::uint32_t> owner_begin(static_cast<std::size_t>(nt) + 1, 0);
  owner_begin[static_cast<std::size_t>(nt)] = static_cast<std::uint32_t>(n);
  for (int t = 1; t < nt; ++t)
    owner_begin[t] = split[t] < npairs ? nlist_.first[split[t]] : static_cast<std::uint32_t>(n);
  cross_.resize(static_cast<std::size_t>(nt));
  std::vector<ThreadTally> tally(static_cast<std::size_t>(nt));
  const ContactPipeline& pipeline = contacts_;
  const Slots& slots = state.slots();
  std::uint8_t* active = state.active.data();
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    Vec3* F = p.f.data();
    Vec3* T = p.t.data();
    const std::uint32_t own0 = owner_begin[t], own1 = owner_begin[t + 1];
    auto& queued = cross_[t];
    queued.clear();
    ThreadTally tl;  // local: threads' tallies side by side in memory would share a cache line
    const std::size_t k0 = rows[own0], k1 = rows[own1];
    ContactKinematics ck;
    ck.dt = dt;
    for (std::size_t k = k0; k < k1; ++k) {
      const std::uint32_t i = nlist_.first[k], j = nlist_.second[k];
      const Vec3 d = p.x[i] - p.x[j];
      const double rsum = p.radius[i] + p.radius[j];
      const double dist2 = norm2(d);
      if (dist2 >= rsum * rsum) {
        if (active[k]) state.clear(k);  // the bodies separated: the contact's state is gone
        continue;
      }
      active[k] = 1;
      const double dist = std::sqrt(dist2);
      const Vec3 nrm = d / dist;
      const double overlap = rsum - dist;
      const double ri = p.radius[i] - 0.5 * overlap, rj = p.radius[j] - 0.5 * overlap;
      const Vec3 vrel = p.v[i] - p.v[j] - cross(p.w[i], ri * nrm) - cross(p.w[j], rj * nrm);
      const double vn = dot(vrel, nrm);
      ck.normal = nrm;
      ck.overlap = overlap;
      ck.overlap_rate = -vn;
      ck.tangential_velocity = vrel - vn * nrm;
      ck.relative_angular_velocity = p.w[i] - p.w[j];
      ck.effective_radius = p.radius[i] * p.radius[j] / rsum;
      ck.effective_mass = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
      ck.effective_inertia = p.inertia[i] * p.inertia[j] / (p.inertia[i] + p.inertia[j]);
      const PairParameters& pp = materials.pair(p.material[i], p.material[j]);
      ContactForces out;
      pipeline.evaluate(ck, pp, StateRef{&slots, k}, out);
      tl.add(out);
      const Vec3 fc = out.normal_force * nrm + out.tangential_force;
      F[i] += fc;
      T[i] += out.rolling_torque - ri * cross(nrm, out.tangential_force);
      const Vec3 tj = -(out.rolling_torque + rj * cross(nrm, out.tangential_force));
      if (j >= own0 && j < own1) {
        F[j] -= fc;
        T[j] += tj;
      } else {
        queued.push_back({j, -fc, tj});
      }
    }
    tally[t] = tl;
  }
  for (const auto& list : cross_)
    for (const auto& c : list) {
      p.f[c.particle] += c.force;
      p.t[c.particle] += c.torque;
    }
  for (const auto& tl : tally) {
    ledger.damping += tl.damping;
    ledger.friction += tl.friction;
    elastic_energy_ += tl.elastic;
  }
}

void Simulation::particle_wall_forces() {
  // Candidates are sorted by particle, so splitting them at particle boundaries gives each thread
  // its own particles; wall forces and tallies are summed per thread and combined in order.
  auto& p = particles;
  const std::size_t nc = wall_candidates_.size();
  const int nt = nc >= kParallelMin / 2 ? max_threads() : 1;
  std::vector<std::size_t> begin(static_cast<std::size_t>(nt) + 1, nc);
  begin[0] = 0;
  for (int t = 1; t < nt; ++t) {
    std::size_t b = std::max(begin[t - 1], nc * t / nt);
    while (b > 0 && b < nc && wall_candidates_[b].particle == wall_candidates_[b - 1].particle) ++b;
    begin[t] = b;
  }
  struct WallTally {
    ThreadTally energy;
    std::vector<Vec3> force, torque;
    std::vector<WallContactRecord> touching;
  };
  std::vector<WallTally> part(static_cast<std::size_t>(nt));
  const ContactPipeline& pipeline = contacts_;
  auto& state = wall_state_;
  const Slots& slots = state.slots();
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    WallTally& mine = part[t];
    mine.force.assign(walls.size(), Vec3{});
    mine.torque.assign(walls.size(), Vec3{});
    std::vector<WallContact> found;
    for (std::size_t q = begin[t]; q < begin[t + 1]; ++q) {
      WallContactRecord& c = wall_candidates_[q];
      const std::uint32_t i = c.particle;
      const Wall& w = *walls[c.wall];
      found.clear();
      w.contacts(p.x[i], p.radius[i], 0.0, found);
      const WallContact* hit = nullptr;  // a full-scan wall's candidate (feature < 0) takes any
      for (const auto& f : found)
        if (f.feature == c.feature || c.feature < 0) hit = &f;
      if (hit == nullptr || hit->overlap <= 0) {
        if (state.active[q]) state.clear(q);
        continue;
      }
      state.active[q] = 1;
      const Vec3 nrm = hit->normal;
      const double overlap = hit->overlap;
      const double ri = p.radius[i] - overlap;
      const Vec3 vwall = w.kinematics.velocity_at(hit->point);
      const Vec3 vrel = p.v[i] - cross(p.w[i], ri * nrm) - vwall;
      const double vn = dot(vrel, nrm);
      ContactKinematics ck;
      ck.dt = dt;
      ck.normal = nrm;
      ck.overlap = overlap;
      ck.overlap_rate = -vn;
      ck.tangential_velocity = vrel - vn * nrm;
      ck.relative_angular_velocity = p.w[i];
      ck.effective_radius = p.radius[i];
      ck.effective_mass = p.mass[i];
      ck.effective_inertia = p.inertia[i];
      const PairParameters& pp = materials.pair(p.material[i], w.material);
      ContactForces out;
      pipeline.evaluate(ck, pp, StateRef{&slots, q}, out);
      const Vec3 fc = out.normal_force * nrm + out.tangential_force;
      p.f[i] += fc;
      p.t[i] += out.rolling_torque - ri * cross(nrm, out.tangential_force);
      mine.force[c.wall] -= fc;
      mine.torque[c.wall] -= cross(hit->point - w.kinematics.center, fc);
      mine.energy.add(out);
      mine.energy.wall_work += dot(fc, vwall) * dt;  // power of the wall's force on the particle
      WallContactRecord rec = c;
      rec.feature = hit->feature;
      rec.candidate = static_cast<std::uint32_t>(q);
      mine.touching.push_back(rec);
    }
  }
  wall_contacts_.clear();
  for (const auto& mine : part) {
    for (std::size_t k = 0; k < walls.size(); ++k) {
      walls[k]->force += mine.force[k];
      walls[k]->torque += mine.torque[k];
    }
    ledger.damping += mine.energy.damping;
    ledger.friction += mine.energy.friction;
    ledger.wall_work += mine.energy.wall_work;
    elastic_energy_ += mine.energy.elastic;
    wall_contacts_.insert(wall_contacts_.end(), mine.touching.begin(), mine.touching.end());
  }
}

Observables Simulation::observe() const {
  Observables o;
  const auto& p = particles;
  o.time = time;
  o.step = step_count;
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
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    a.put("fields/" + p.field_names()[k], p.field(k));
  a.put("pairs/first", nlist_.first);
  a.put("pairs/second", nlist_.second);
  pair_state_.save(a, "pairs/state/");
  a.put("pairs/ids", nlist_.ids_at_build());
  a.put("pairs/large", nlist_.large());
  a.put("pairs/x_at_build", x_at_build_);
  a.put("pairs/r_at_build", r_at_build_);
  a.put("pairs/reach_tracked", reach_tracked_);
  a.put("walls/candidates", wall_candidates_);
  wall_state_.save(a, "walls/state/");
  a.put("walls/travel", wall_travel_);
  a.put("walls/full_scan", wall_full_scan_);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const std::string pre = fmt::format("walls/{}/", k);
    walls[k]->save(a, pre);
    a.put(pre + "kinematics", std::vector<Kinematics>{walls[k]->kinematics});
  }
  a.put_value("sim/time", time);
  a.put_value("sim/step", step_count);
  a.put_value("sim/dt", dt);
  a.put_value("sim/skin", options.skin);
  a.put_value("sim/rebuilds", rebuilds_);
  a.put_value("sim/ledger", ledger);
  a.put_value("sim/elastic", elastic_energy_);
  a.put_value("sim/max_disp2", max_disp2_);
  a.put_value("sim/need_rebuild", static_cast<std::uint8_t>(need_rebuild_));
  a.put_value("sim/forces_cleared", static_cast<std::uint8_t>(forces_cleared_));
  for (const auto& m : modules) m->save(a);
}

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
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    p.field(k) = a.get<double>("fields/" + p.field_names()[k]);
  nlist_.restore(a.get<std::uint32_t>("pairs/first"), a.get<std::uint32_t>("pairs/second"),
                 a.get<std::uint64_t>("pairs/ids"), a.get<std::uint8_t>("pairs/large"));
  pair_state_.load(a, "pairs/state/", nlist_.size());
  x_at_build_ = a.get<Vec3>("pairs/x_at_build");
  r_at_build_ = a.get<double>("pairs/r_at_build");
  reach_tracked_ = a.get<std::uint32_t>("pairs/reach_tracked");
  if (x_at_build_.size() == p.size()) nlist_.rebuild_index(x_at_build_, r_at_build_, options.skin);
  wall_candidates_ = a.get<WallContactRecord>("walls/candidates");
  wall_state_.load(a, "walls/state/", wall_candidates_.size());
  wall_travel_ = a.get<double>("walls/travel");
  wall_full_scan_ = a.get<std::uint8_t>("walls/full_scan");
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const std::string pre = fmt::format("walls/{}/", k);
    walls[k]->load(a, pre);
    walls[k]->kinematics = a.get<Kinematics>(pre + "kinematics").at(0);
  }
  time = a.get_value<double>("sim/time");
  step_count = a.get_value<std::uint64_t>("sim/step");
  dt = a.get_value<double>("sim/dt");
  options.skin = a.get_value<double>("sim/skin");
  rebuilds_ = a.get_value<std::uint64_t>("sim/rebuilds");
  ledger = a.get_value<EnergyLedger>("sim/ledger");
  flush_denormals_to_zero();
  elastic_energy_ = a.get_value<double>("sim/elastic");
  max_disp2_ = a.get_value<double>("sim/max_disp2");
  for (auto& m : modules) m->load(a);
  // a module may have inserted or removed particles after the last force computation
  need_rebuild_ = a.get_value<std::uint8_t>("sim/need_rebuild") != 0;
  forces_cleared_ = a.get_value<std::uint8_t>("sim/forces_cleared") != 0;
  // Forces were saved with the particles, so the next step continues exactly; modules restored
  // their own state in load() and are not set up again (a fill would insert twice).
  is_setup_ = true;
}

}  // namespace comminute
