#pragma once
// The particle–particle force loop. Each thread owns a contiguous range of particle slots and the
// pairs they own (pairs are grouped by owner), split so that the threads finish together: by the
// cost of the pairs and by each thread's measured speed (a processor shared with other work runs
// slower for minutes at a time). The split decides the speed, never the result: the thread that
// holds a slot's first pair adds the slot's loads directly, in pair order; a later thread's loads
// for it queue, in pair order, and the slot's owner thread adds them after the loop in thread
// order; an owner's own row is summed from zero and added when the row ends. So every slot
// receives its loads in the order of the whole list, and the energy is summed per block of owners
// in block order: the results are the same bit for bit for any split and any thread count. No
// atomics, no per-thread copies of the force arrays.
#include <cstdint>
#include <vector>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/vector_clones.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/ended_contact.hpp"
#include "comminute/engine/energy_tally.hpp"
#include "comminute/engine/particle_ranges.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/neighbor/pruned_pairs.hpp"
#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class PairForceLoop {
 public:
  // Adds the contact forces and torques of every touching pair to p.f, p.t, updates `state`
  // (active flags, slots), books the step's dissipation in `ledger` and adds the elastic energy
  // held in the contacts to `elastic` (J), thread by thread in order. When the pipeline keeps
  // the collision record, appends the pairs that separated to `ended`, in pair order. When the
  // pipeline carries a ContactStress, lists the contacts that began and, on armed steps, fills its
  // moments, counts and contact list (the other particle's share queued like its force, lists in
  // thread order). With `near` (not null) it visits only the pairs of `pairs` that `near` kept:
  // every pair that may touch.
  void run(ParticleStore& p, const MaterialTable& materials, const NeighborList& pairs,
           const PrunedPairs* near, const ContactPipeline& pipeline, ContactStateStore& state,
           double dt, EnergyLedger& ledger, double& elastic, std::vector<EndedContact>& ended);
  // The threads' particle ranges this loop placed in its last run (particle_ranges.hpp), which
  // the step's other per-particle loops follow.
  const ParticleRanges& ranges() const { return ranges_; }

 private:
  struct Shared;  // what every thread of run() reads (pair_force_loop.cpp)
  // One thread's share of run(): the pairs owned by particles [ranges_.begin()[t],
  // ranges_.begin()[t + 1]), or the pruned ones among them. In AVX-512, AVX2 and baseline versions
  // (core/vector_clones.hpp).
  COMMINUTE_VECTOR_CLONES void thread_pairs(const Shared& s, int t);

  struct CrossForce {  // a pair's share for a particle owned by another thread
    std::uint32_t particle;
    Vec3 force, torque;
  };
  std::vector<std::vector<CrossForce>> cross_;    // per thread, reused
  std::vector<std::vector<EndedContact>> ended_;  // per thread, reused
  // Takes the seconds the threads spent on the last ranges (this loop's, and every loop's that
  // followed the ranges: ParticleRanges::seconds) into their speeds and the shares of the next
  // split: a thread's speed is the cost of its pairs per second of all that, so the shares settle
  // where the threads take equal time.
  void learn_speeds();
  static constexpr double kSpeedWeight = 0.2;  // of the last step in the threads' speeds
  struct CrossMoment {  // a pair's Love–Weber share for a particle owned by another thread
    std::uint32_t particle;
    std::uint32_t load_bearing;
    SymTensor moment;
  };
  struct StressPart {  // per thread, reused
    std::vector<CrossMoment> cross;
    std::vector<ContactStart> starts;
    std::vector<ContactRecord> contacts;
  };
  std::vector<StressPart> stress_;
  // reused from step to step: the threads' ranges of owner blocks, their first owned particles,
  // the blocks' costs and energy, the threads' seconds in the loop, speeds and shares
  std::vector<std::size_t> split_;
  ParticleRanges ranges_;                  // the threads' first owned particles, and the end
  std::vector<std::uint64_t> block_cost_;  // the cost of each block of owners (pair_split.hpp)
  std::vector<EnergyTally> tally_;         // per block of owners
  std::vector<double> speed_, share_;
};

}  // namespace comminute
