// The pair force loop splits a step's rows between its threads in blocks of kSplitBlock owners,
// by cost (a touching pair 7, a listed pair that does not touch 1) and by the threads' shares.
// These tests hold the block costs to their definition written out pair by pair, and the cuts to
// theirs (thread t starts at the first block where the running cost before it reaches the shares
// of the threads before t, times the total), on random and lopsided lists.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/engine/pair_split.hpp"

using namespace comminute;

namespace {

// A random list's CSR offsets over n owners (0 to 8 pairs each) and its touching flags.
struct List {
  std::vector<std::uint32_t> rows;
  std::vector<std::uint8_t> active;
};
List random_list(std::size_t n, double touching, Rng& rng) {
  List l;
  l.rows.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    l.rows[i + 1] = l.rows[i] + static_cast<std::uint32_t>(rng.uniform() * 9);
  l.active.resize(l.rows[n]);
  for (auto& a : l.active) a = rng.uniform() < touching ? 1 : 0;
  return l;
}

// The definition: the pairs of the block's owners, 1 + 6 per touching one.
std::vector<std::uint64_t> costs_by_definition(const List& l, std::size_t n) {
  std::vector<std::uint64_t> cost(split_blocks(n), 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = l.rows[i]; k < l.rows[i + 1]; ++k)
      cost[i / kSplitBlock] += 1 + 6 * l.active[k];
  return cost;
}

// The cuts must be where the definition puts them: the running cost before at[t] reaches the
// target, the running cost before at[t] - 1 does not (unless at[t] is at the previous cut).
void expect_cuts_by_definition(const std::vector<std::uint64_t>& cost,
                               const std::vector<double>& share,
                               const std::vector<std::size_t>& at) {
  const std::size_t nt = share.size(), blocks = cost.size();
  ASSERT_EQ(at.size(), nt + 1);
  EXPECT_EQ(at[0], 0U);
  EXPECT_EQ(at[nt], blocks);
  const double total = static_cast<double>(std::accumulate(cost.begin(), cost.end(), 0ULL));
  double before = 0;
  for (std::size_t t = 1; t < nt; ++t) {
    before += share[t - 1];
    const double target = before * total;
    ASSERT_GE(at[t], at[t - 1]);
    const auto running = [&](std::size_t b) {  // cost of blocks [0, b)
      return static_cast<double>(std::accumulate(cost.begin(), cost.begin() + b, 0ULL));
    };
    EXPECT_TRUE(at[t] == blocks || running(at[t]) >= target) << "thread " << t;
    if (at[t] > at[t - 1]) {
      EXPECT_LT(running(at[t] - 1), target) << "thread " << t;
    }
  }
}

}  // namespace

TEST(PairSplit, BlockCostsEqualTheirDefinitionInAnyShareOfTheBlocks) {
  Rng rng(7, 0);
  // sizes around and across a block of owners, and a bed-sized list
  for (std::size_t n : {0UL, 1UL, 2UL, 127UL, 128UL, 129UL, 1000UL, 100000UL})
    for (double touching : {0.0, 0.55, 1.0}) {
      const List l = random_list(n, touching, rng);
      const std::size_t blocks = split_blocks(n);
      ASSERT_EQ(blocks, (n + kSplitBlock - 1) / kSplitBlock);
      for (std::size_t nt : {1UL, 2UL, 3UL, 16UL}) {
        std::vector<std::uint64_t> cost(blocks, 99);  // stale content must not matter
        for (std::size_t u = nt; u-- > 0;)  // shares as the loop makes them, in reverse order
          split_block_costs(l.rows.data(), l.active.data(), n, blocks * u / nt,
                            blocks * (u + 1) / nt, cost.data());
        EXPECT_EQ(cost, costs_by_definition(l, n)) << "n " << n << " threads " << nt;
      }
    }
}

TEST(PairSplit, CutsFollowTheSharesOnRandomCosts) {
  Rng rng(11, 0);
  for (std::size_t blocks : {0UL, 1UL, 2UL, 7UL, 782UL})
    for (std::size_t nt : {1UL, 2UL, 3UL, 16UL}) {
      std::vector<std::uint64_t> cost(blocks);
      for (auto& c : cost) c = static_cast<std::uint64_t>(rng.uniform() * 5000);
      std::vector<double> equal(nt, 1.0 / static_cast<double>(nt)), uneven(nt);
      for (auto& s : uneven) s = rng.uniform(0.1, 1.0);
      const double sum = std::accumulate(uneven.begin(), uneven.end(), 0.0);
      for (auto& s : uneven) s /= sum;
      for (const auto* share : {&equal, &uneven}) {
        std::vector<std::size_t> at{99};  // reused storage: stale content must not matter
        split_blocks_by_share(cost.data(), blocks, *share, at);
        expect_cuts_by_definition(cost, *share, at);
      }
    }
}

TEST(PairSplit, LopsidedSharesMoveTheCut) {
  // ten blocks of cost 10: a thread with a quarter of the speed gets the first three blocks (the
  // running cost 20 before block 2 is short of 25, 30 before block 3 reaches it); equal shares cut
  // at block 5 (50 reaches 50)
  const std::vector<std::uint64_t> cost(10, 10);
  std::vector<std::size_t> at;
  split_blocks_by_share(cost.data(), cost.size(), {0.25, 0.75}, at);
  EXPECT_EQ(at, (std::vector<std::size_t>{0, 3, 10}));
  split_blocks_by_share(cost.data(), cost.size(), {0.5, 0.5}, at);
  EXPECT_EQ(at, (std::vector<std::size_t>{0, 5, 10}));
  // all the cost in the last block: the first thread's share is reached only there
  std::vector<std::uint64_t> last(10, 0);
  last[9] = 100;
  split_blocks_by_share(last.data(), last.size(), {0.5, 0.5}, at);
  EXPECT_EQ(at, (std::vector<std::size_t>{0, 10, 10}));
}
