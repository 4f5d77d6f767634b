#pragma once
// Verlet neighbour list on a cell grid: a half list of candidate pairs (i < j by slot) within
// r_i + r_j + skin, rebuilt when some particle has moved more than skin/2 since the last build
// (or after insertion/removal). Stored as pair arrays (first, second, history) so that hot loops
// run over plain arrays; contact history is carried across rebuilds by particle ids.
#include <cstdint>
#include <vector>

#include "comminute/contact/contact_law.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class NeighborList {
 public:
  std::vector<std::uint32_t> first;     // slot i of each pair
  std::vector<std::uint32_t> second;    // slot j > i
  std::vector<ContactHistory> history;  // per pair
  std::vector<std::uint8_t> touching;   // 1 when the pair overlapped in the last force step

  std::size_t size() const { return first.size(); }

  // Builds the list for the current positions. The history of pairs that were touching is moved
  // over from the previous list, matched by particle ids (prev_ids: ids of the previous slots).
  void build(const ParticleStore& p, double skin, const std::vector<std::uint64_t>& prev_ids);
  // Slot order that sorts particles by grid cell (memory locality); cell edge = `cell`.
  static std::vector<std::size_t> cell_order(const ParticleStore& p, double cell);
};

}  // namespace comminute
