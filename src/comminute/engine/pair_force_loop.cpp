#include "comminute/engine/pair_force_loop.hpp"

#include <cmath>

#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

namespace {
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

void PairForceLoop::run(ParticleStore& p, const MaterialTable& materials, const NeighborList& pairs,
                        const ContactPipeline& pipeline, ContactStateStore& state, double dt,
                        EnergyLedger& ledger, double& elastic) {
  const std::size_t n = p.size();
  const std::size_t npairs = pairs.size();
  const int nt = npairs >= 2 * kParallelMin ? max_threads() : 1;
  const auto& rows = pairs.rows();
  // balance by cost: a touching pair (contact law) costs several times a distance check
  const auto& touching = state.active;
  const auto split =
      balanced_split(npairs, nt, [&](std::size_t k) { return 1.0 + 6.0 * touching[k]; });
  std::vector<std::uint32_t> owner_begin(static_cast<std::size_t>(nt) + 1, 0);
  owner_begin[static_cast<std::size_t>(nt)] = static_cast<std::uint32_t>(n);
  for (int t = 1; t < nt; ++t)
    owner_begin[t] = split[t] < npairs ? pairs.first[split[t]] : static_cast<std::uint32_t>(n);
  cross_.resize(static_cast<std::size_t>(nt));
  std::vector<EnergyTally> tally(static_cast<std::size_t>(nt));
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
    EnergyTally tl;  // local: threads' tallies side by side in memory would share a cache line
    const std::size_t k0 = rows[own0], k1 = rows[own1];
    ContactKinematics ck;
    ck.dt = dt;
    for (std::size_t k = k0; k < k1; ++k) {
      const std::uint32_t i = pairs.first[k], j = pairs.second[k];
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
  for (const auto& tl : tally) tl.book(ledger, elastic);
}

}  // namespace comminute
