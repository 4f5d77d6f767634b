// The threads' particle ranges (engine/particle_ranges.hpp): whatever the ranges were placed for,
// the per-particle loops must visit every slot exactly once, or a particle would skip its
// integration or be integrated twice.
#include <gtest/gtest.h>

#include <vector>

#include "comminute/engine/particle_ranges.hpp"

namespace comminute {
namespace {

// How often for_each_range visits each of n slots.
std::vector<int> visits(const ParticleRanges& ranges, std::size_t n, int threads) {
  std::vector<int> seen(n, 0);
  for_each_range(ranges, n, threads, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t i = b; i < e; ++i) ++seen[i];  // ranges are disjoint: no race
  });
  return seen;
}

TEST(ParticleRanges, EvenSplitCoversEverySlotOnce) {
  ParticleRanges r;
  r.split_evenly(10, 3);
  ASSERT_EQ(r.threads(), 3);
  EXPECT_EQ(r.of(0, 10), (std::pair<std::size_t, std::size_t>{0, 3}));
  EXPECT_EQ(r.of(1, 10), (std::pair<std::size_t, std::size_t>{3, 6}));
  EXPECT_EQ(r.of(2, 10), (std::pair<std::size_t, std::size_t>{6, 10}));
  EXPECT_EQ(visits(r, 10, 3), std::vector<int>(10, 1));
}

TEST(ParticleRanges, PlacedRangesFollowTheSlotsWhenTheirNumberChanged) {
  ParticleRanges r;
  r.begin() = {0, 7, 12};  // placed for 12 slots (say owned and ghosts)
  // fewer slots now (ghosts dropped): the ranges are cut
  EXPECT_EQ(r.of(0, 9), (std::pair<std::size_t, std::size_t>{0, 7}));
  EXPECT_EQ(r.of(1, 9), (std::pair<std::size_t, std::size_t>{7, 9}));
  // fewer than the second range's start: it is empty
  EXPECT_EQ(r.of(1, 5), (std::pair<std::size_t, std::size_t>{5, 5}));
  // more slots now (particles inserted): the last range reaches them
  EXPECT_EQ(r.of(1, 20), (std::pair<std::size_t, std::size_t>{7, 20}));
  for (std::size_t n : {0u, 5u, 9u, 12u, 20u}) EXPECT_EQ(visits(r, n, 2), std::vector<int>(n, 1));
}

TEST(ParticleRanges, OtherThreadCountSplitsEvenly) {
  ParticleRanges r;
  r.begin() = {0, 7, 12};  // two threads' ranges, asked for three and for one
  EXPECT_EQ(visits(r, 12, 3), std::vector<int>(12, 1));
  EXPECT_EQ(visits(r, 12, 1), std::vector<int>(12, 1));
  ParticleRanges none;  // never placed
  EXPECT_EQ(visits(none, 8, 2), std::vector<int>(8, 1));
}

}  // namespace
}  // namespace comminute
