#include "comminute/engine/pair_split.hpp"

#include <algorithm>

namespace comminute {

std::size_t split_blocks(std::size_t n) {
  return (n + kSplitBlock - 1) / kSplitBlock;
}

// The costs are summed as integers (exact, and a byte sum the compiler vectorises): this pass
// reads every pair's flag in every step of a threaded run, so it is shared by the threads and
// must cost little against the loop it splits.
void split_block_costs(const std::uint32_t* rows, const std::uint8_t* active, std::size_t n,
                       std::size_t b0, std::size_t b1, std::uint64_t* cost) {
  for (std::size_t b = b0; b < b1; ++b) {
    const std::size_t k0 = rows[b * kSplitBlock], k1 = rows[std::min(n, (b + 1) * kSplitBlock)];
    std::uint32_t touching = 0;  // (a 32-bit byte sum vectorises; a block has far fewer pairs)
    for (std::size_t k = k0; k < k1; ++k) touching += active[k];
    cost[b] = (k1 - k0) + 6 * std::uint64_t{touching};
  }
}

void split_blocks_by_share(const std::uint64_t* cost, std::size_t blocks,
                           const std::vector<double>& share, std::vector<std::size_t>& at) {
  const std::size_t nt = share.size();
  at.assign(nt + 1, blocks);
  at[0] = 0;
  std::uint64_t total = 0;
  for (std::size_t b = 0; b < blocks; ++b) total += cost[b];
  double before = 0;  // the shares of threads [0, t)
  std::uint64_t sum = 0;
  std::size_t b = 0;
  for (std::size_t t = 1; t < nt; ++t) {
    before += share[t - 1];
    const double target = before * static_cast<double>(total);
    while (b < blocks && static_cast<double>(sum) < target) sum += cost[b++];
    at[t] = b;
  }
}

}  // namespace comminute
