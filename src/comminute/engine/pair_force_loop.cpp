#include "comminute/engine/pair_force_loop.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "comminute/core/parallel.hpp"
#include "comminute/engine/contact_run.hpp"
#include "comminute/engine/pair_split.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute {

namespace {
constexpr std::size_t kAhead = 16;  // pairs between a position's prefetch and its use
constexpr std::size_t kNoBlock = ~std::size_t{0};
constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;
struct Touching {  // a touching pair of a run: its particles and lever arms (m)
  std::uint32_t i, j;
  double ri, rj;
};
using PairRun = ContactRun<Touching>;
constexpr std::size_t kRun = PairRun::kSize;

}  // namespace

// What every thread of run() reads: the step's arrays, the pipeline and the state's columns.
struct PairForceLoop::Shared {
  ParticleStore& p;
  const MaterialTable& materials;
  const NeighborList& pairs;
  const PrunedPairs* near;
  const ContactPipeline& pipeline;
  ContactStateStore& state;
  double dt;
  const CollisionRecord* record;
  ContactStress* cs;
  bool armed, want_list;
  double threshold;
  const Slots& slots;
  bool rolling;
  std::uint8_t* active;
  std::array<const char*, 4> columns;  // the contact state's columns and their widths
  std::array<std::size_t, 4> widths;
  std::size_t ncolumns;
};

void PairForceLoop::thread_pairs(const Shared& s, int t) {
  ParticleStore& p = s.p;
  const MaterialTable& materials = s.materials;
  const NeighborList& pairs = s.pairs;
  const PrunedPairs* near = s.near;
  const ContactPipeline& pipeline = s.pipeline;
  ContactStateStore& state = s.state;
  const double dt = s.dt;
  const CollisionRecord* record = s.record;
  ContactStress* cs = s.cs;
  const bool armed = s.armed, want_list = s.want_list, rolling = s.rolling;
  const double threshold = s.threshold;
  const Slots& slots = s.slots;
  std::uint8_t* active = s.active;
  const auto& columns = s.columns;
  const auto& widths = s.widths;
  const std::size_t ncolumns = s.ncolumns;
  const auto& rows = pairs.rows();
  Vec3* F = p.f.data();
  Vec3* T = p.t.data();
  const Vec3 *X = p.x.data(), *V = p.v.data(), *W = p.w.data();
  const double *R = p.radius.data(), *M = p.mass.data(), *I = p.inertia.data();
  const std::uint16_t* mat = p.material.data();
  const std::uint32_t *first = pairs.first.data(), *second = pairs.second.data();
  const std::uint32_t own0 = ranges_.begin()[t], own1 = ranges_.begin()[t + 1];
  // the thread that holds a slot's first pair (NeighborList::first_owner) adds its loads to the
  // slot here, in pair order; a later thread queues them, in pair order, for the slot's owner
  // thread to add after the loop in thread order: either way each slot receives them in the
  // order of the whole list, whatever the split (a thread with every slot, as one thread, has no
  // need to look)
  const std::uint32_t* lowest = pairs.first_owner().data();
  const bool whole = own0 == 0 && own1 >= p.size();
  const std::uint32_t width = own1 - own0;  // (own0 <= s < own1 as one unsigned comparison)
  const auto alone =
      [ lowest, own0, width, whole ](std::uint32_t slot) __attribute__((always_inline)) {
    return whole || lowest[slot] - own0 < width;
  };
  auto& queued = cross_[t];
  queued.clear();
  auto& separated = ended_[t];
  separated.clear();
  StressPart* sp = cs ? &stress_[t] : nullptr;
  if (sp) {
    sp->cross.clear();
    sp->starts.clear();
    sp->contacts.clear();
  }
  // the energy of the contacts of each block of owners (pair_split.hpp), summed here and stored
  // when the next block begins: a block's rows are all this thread's
  EnergyTally tl;
  std::size_t block = kNoBlock;
  EnergyTally* tally = tally_.data();
  // the owner whose row is being summed (rows run over several runs of contacts): its row's
  // force, torque, Love–Weber moment and load-bearing count, from zero, added to the slot (or
  // queued) when its row ends
  // (the moment apart: its address is taken, which would keep the force and torque in memory)
  struct Row {
    std::uint32_t held = kNoSlot;
    Vec3 f, t;
  };
  Row row;
  SymTensor row_moment{};
  std::uint32_t row_bearing = 0;
  const auto end_row = [&](const Row& r) __attribute__((always_inline)) {
    if (r.held == kNoSlot) return;
    if (alone(r.held)) {
      F[r.held] += r.f;
      T[r.held] += r.t;
      if (armed) {
        for (std::size_t a = 0; a < 6; ++a) cs->moment[r.held][a] += row_moment[a];
        cs->load_bearing[r.held] += row_bearing;
      }
    } else {
      queued.push_back({r.held, r.f, r.t});
      if (armed) sp->cross.push_back({r.held, row_bearing, row_moment});
    }
  };
  const std::size_t k0 = rows[own0], k1 = rows[own1];
  // the touching pairs are gathered into runs (contact_run.hpp), evaluated in one call (the law
  // inlined in its loop), then their forces are added in pair order
  PairRun run;
  run.kinematics.dt = dt;
  std::array<Vec3, kRun> gap;  // x_i - x_j of the gathered pairs
  std::array<double, kRun> gap2, reach, dist;
  // (the lambdas always inlined: each version of thread_pairs gets its own copy)
  auto flush = [&]() __attribute__((always_inline)) {
    const std::size_t n = run.size;  // (a local, as in the gather below)
    if (n == 0) return;
    run.evaluate(pipeline, slots);
    const ForceColumns& o = run.forces;
    const KinematicsColumns& k = run.kinematics;
    // the row and the block's energy in locals over the run (registers), as the sums go on
    Row r = row;
    EnergyTally e = tl;
    std::size_t b = block;
    for (std::size_t c = 0; c < n; ++c) {
      const Vec3 nrm{k.nx[c], k.ny[c], k.nz[c]};
      const double fn = o.normal_force[c];
      const Vec3 ft{o.fx[c], o.fy[c], o.fz[c]}, rolling_torque{o.tx[c], o.ty[c], o.tz[c]};
      // by reference: a copy of the record stalls on its two stores
      const auto& [i, j, ri, rj] = run.who[c];
      if (i != r.held) {  // (the list is sorted by owner: a row's contacts come together)
        end_row(r);
        r.held = i;
        r.f = r.t = Vec3{};
        if (armed) {
          row_moment = SymTensor{};
          row_bearing = 0;
        }
        if (i / kSplitBlock != b) {  // (a block begins with a row)
          if (b != kNoBlock) tally[b] = e;
          e = EnergyTally{};
          b = i / kSplitBlock;
        }
      }
      e.add(o.damping_dissipation[c], o.friction_dissipation[c], o.stored_energy[c]);
      const Vec3 fc = fn * nrm + ft;
      r.f += fc;
      r.t += rolling_torque - ri * cross(nrm, ft);
      const Vec3 tj = -(rolling_torque + rj * cross(nrm, ft));
      const bool j_alone = alone(j);
      if (j_alone) {
        F[j] -= fc;
        T[j] += tj;
      } else {
        queued.push_back({j, -fc, tj});
      }
      if (armed) {  // Love–Weber: l_i = -ri n, l_j = +rj n, forces ±fc
        const std::uint32_t lb = fn > threshold ? 1 : 0;
        add_sym_outer(row_moment, fc, nrm, -ri);
        row_bearing += lb;
        if (j_alone) {
          add_sym_outer(cs->moment[j], fc, nrm, -rj);
          cs->load_bearing[j] += lb;
        } else {
          CrossMoment cm{j, lb, {}};
          add_sym_outer(cm.moment, fc, nrm, -rj);
          sp->cross.push_back(cm);
        }
        if (want_list)
          sp->contacts.push_back({i, static_cast<std::int32_t>(j), X[i], X[j], fc, fn});
      }
    }
    row = r;
    tl = e;
    block = b;
    run.clear();
  };
  // the pairs visited, by position m: the pruned list's (pair_at(m) = its m-th pair), or all of
  // [k0, k1) (pair_at(m) = m)
  const auto visit = [&](auto pair_at, std::size_t m0, std::size_t m1)
      __attribute__((always_inline)) {
    for (std::size_t m = m0; m < m1;) {
      // 1. gather the next run of touching pairs without a branch per pair (whether a pair
      // touches is unpredictable in a dense bed); a pair that separated is rare
      // (the run's count in a local while it grows: the run itself stays in memory, where a
      // store of a byte, active[k], could change it as far as the compiler knows)
      std::size_t n = run.size;
      for (; m < m1 && n < kRun; ++m) {
        const std::size_t k = pair_at(m);
        const std::uint32_t i = first[k], j = second[k];
        // the other particles are scattered in memory: their positions are asked for kAhead
        // pairs early, the fields read later (kinematics, forces) as soon as the pair is seen
        const std::uint32_t ja = second[pair_at(std::min(m + kAhead, m1 - 1))];
        __builtin_prefetch(&X[ja]);
        __builtin_prefetch(&R[ja]);
        __builtin_prefetch(&V[j]);
        __builtin_prefetch(&W[j]);
        __builtin_prefetch(&M[j]);
        __builtin_prefetch(&mat[j]);
        __builtin_prefetch(&F[j], 1);
        __builtin_prefetch(&T[j], 1);
        for (std::size_t c = 0; c < ncolumns; ++c)
          __builtin_prefetch(columns[c] + k * widths[c], 1);
        const Vec3 d = X[i] - X[j];
        const double rsum = R[i] + R[j];
        const double dist2 = norm2(d);
        const bool touches = dist2 < rsum * rsum;
        gap[n] = d;
        gap2[n] = dist2;
        reach[n] = rsum;
        run.index[n] = k;
        n += touches ? 1 : 0;
        if (!touches & (active[k] != 0)) {  // the bodies separated: the contact's state is gone
          if (record) separated.push_back({i, j, false, record->totals(state.at(k))});
          state.clear(k);
        }
      }
      run.size = n;
      // 2. the kinematics of the run's contacts; the distances' roots first, in a loop of their
      // own (independent roots overlap instead of each contact waiting on its own)
      for (std::size_t c = 0; c < n; ++c) dist[c] = std::sqrt(gap2[c]);
      for (std::size_t c = 0; c < n; ++c) {
        const std::size_t kc = run.index[c];
        const std::uint32_t i = first[kc], j = second[kc];
        if (sp && !active[kc]) sp->starts.push_back({i, static_cast<std::int32_t>(j)});
        active[kc] = 1;
        const double rsum = reach[c];
        const Vec3 nrm = gap[c] / dist[c];
        const double overlap = rsum - dist[c];
        const double ri = R[i] - 0.5 * overlap, rj = R[j] - 0.5 * overlap;
        const Vec3 vrel = V[i] - V[j] - cross(W[i], ri * nrm) - cross(W[j], rj * nrm);
        const double vn = dot(vrel, nrm);
        const Vec3 vt = vrel - vn * nrm;
        KinematicsColumns& kin = run.kinematics;
        kin.nx[c] = nrm.x, kin.ny[c] = nrm.y, kin.nz[c] = nrm.z;
        kin.overlap[c] = overlap;
        kin.overlap_rate[c] = -vn;
        kin.vx[c] = vt.x, kin.vy[c] = vt.y, kin.vz[c] = vt.z;
        kin.effective_radius[c] = R[i] * R[j] / rsum;
        kin.effective_mass[c] = M[i] * M[j] / (M[i] + M[j]);
        if (rolling) {  // read by the rolling models only
          const Vec3 dw = W[i] - W[j];
          kin.wx[c] = dw.x, kin.wy[c] = dw.y, kin.wz[c] = dw.z;
          kin.effective_inertia[c] = I[i] * I[j] / (I[i] + I[j]);
        }
        run.parameters[c] = &materials.pair(mat[i], mat[j]);
        run.who[c] = {i, j, ri, rj};
      }
      // 3. the law and the forces
      if (run.full() || m == m1) flush();
    }
  };
  if (near != nullptr) {
    const auto [m0, m1] = near->range(k0, k1);
    const std::uint32_t* kept = near->pairs().data();
    visit(
        [kept](std::size_t m)
            __attribute__((always_inline)) { return static_cast<std::size_t>(kept[m]); },
        m0, m1);
  } else {
    visit(
        [](std::size_t m) __attribute__((always_inline)) { return m; }, k0, k1);
  }
  end_row(row);
  if (block != kNoBlock) tally[block] = tl;
}

void PairForceLoop::run(ParticleStore& p, const MaterialTable& materials, const NeighborList& pairs,
                        const PrunedPairs* near, const ContactPipeline& pipeline,
                        ContactStateStore& state, double dt, EnergyLedger& ledger, double& elastic,
                        std::vector<EndedContact>& ended) {
  const std::size_t n = p.size();
  const std::size_t npairs = pairs.size();
  const int nt = npairs >= 2 * kParallelMin ? max_threads() : 1;
  // the threads split the owners' rows by cost, in blocks of owners (engine/pair_split.hpp), at
  // the start of their region: the cost of each block is summed by the threads together, then
  // one places the split by the threads' shares (their measured speeds, learn_speeds)
  const auto unt = static_cast<std::size_t>(nt);
  if (share_.size() != unt) {  // (a new thread count: equal shares until measured)
    share_.assign(unt, 1.0 / static_cast<double>(nt));
    speed_.assign(unt, 0.0);
  } else if (nt > 1) {
    learn_speeds();  // (from the last split, before it is replaced)
  }
  auto& split = split_;
  auto& owner_begin = ranges_.begin();
  owner_begin.assign(unt + 1, 0);
  owner_begin[unt] = static_cast<std::uint32_t>(n);
  const std::size_t blocks = split_blocks(n);
  block_cost_.resize(blocks);
  split.assign(unt + 1, blocks);
  split[0] = 0;
  std::vector<double>& seconds = ranges_.seconds();
  seconds.assign(unt, 0.0);
  const std::uint32_t* rows = pairs.rows().data();
  cross_.resize(static_cast<std::size_t>(nt));
  ended_.resize(static_cast<std::size_t>(nt));
  const CollisionRecord* record = pipeline.collisions();
  ContactStress* cs = pipeline.stress();
  const bool armed = cs && cs->armed();
  const bool want_list = armed && cs->contact_list_wanted();
  const double threshold = cs ? cs->threshold() : 0.0;
  if (cs) stress_.resize(static_cast<std::size_t>(nt));
  auto& tally = tally_;
  tally.assign(blocks, EnergyTally{});
  const Slots& slots = state.slots();
  const bool rolling = pipeline.has_rolling();
  std::uint8_t* active = state.active.data();
  // the contact state's columns (the law's spring, ...): a touching pair's slots are read by the
  // law a run later, so each pair's are asked for as soon as the pair is seen
  std::array<const char*, 4> columns{};
  std::array<std::size_t, 4> widths{};
  std::size_t ncolumns = 0;
  const auto add_columns = [&](const auto& kind, std::size_t width) {
    for (const auto* c : kind)
      if (c != nullptr && ncolumns < columns.size()) {
        columns[ncolumns] = reinterpret_cast<const char*>(c);
        widths[ncolumns++] = width;
      }
  };
  add_columns(slots.vec3, sizeof(Vec3));
  add_columns(slots.f64, sizeof(double));
  add_columns(slots.f32, sizeof(float));
  const Shared shared{p,     materials, pairs,  near,    pipeline,  state,
                      dt,    record,    cs,     armed,   want_list, threshold,
                      slots, rolling,   active, columns, widths,    ncolumns};
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    const auto ut = static_cast<std::size_t>(t);
    if (nt > 1) {
      split_block_costs(rows, active, n, blocks * ut / unt, blocks * (ut + 1) / unt,
                        block_cost_.data());
#pragma omp barrier
#pragma omp single
      {
        split_blocks_by_share(block_cost_.data(), blocks, share_, split);
        for (std::size_t u = 1; u < unt; ++u)
          owner_begin[u] = static_cast<std::uint32_t>(std::min(n, split[u] * kSplitBlock));
      }  // (the threads wait here for the split)
    }
    const double start = omp_get_wtime();
    thread_pairs(shared, t);
    seconds[ut] += omp_get_wtime() - start;
    if (nt > 1) {
      // each thread adds the shares queued for its own particles, in thread order (the same sums
      // as adding every list in turn), so that their forces stay in its core's cache
#pragma omp barrier
      const std::uint32_t own0 = owner_begin[t], own1 = owner_begin[t + 1];
      for (const auto& list : cross_)
        for (const auto& c : list)
          if (c.particle >= own0 && c.particle < own1) {
            p.f[c.particle] += c.force;
            p.t[c.particle] += c.torque;
          }
    }
  }
  for (const auto& tl : tally) tl.book(ledger, elastic);
  for (const auto& list : ended_) ended.insert(ended.end(), list.begin(), list.end());
  if (cs)
    for (const auto& part : stress_) {
      for (const auto& c : part.cross) {
        for (std::size_t a = 0; a < 6; ++a) cs->moment[c.particle][a] += c.moment[a];
        cs->load_bearing[c.particle] += c.load_bearing;
      }
      cs->starts.insert(cs->starts.end(), part.starts.begin(), part.starts.end());
      cs->contacts.insert(cs->contacts.end(), part.contacts.begin(), part.contacts.end());
    }
}

void PairForceLoop::learn_speeds() {
  const std::size_t nt = share_.size();
  const std::vector<double>& seconds = ranges_.seconds();
  if (seconds.size() != nt || split_.size() != nt + 1) return;  // not placed for these threads
  double sum = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    std::uint64_t cost = 0;
    for (std::size_t b = split_[t]; b < split_[t + 1]; ++b) cost += block_cost_[b];
    if (cost > 0 && seconds[t] > 0) {
      const double speed = static_cast<double>(cost) / seconds[t];
      speed_[t] = speed_[t] > 0 ? (1 - kSpeedWeight) * speed_[t] + kSpeedWeight * speed : speed;
    }
    sum += speed_[t];
  }
  for (std::size_t t = 0; t < nt; ++t)
    if (!(speed_[t] > 0)) return;  // a thread not measured yet: the shares stay
  for (std::size_t t = 0; t < nt; ++t) share_[t] = speed_[t] / sum;
}

}  // namespace comminute
