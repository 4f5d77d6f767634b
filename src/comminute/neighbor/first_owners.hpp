#pragma once
// Per slot, the lowest owner (`first`) among the pairs of a half list that hold the slot: its
// first pair in the list (kNone for a slot in no pair). A loop over the rows in list order meets
// a slot's pairs from this row on, so the pair force loop lets the thread with this row add to the
// slot directly and the later threads queue their loads behind it (engine/pair_force_loop.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace comminute {

class FirstOwners {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // Slots [0, n) of the list (first, second): its pairs from `from` on taken into what the slots
  // hold already (from = 0: made afresh from all pairs; the pairs before `from` unchanged).
  void find(const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& second,
            std::size_t n, std::size_t from);
  const std::vector<std::uint32_t>& of_slots() const { return lowest_; }

 private:
  std::vector<std::uint32_t> lowest_;  // by slot
};

}  // namespace comminute
