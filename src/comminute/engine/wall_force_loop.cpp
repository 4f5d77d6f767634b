#include "comminute/engine/wall_force_loop.hpp"

#include <algorithm>
#include <span>

#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

namespace {
constexpr std::size_t kChunk = 256;  // candidates per chunk (about)
constexpr std::size_t kAhead = 8;    // candidates between a particle's prefetch and its use

void prefetch_particle(const ParticleStore& p, std::uint32_t i) {
  __builtin_prefetch(&p.x[i]);
  __builtin_prefetch(&p.radius[i]);
  __builtin_prefetch(&p.v[i]);
  __builtin_prefetch(&p.w[i]);
  __builtin_prefetch(&p.mass[i]);
  __builtin_prefetch(&p.material[i]);
  __builtin_prefetch(&p.f[i], 1);
  __builtin_prefetch(&p.t[i], 1);
}
}  // namespace

void WallForceLoop::run(ParticleStore& p, const MaterialTable& materials,
                        const std::vector<std::unique_ptr<Wall>>& walls,
                        const std::vector<WallContactRecord>& candidates,
                        const WallElementLists& elements, const ContactPipeline& pipeline,
                        ContactStateStore& state, double dt, EnergyLedger& ledger, double& elastic,
                        std::vector<WallContactRecord>& touching, std::vector<EndedContact>& ended,
                        const ParticleRanges& ranges) {
  const std::size_t nc = candidates.size();
  // chunks of about kChunk candidates, each ending at a particle boundary
  const std::size_t nchunk = std::max<std::size_t>(1, (nc + kChunk - 1) / kChunk);
  auto& begin = begin_;
  begin.assign(nchunk + 1, nc);
  begin[0] = 0;
  for (std::size_t c = 1; c < nchunk; ++c) {
    std::size_t b = std::max(begin[c - 1], nc * c / nchunk);
    while (b > 0 && b < nc && candidates[b].particle == candidates[b - 1].particle) ++b;
    begin[c] = b;
  }
  const int nt = nc >= kParallelMin / 2 ? max_threads() : 1;
  const CollisionRecord* record = pipeline.collisions();
  if (parts_.size() < nchunk) parts_.resize(nchunk);
  if (scratch_.size() < static_cast<std::size_t>(nt)) scratch_.resize(static_cast<std::size_t>(nt));
  auto& part = parts_;
  const Slots& slots = state.slots();
  ContactStress* cs = pipeline.stress();
  const bool armed = cs && cs->armed();
  const bool list = armed && cs->contact_list_wanted();
  const bool rolling = pipeline.has_rolling();
  // which thread takes which chunk does not change the results: a chunk's particles are its own,
  // and its sums are combined in chunk order below. A thread takes the chunks that start in its
  // particle range (particle_ranges.hpp), so that it works on particles whose values its core
  // holds; with no ranges for as many threads, an equal share of the chunks. (A chunk may start at
  // the end, nc, when the last particle's candidates filled the chunk before.)
  auto& first_chunk = first_chunk_;
  first_chunk.assign(static_cast<std::size_t>(nt) + 1, nchunk);
  first_chunk[0] = 0;
  for (int t = 1; t < nt; ++t) {
    const auto ut = static_cast<std::size_t>(t);
    if (ranges.threads() != nt) {
      first_chunk[ut] = nchunk * ut / static_cast<std::size_t>(nt);
      continue;
    }
    const std::size_t from = ranges.of(t, p.size()).first;
    first_chunk[ut] = static_cast<std::size_t>(
        std::partition_point(
            begin.begin() + static_cast<std::ptrdiff_t>(first_chunk[ut - 1]),
            begin.begin() + static_cast<std::ptrdiff_t>(nchunk),
            [&](std::size_t b) { return b < nc && candidates[b].particle < from; }) -
        begin.begin());
  }
#pragma omp parallel num_threads(nt)
  for (int t = thread_id(); t < nt; t += omp_get_num_threads()) {
    const double start = omp_get_wtime();
    LookUp& look = scratch_[static_cast<std::size_t>(t)];
    const auto ut = static_cast<std::size_t>(t);
    for (std::size_t chunk = first_chunk[ut]; chunk < first_chunk[ut + 1]; ++chunk) {
      WallTally& mine = part[chunk];
      mine.energy = {};
      mine.force.assign(walls.size(), Vec3{});
      mine.torque.assign(walls.size(), Vec3{});
      mine.touching.clear();
      mine.wear.clear();
      mine.ended.clear();
      mine.starts.clear();
      mine.contacts.clear();
      // the touching contacts wait in a run for the law, evaluated in one call (the law inlined
      // in its loop, as in the pair loop); their forces are then added in candidate order, so
      // every particle and wall sums them in the same order as one by one
      ContactRun<Touch>& run = look.run;
      run.kinematics.dt = dt;
      const auto evaluate_run = [&]() {
        if (run.size == 0) return;
        run.evaluate(pipeline, slots);
        for (std::size_t r = 0; r < run.size; ++r) {
          const ContactForces out = run.forces.at(r);
          const auto& [i, hit, vwall, ri] = run.who[r];
          const WallContactRecord& c = candidates[run.index[r]];
          const Wall& w = *walls[c.wall];
          const Vec3& nrm = hit.normal;
          const Vec3 fc = out.normal_force * nrm + out.tangential_force;
          p.f[i] += fc;
          p.t[i] += out.rolling_torque - ri * cross(nrm, out.tangential_force);
          mine.force[c.wall] -= fc;
          mine.torque[c.wall] -= cross(hit.point - w.kinematics.center, fc);
          if (armed) {  // Love–Weber: a particle's slots are all in this thread's range
            add_sym_outer(cs->moment[i], fc, hit.point - p.x[i], 1.0);
            if (list)
              mine.contacts.push_back({i, -1 - static_cast<std::int32_t>(c.wall), p.x[i], hit.point,
                                       fc, out.normal_force});
          }
          mine.energy.add(out);
          // the work of the wall's force on the particle
          mine.energy.wall_work += dot(fc, vwall) * dt;
          if (w.tracks_wear() && hit.element >= 0)
            mine.wear.push_back({c.wall, hit.element, out.normal_force,
                                 norm(run.kinematics.at(r).tangential_velocity) * dt});
          WallContactRecord rec = c;
          rec.feature = hit.feature;
          rec.candidate = static_cast<std::uint32_t>(run.index[r]);
          mine.touching.push_back(rec);
        }
        run.clear();
      };
      // candidate q touching as `hit` joins the run (not touching: its state is cleared)
      const auto touch = [&](std::size_t q, const WallContact& hit) {
        const WallContactRecord& c = candidates[q];
        const std::uint32_t i = c.particle;
        const Wall& w = *walls[c.wall];
        if (hit.overlap <= 0) {
          if (state.active[q]) {
            if (record) mine.ended.push_back({i, c.wall, true, record->totals(state.at(q))});
            state.clear(q);
          }
          return;
        }
        if (cs && !state.active[q])
          mine.starts.push_back({i, -1 - static_cast<std::int32_t>(c.wall)});
        state.active[q] = 1;
        const Vec3 nrm = hit.normal;
        const double overlap = hit.overlap;
        const double ri = p.radius[i] - overlap;
        const Vec3 vwall = w.kinematics.velocity_at(hit.point);
        const Vec3 vrel = p.v[i] - cross(p.w[i], ri * nrm) - vwall;
        const double vn = dot(vrel, nrm);
        ContactKinematics ck;  // (its dt: the run's)
        ck.normal = nrm;
        ck.overlap = overlap;
        ck.overlap_rate = -vn;
        ck.tangential_velocity = vrel - vn * nrm;
        ck.effective_radius = p.radius[i];
        ck.effective_mass = p.mass[i];
        if (rolling) {  // read by the rolling models only (as in the pair loop)
          ck.relative_angular_velocity = p.w[i];
          ck.effective_inertia = p.inertia[i];
        }
        run.kinematics.set(run.size, ck);
        run.parameters[run.size] = &materials.pair(p.material[i], w.material);
        run.index[run.size] = q;
        run.who[run.size] = {i, hit, vwall, ri};
        ++run.size;
        if (run.full()) evaluate_run();
      };
      auto& found = look.found;
      auto& hits = look.hits;
      std::size_t q = begin[chunk];
      while (q < begin[chunk + 1]) {
        // the candidates of one particle, [q, end): all are looked up first, so that a contact
        // passing to an adjacent feature of the same wall can take over the old one's history
        std::size_t end = q + 1;
        while (end < begin[chunk + 1] && candidates[end].particle == candidates[q].particle) ++end;
        // the particles near a wall lie scattered in the store: the fields of a particle a few
        // candidates ahead are asked for now, to be at hand when its turn comes
        prefetch_particle(p, candidates[std::min(q + kAhead, begin[chunk + 1] - 1)].particle);
        hits.assign(end - q, WallContact{{}, {}, 0, 0, -1});
        for (std::size_t k = q; k < end; ++k) {
          const WallContactRecord& c = candidates[k];
          if (k == q || c.wall != candidates[k - 1].wall) {  // one look-up per wall (a mesh may
            found.clear();                                   // list many features)
            const Wall& w = *walls[c.wall];
            const auto listed = elements.find(c.wall, c.particle);
            if (listed)
              w.contacts_among(p.x[c.particle], p.radius[c.particle], 0.0, *listed, found);
            else
              w.contacts(p.x[c.particle], p.radius[c.particle], 0.0, found);
          }
          for (const auto& f : found)  // a full-scan wall's candidate (feature < 0) takes any
            if (f.feature == c.feature || c.feature < 0) hits[k - q] = f;
        }
        for (std::size_t k = q; k < end; ++k) {
          if (hits[k - q].overlap <= 0 || state.active[k]) continue;
          const Wall& w = *walls[candidates[k].wall];
          for (std::size_t j = q; j < end; ++j)
            if (state.active[j] && hits[j - q].overlap <= 0 &&
                candidates[j].wall == candidates[k].wall &&
                w.continues(candidates[j].feature, hits[k - q].feature)) {
              state.move(j, k);
              break;
            }
        }
        for (std::size_t k = q; k < end; ++k) touch(k, hits[k - q]);
        q = end;
      }
      evaluate_run();
    }
    if (ranges.threads() == nt) ranges.add_seconds(t, omp_get_wtime() - start);
  }
  touching.clear();
  for (const auto& mine : std::span(part.data(), nchunk)) {
    for (std::size_t k = 0; k < walls.size(); ++k) {
      walls[k]->force += mine.force[k];
      walls[k]->torque += mine.torque[k];
    }
    for (const auto& e : mine.wear) walls[e.wall]->wear(e.element, e.fn, e.slip);
    mine.energy.book(ledger, elastic);
    touching.insert(touching.end(), mine.touching.begin(), mine.touching.end());
    ended.insert(ended.end(), mine.ended.begin(), mine.ended.end());
    if (cs) {
      cs->starts.insert(cs->starts.end(), mine.starts.begin(), mine.starts.end());
      cs->contacts.insert(cs->contacts.end(), mine.contacts.begin(), mine.contacts.end());
    }
  }
}

}  // namespace comminute
