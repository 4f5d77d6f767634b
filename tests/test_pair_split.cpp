// The pair force loop splits a step's pairs between its threads by cost (a touching pair 7, a
// listed pair that does not touch 1). The split is summed in integers, block by block; it must be
// the split of the plain running sum compared with t / nt of the total, so these tests hold it to
// that definition written out pair by pair, on random and on lopsided lists.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/engine/pair_split.hpp"

using namespace comminute;

namespace {

// The definition: thread t starts one past the first pair where the running cost reaches
// t / nt of the total.
std::vector<std::size_t> split_by_definition(const std::vector<std::uint8_t>& active, int nt) {
  const std::size_t n = active.size();
  std::vector<std::size_t> at(static_cast<std::size_t>(nt) + 1, n);
  at[0] = 0;
  double total = 0;
  for (auto a : active) total += 1.0 + 6.0 * a;
  double sum = 0;
  int t = 1;
  for (std::size_t k = 0; k < n && t < nt; ++k) {
    sum += 1.0 + 6.0 * active[k];
    while (t < nt && sum >= total * t / nt) at[static_cast<std::size_t>(t++)] = k + 1;
  }
  return at;
}

// The split as the pair force loop makes it, the block costs summed in one share.
std::vector<std::size_t> split(const std::vector<std::uint8_t>& active, int nt) {
  std::vector<std::uint64_t> cost(pair_split_blocks(active.size()));
  pair_block_costs(active.data(), active.size(), 0, cost.size(), cost.data());
  std::vector<std::size_t> at{99};  // reused storage: stale content must not matter
  split_from_block_costs(active.data(), active.size(), nt, cost.data(), at);
  return at;
}

}  // namespace

TEST(PairSplit, EqualsTheRunningSumDefinitionOnRandomLists) {
  Rng rng(7, 0);
  // sizes around and across the block of 4096 pairs, and a bed-sized list
  for (std::size_t n : {0UL, 1UL, 2UL, 5UL, 4095UL, 4096UL, 4097UL, 12289UL, 444000UL})
    for (double touching : {0.0, 0.3, 0.55, 1.0}) {
      std::vector<std::uint8_t> active(n);
      for (auto& a : active) a = rng.uniform() < touching ? 1 : 0;
      for (int nt : {1, 2, 3, 7, 16})
        EXPECT_EQ(split(active, nt), split_by_definition(active, nt))
            << "n " << n << " touching " << touching << " threads " << nt;
    }
}

TEST(PairSplit, LopsidedListPutsTheSplitWhereTheContactsAre) {
  // the first 10000 pairs all touch, the next 60000 do not: cost 70000 + 60000, half at 65000,
  // reached inside the touching block at pair 9286 (9286 * 7 = 65002)
  std::vector<std::uint8_t> active(70000, 0);
  for (std::size_t k = 0; k < 10000; ++k) active[k] = 1;
  const auto at = split(active, 2);
  ASSERT_EQ(at.size(), 3U);
  EXPECT_EQ(at[1], 9286U);
  EXPECT_EQ(split_by_definition(active, 2), at);
}

TEST(PairSplit, BlockCostsSummedInSharesGiveTheSameSplit) {
  // the pair force loop's threads sum the block costs each over their share of the blocks, then
  // one places the split: for any division of the blocks it must be the definition's split
  Rng rng(11, 0);
  for (std::size_t n : {1UL, 4096UL, 4097UL, 40000UL, 444000UL})
    for (double touching : {0.0, 0.55, 1.0}) {
      std::vector<std::uint8_t> active(n);
      for (auto& a : active) a = rng.uniform() < touching ? 1 : 0;
      const std::size_t blocks = pair_split_blocks(n);
      for (int nt : {2, 3, 16}) {
        std::vector<std::uint64_t> cost(blocks, 99);  // stale content must not matter
        for (int t = 0; t < nt; ++t)  // shares as the loop makes them, in reverse order
        {
          const auto u = static_cast<std::size_t>(nt - 1 - t);
          pair_block_costs(active.data(), n, blocks * u / nt, blocks * (u + 1) / nt, cost.data());
        }
        std::vector<std::size_t> at{7};
        split_from_block_costs(active.data(), n, nt, cost.data(), at);
        EXPECT_EQ(at, split_by_definition(active, nt))
            << "n " << n << " touching " << touching << " threads " << nt;
      }
    }
}
