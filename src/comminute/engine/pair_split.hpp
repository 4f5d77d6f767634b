#pragma once
// The split of a step's pair list between the threads of the pair force loop. The list is cut
// only between blocks of kSplitBlock owner slots (the rows of slots [b B, (b + 1) B), B =
// kSplitBlock), so that each block's sums (the energy of its contacts) are made by one thread
// whatever the split: the split then decides the speed, never the result. A block costs 1 per
// listed pair and 6 more per touching one (active[k] = 1; the contact law costs several times a
// distance check). In two parts, so that the threads can sum the costs together:
// 1. each thread sums its share of the blocks with split_block_costs;
// 2. one thread places the cuts with split_blocks_by_share: thread t's range of blocks starts at
//    the first block where the running cost before it reaches the sum of the shares of the
//    threads before t, times the total (the shares add up to 1: equal shares, or shares that
//    follow the threads' measured speeds).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace comminute {

constexpr std::size_t kSplitBlock = 128;  // owner slots per block

// Blocks of n owner slots.
std::size_t split_blocks(std::size_t n);
// Costs of blocks [b0, b1) of n owner slots into cost[b] (rows: the list's CSR offsets, n + 1 of
// them; active: one flag per pair).
void split_block_costs(const std::uint32_t* rows, const std::uint8_t* active, std::size_t n,
                       std::size_t b0, std::size_t b1, std::uint64_t* cost);
// The first block of each thread's range (at[t]; at[share.size()] = blocks).
void split_blocks_by_share(const std::uint64_t* cost, std::size_t blocks,
                           const std::vector<double>& share, std::vector<std::size_t>& at);

}  // namespace comminute
