#pragma once
// The split of a step's pair list between the threads of the pair force loop.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace comminute {

// Splits the pairs [0, n) into nt ranges of about equal cost, a touching pair (active[k] = 1)
// costing 7 distance checks and another pair 1 (the contact law costs several times a distance
// check). The range of thread t is [at[t], at[t + 1]): at[t] is one past the first pair where the
// running cost reaches t / nt of the total. In two parts, so that the threads that are to share
// the pairs can sum the costs together (a serial pass over every pair's flag in every step is what
// limits two threads):
// 1. pair_split_blocks(n) blocks of pairs; each thread sums its share of them into `cost` with
//    pair_block_costs (cost must hold pair_split_blocks(n) entries; blocks [b0, b1) are written);
// 2. one thread then places the split points with split_from_block_costs (`at` is reused from
//    step to step).
std::size_t pair_split_blocks(std::size_t n);
void pair_block_costs(const std::uint8_t* active, std::size_t n, std::size_t b0, std::size_t b1,
                      std::uint64_t* cost);
void split_from_block_costs(const std::uint8_t* active, std::size_t n, int nt,
                            const std::uint64_t* cost, std::vector<std::size_t>& at);

}  // namespace comminute
