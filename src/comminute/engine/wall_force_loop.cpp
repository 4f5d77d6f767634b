#include "comminute/engine/wall_force_loop.hpp"

#include <algorithm>

#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

void WallForceLoop::run(ParticleStore& p, const MaterialTable& materials,
                        const std::vector<std::unique_ptr<Wall>>& walls,
                        const std::vector<WallContactRecord>& candidates,
                        const ContactPipeline& pipeline, ContactStateStore& state, double dt,
                        EnergyLedger& ledger, double& elastic,
                        std::vector<WallContactRecord>& touching) {
  const std::size_t nc = candidates.size();
  const int nt = nc >= kParallelMin / 2 ? max_threads() : 1;
  std::vector<std::size_t> begin(static_cast<std::size_t>(nt) + 1, nc);
  begin[0] = 0;
  for (int t = 1; t < nt; ++t) {
    std::size_t b = std::max(begin[t - 1], nc * t / nt);
    while (b > 0 && b < nc && candidates[b].particle == candidates[b - 1].particle) ++b;
    begin[t] = b;
  }
  struct WallTally {
    EnergyTally energy;
    std::vector<Vec3> force, torque;
    std::vector<WallContactRecord> touching;
  };
  std::vector<WallTally> part(static_cast<std::size_t>(nt));
  const Slots& slots = state.slots();
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    WallTally& mine = part[t];
    mine.force.assign(walls.size(), Vec3{});
    mine.torque.assign(walls.size(), Vec3{});
    std::vector<WallContact> found;
    for (std::size_t q = begin[t]; q < begin[t + 1]; ++q) {
      const WallContactRecord& c = candidates[q];
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
  touching.clear();
  for (const auto& mine : part) {
    for (std::size_t k = 0; k < walls.size(); ++k) {
      walls[k]->force += mine.force[k];
      walls[k]->torque += mine.torque[k];
    }
    mine.energy.book(ledger, elastic);
    touching.insert(touching.end(), mine.touching.begin(), mine.touching.end());
  }
}

}  // namespace comminute
