#pragma once
// The pairs of a Verlet list that may touch soon: a sub-list pruned from the neighbour list with a
// buffer smaller than its skin, and pruned again once particles may have moved half that buffer
// (dynamic pruning, Páll et al., J. Chem. Phys. 153 (2020) 134110, sec. II C). The pair force loop
// visits these pairs instead of the whole list. A pair left out cannot touch before the next prune,
// so the loop finds the same touching pairs in the same order as on the whole list: the forces are
// the same bits. Geometry only: which pairs, by their index in the list.
#include <cstdint>
#include <utility>
#include <vector>

#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class PrunedPairs {
 public:
  // Keeps pair k of `list` when |x_i - x_j| < r_i + r_j + buffer (m), when i or j is growing
  // (pflag::growing: its radius changes), or when keep[k] != 0 (may be null). Ascending pair
  // indices; the same list on any number of threads.
  void prune(const ParticleStore& p, const NeighborList& list, double buffer,
             const std::uint8_t* keep);
  // Indices into the list of the kept pairs, ascending.
  const std::vector<std::uint32_t>& pairs() const { return pairs_; }
  // The positions in pairs() of the kept pairs among the list's pairs [k0, k1).
  std::pair<std::size_t, std::size_t> range(std::size_t k0, std::size_t k1) const;

 private:
  // keeps(k0, k1, part) appends the kept ones of [k0, k1) to part, on each thread its own range;
  // `out` gets them all, ascending
  template <class Keeps>
  void select(std::size_t n, std::vector<std::uint32_t>& out, Keeps keeps);
  std::vector<std::uint32_t> pairs_;
  std::vector<std::vector<std::uint32_t>> parts_;  // each thread's kept pairs while selecting
  std::vector<std::size_t> offsets_;
};

}  // namespace comminute
