// The first owner of each slot (neighbor/first_owners.hpp): the lowest `first` among the pairs that
// hold the slot, which the pair force loop uses to decide which thread adds to a slot directly.
// Checked against a hand-worked list, and pairs appended later (in-place updates) taken in
// incrementally must give what a pass over the whole list gives.
#include <gtest/gtest.h>

#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/neighbor/first_owners.hpp"

using namespace comminute;

TEST(FirstOwners, LowestOwnerOfEverySlotOnAHandWorkedList) {
  // rows of owners 0, 1, 3 (slot 2 owns nothing; slot 5 is in no pair); pair (3, 1) is listed the
  // other way round, as after an in-place update
  const std::vector<std::uint32_t> first{0, 0, 1, 3, 3}, second{2, 4, 2, 1, 4};
  FirstOwners f;
  f.find(first, second, 6, 0);
  EXPECT_EQ(f.of_slots(), (std::vector<std::uint32_t>{0, 1, 0, 3, 0, FirstOwners::kNone}));
}

TEST(FirstOwners, AppendedPairsTakenInEqualAWholePass) {
  Rng rng(3, 0);
  const std::size_t n0 = 500, n = 600;
  std::vector<std::uint32_t> first, second;
  for (std::uint32_t i = 0; i + 1 < n0; ++i)  // rows of the kept slots, partners above them
    for (int k = 0; k < 4; ++k) {
      first.push_back(i);
      second.push_back(i + 1 + static_cast<std::uint32_t>(rng.uniform() * (n0 - 1 - i)));
    }
  FirstOwners incremental;
  incremental.find(first, second, n0, 0);
  const std::size_t m0 = first.size();
  for (auto s = static_cast<std::uint32_t>(n0); s < n; ++s)  // appended rows, partners below
    for (int k = 0; k < 3; ++k) {
      first.push_back(s);
      second.push_back(static_cast<std::uint32_t>(rng.uniform() * s));
    }
  incremental.find(first, second, n, m0);
  FirstOwners whole;
  whole.find(first, second, n, 0);
  EXPECT_EQ(incremental.of_slots(), whole.of_slots());
  // an appended slot's first pair is its own row (its other pairs come from later rows)
  for (std::size_t s = n0; s < n; ++s) EXPECT_EQ(whole.of_slots()[s], s);
  EXPECT_EQ(whole.of_slots()[0], 0U);
}
