#pragma once
#include <cstdint>

namespace comminute {

// A particle–wall contact candidate, keyed by particle id, wall and feature; its state is in the
// engine's wall-contact store at index `candidate`. Simulation::wall_contacts() lists those
// touching in the last force computation.
struct WallContactRecord {
  std::uint32_t particle = 0;  // current slot
  std::uint32_t wall = 0;
  std::int32_t feature = 0;
  std::uint32_t candidate = 0;  // index in the candidate list (and the wall-contact store)
  std::uint64_t id = 0;         // particle id
};

}  // namespace comminute
