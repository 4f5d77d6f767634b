#include "comminute/breakage/fragment_growth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "comminute/breakage/breakage_ledger.hpp"
#include "comminute/breakage/contact_at_rest.hpp"
#include "comminute/breakage/parallel_filter.hpp"
#include "comminute/breakage/placement/fragment_placement.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

namespace {
constexpr std::size_t kAhead = 16;  // hit pairs between a particle's prefetch and its use
}  // namespace

void FragmentGrowth::recount(const ParticleStore& p) {
  pending_ = 0;
  for (std::size_t i = 0; i < p.size(); ++i) pending_ += (p.flags[i] & pflag::growing) ? 1 : 0;
}

void FragmentGrowth::grow(Simulation& sim, std::size_t f_target, BreakageLedger& ledger) {
  auto& p = sim.particles;
  const std::size_t n = p.size();
  const double eps = eps_;
  const bool pushing = pushing_;
  std::vector<double>& limit = limit_;
  // one byte per slot, bit 0: growing at the start of the step, bit 1: its radius changed; the
  // pair scans read these (n bytes stay in cache) instead of the flags and both radius arrays
  constexpr std::uint8_t was_growing = 1, grew = 2;
  std::vector<std::uint8_t>& state = state_;
  std::vector<double>& r_before = r_before_;
  limit.resize(n);
  state.resize(n);
  r_before.resize(n);
  const auto& target = p.field(f_target);
  double target_max = 0;  // m, the largest final radius of a growing particle
  {
    // (plain pointers: through the vectors every store would reload their data pointers)
    const std::uint32_t* flags = p.flags.data();
    const double *radius = p.radius.data(), *final_radius = target.data();
    std::uint8_t* st = state.data();
    double* rb = r_before.data();
#pragma omp parallel for schedule(static) reduction(max : target_max) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const bool g = (flags[i] & pflag::growing) != 0;
      st[i] = g ? was_growing : 0;
      rb[i] = radius[i];
      target_max = std::max(target_max, g ? final_radius[i] : 0.0);
    }
  }
  // No particle grows by more than this (m) in the step. A pair whose gap is at least twice it
  // cannot bound either particle's growth: every rule below allows each of them at least half the
  // gap (the margin, relative 1e-9, covers rounding), so it is passed over without a root.
  const double growth_max = step_ * target_max;
  const auto& nl = sim.pairs();
  // The pairs with a growing particle, in list order (a third or more of them): only these bound
  // the growth and carry growth energy.
  std::vector<std::uint32_t>& hits = hit_pairs_;
  parallel_select(
      nl.size(), [&](std::size_t k) { return (state[nl.first[k]] | state[nl.second[k]]) != 0; },
      hits, select_parts_);
  // the largest radius (m) the neighbours allow each growing particle, +inf where none bounds it
  // (the growth below is capped at the final radius as well); reset by the scatter
  std::vector<double>& hit_d2 = hit_d2_;
  hit_d2.resize(hits.size());
  owner_scatter(
      hits.size(), [&](std::size_t m) { return nl.first[hits[m]]; }, limit,
      std::numeric_limits<double>::infinity(),
      [&](std::size_t m, auto& bound) {
        // the second particles are scattered in memory: asked for kAhead hits before their use
        const std::uint32_t ja = nl.second[hits[std::min(m + kAhead, hits.size() - 1)]];
        __builtin_prefetch(&p.x[ja]);
        __builtin_prefetch(&p.radius[ja]);
        const std::uint32_t i = nl.first[hits[m]], j = nl.second[hits[m]];
        const double apart = p.radius[i] + p.radius[j] + 2 * growth_max;
        const double d2 = norm2(p.x[i] - p.x[j]);
        const bool near = !(d2 > apart * apart * (1 + 1e-9));
        hit_d2[m] = near ? d2 : std::numeric_limits<double>::infinity();
        if (!near) return;
        const bool gi = state[i] != 0, gj = state[j] != 0;
        if (pushing) {  // the overlap may deepen by eps min(r_i, r_j), shared when both grow
          const double gap = std::sqrt(d2) - p.radius[i] - p.radius[j];
          const double room = std::max(0.0, gap) + eps * std::min(p.radius[i], p.radius[j]);
          const double share = gi && gj ? 0.5 * room : room;
          if (gi) bound(i, p.radius[i] + share);
          if (gj) bound(j, p.radius[j] + share);
        } else if (gi && gj) {  // two growing spheres share the room up to the allowed overlap
          const double room =
              std::sqrt(d2) - p.radius[i] - p.radius[j] + eps * std::min(p.radius[i], p.radius[j]);
          bound(i, p.radius[i] + 0.5 * room);
          bound(j, p.radius[j] + 0.5 * room);
        } else if (gi) {
          bound(i, radius_allowed(p.x[i], target[i], {p.x[j], p.radius[j]}, eps));
        } else {
          bound(j, radius_allowed(p.x[j], target[j], {p.x[i], p.radius[i]}, eps));
        }
      },
      [](double a, double b) { return std::min(a, b); }, limit_queues_);
  // a ghost's neighbours bound its owner's growth (periodic boundaries)
  for (std::size_t s = p.owned(); s < n; ++s)
    limit[p.owner_of(s)] = std::min(limit[p.owner_of(s)], limit[s]);
  // Growth at fixed positions raises the overlaps of the growing spheres: that elastic energy
  // comes from nowhere, so it is booked (as negative removed energy) to keep the balance closed.
  struct GrowthTally {
    double wall_energy = 0;     // J, created in wall contacts
    std::size_t completed = 0;  // fragments that reached full size
    bool rebuild = false;       // some fragment used up its reach margin
  };
  // the growing fragments not blocked by a neighbour already (the others do not grow this step;
  // this spares their wall look-ups), shared evenly between the threads: fragments are appended
  // at the end of the store, so a split of the slots would hand most of them to the last thread
  std::vector<std::uint32_t>& free = free_slots_;
  parallel_select(
      p.owned(),
      [&](std::size_t i) { return (state[i] & was_growing) && !(limit[i] <= p.radius[i]); }, free,
      select_parts_);
  std::vector<GrowthTally> tally(1);
  parallel_scatter(
      free.size(), tally, GrowthTally{},
      [&](std::size_t m, std::vector<GrowthTally>& acc) {
        const std::size_t i = free[m];
        thread_local std::vector<WallContact> found;
        bool near_wall = false;  // some wall within the final radius (it grows no further)
        for (const auto& w : sim.walls) {
          found.clear();
          w->contacts(p.x[i], p.radius[i], target[i], found);
          near_wall = near_wall || !found.empty();
          for (const auto& c : found)  // distance to the wall = r - overlap
            limit[i] = std::min(
                limit[i], pushing_ ? p.radius[i] + std::max(0.0, -c.overlap) + eps * p.radius[i]
                                   : (p.radius[i] - c.overlap) / (1.0 - eps));  // <= eps r
        }
        double r_new =
            std::min({target[i], p.radius[i] + step_ * target[i], std::max(p.radius[i], limit[i])});
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
          p.field(f_target)[i] = 0;
          ++acc[0].completed;
        }
        p.radius[i] = r_new;
        if (r_new == r_before[i]) return;
        state[i] |= grew;
        if (!near_wall) return;  // no wall it could touch at its new radius
        for (const auto& w : sim.walls) {
          found.clear();
          w->contacts(p.x[i], r_new, 0.0, found);
          for (const auto& c : found)
            acc[0].wall_energy +=
                overlap_energy(sim, c.overlap, r_new, p.material[i], 0, w->material) -
                overlap_energy(sim, c.overlap - (r_new - r_before[i]), r_before[i], p.material[i],
                               0, w->material);
        }
      },
      [](GrowthTally a, const GrowthTally& b) {
        return GrowthTally{a.wall_energy + b.wall_energy, a.completed + b.completed,
                           a.rebuild || b.rebuild};
      });
  pending_ -= tally[0].completed;
  for (std::size_t s = p.owned(); s < n; ++s) {  // ghosts
    p.radius[s] = p.radius[p.owner_of(s)];
    if (p.radius[s] != r_before[s]) state[s] |= grew;
  }
  // the growth energy of the pairs close enough to touch after growth
  std::vector<std::uint32_t>& near = near_hits_;
  parallel_select(
      hits.size(),
      [&](std::size_t m) { return hit_d2[m] != std::numeric_limits<double>::infinity(); }, near,
      select_parts_);
  const int nh = near.size() >= kScatterMin ? max_threads() : 1;
  std::vector<double> pair_energy(static_cast<std::size_t>(nh), 0.0);  // J, per thread
#pragma omp parallel num_threads(nh)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    double sum = 0;  // in pair order over thread t's range of the near hits
    const std::size_t q0 = near.size() * t / static_cast<std::size_t>(nh),
                      q1 = near.size() * (t + 1) / static_cast<std::size_t>(nh);
    for (std::size_t q = q0; q < q1; ++q) {
      const std::uint32_t ja = nl.second[hits[near[std::min(q + kAhead, q1 - 1)]]];
      __builtin_prefetch(&p.radius[ja]);
      __builtin_prefetch(&r_before[ja]);
      const double d2 = hit_d2[near[q]];
      const std::uint32_t k = hits[near[q]];
      const std::uint32_t i = nl.first[k], j = nl.second[k];
      if (((state[i] | state[j]) & grew) == 0) continue;  // nothing grew
      // apart by a clear margin (most pairs): no overlap after, no root taken; the margin
      // (relative 1e-9, far above rounding) keeps the exact test below for the touching ones
      const double reach = p.radius[i] + p.radius[j];
      if (d2 > reach * reach * (1 + 1e-9)) continue;
      const double dist = std::sqrt(d2);
      const double before = r_before[i] + r_before[j] - dist,
                   after = p.radius[i] + p.radius[j] - dist;
      if (after <= 0) continue;
      sum += overlap_energy(sim, after, p.radius[i], p.material[i], p.radius[j], p.material[j]) -
             overlap_energy(sim, before, r_before[i], p.material[i], r_before[j], p.material[j]);
    }
    pair_energy[t] = sum;
  }
  for (int t = 1; t < nh; ++t) pair_energy[0] += pair_energy[static_cast<std::size_t>(t)];
  ledger.create(sim, pair_energy[0] + tally[0].wall_energy);
  if (tally[0].rebuild) sim.particles_changed();
}

}  // namespace comminute::breakage
