#pragma once
// Growth of fragments towards their full radius (docs/breakage.md). A fragment placed smaller than
// its final size carries pflag::growing and its final radius in the target field; each step it
// grows by at most growth_step of that radius, capped so that it creates at most an overlap of
// growth_overlap_ratio times the smaller radius with neighbours and walls, and within the pair
// list's reach margin. The elastic energy growth creates is booked in the ledger.
// Capped growth stops for good where a sustained load holds an overlap above that cap (a
// fragment in a compressed bed or the nip of a roll press stays shrunk, unloaded and unbroken,
// docs/breakage.md); pushing growth instead lets every overlap deepen by the ratio per step, so
// the fragment grows against the load and carries it at its full size.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "comminute/core/parallel.hpp"

namespace comminute {
class Simulation;
class ParticleStore;
}  // namespace comminute

namespace comminute::breakage {

class BreakageLedger;

class FragmentGrowth {
 public:
  FragmentGrowth(double overlap_ratio, double step, bool pushing = false)
      : eps_(overlap_ratio), step_(step), pushing_(pushing) {}

  // Counts the growing particles (after setup or a checkpoint).
  void recount(const ParticleStore& p);
  void started() { ++pending_; }  // a fragment placed smaller than its final size
  void dropped() { --pending_; }  // a growing fragment broke
  // Fragments still growing to full size.
  std::size_t pending() const { return pending_; }

  // One growth step of every growing particle; `target` is the index of the target-radius field.
  void grow(Simulation& sim, std::size_t target, BreakageLedger& ledger);

 private:
  double eps_;    // largest overlap growth may create, fraction of the smaller radius
  double step_;   // largest radius increment per step, fraction of the final radius
  bool pushing_;  // the overlap cap applies to the deepening per step, not to the overlap
  std::size_t pending_ = 0;
  // scratch of grow(), one entry per slot, kept between steps (no allocation and first touch of
  // fresh pages each step); filled on all threads
  std::vector<double> limit_, r_before_;
  std::vector<std::uint8_t> state_;
  std::vector<std::uint32_t> hit_pairs_;  // pairs with a growing particle, in list order
  // per hit pair: the squared distance (m2) of its centres when close enough to touch after
  // growth, else +inf; the energy pass reads it instead of both positions again
  std::vector<double> hit_d2_;
  // the hits close enough to touch after growth (finite hit_d2_), by position among the hits,
  // ascending: about a sixth of them in the breakage benchmark's bed, and the only ones the energy
  // pass visits
  std::vector<std::uint32_t> near_hits_;
  std::vector<std::uint32_t> free_slots_;  // growing particles with room to grow, ascending
  std::vector<std::vector<std::uint32_t>> select_parts_;  // per thread, for parallel_select
  OwnerScatterQueues<double> limit_queues_;               // owner_scatter's, for limit_
};

}  // namespace comminute::breakage
