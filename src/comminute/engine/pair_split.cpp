#include "comminute/engine/pair_split.hpp"

#include <algorithm>

namespace comminute {

namespace {
constexpr std::size_t kBlock = 4096;
}  // namespace

std::size_t pair_split_blocks(std::size_t n) {
  return (n + kBlock - 1) / kBlock;
}

// The costs are summed as integers (exact, and a byte sum the compiler vectorises) per block of
// pairs: this pass reads every pair's flag in every step of a threaded run, so it is shared by the
// threads and must cost little against the loop it splits.
void pair_block_costs(const std::uint8_t* active, std::size_t n, std::size_t b0, std::size_t b1,
                      std::uint64_t* cost) {
  for (std::size_t b = b0; b < b1; ++b) {
    const std::size_t k0 = b * kBlock, k1 = std::min(n, k0 + kBlock);
    std::uint32_t touching = 0;  // a 32-bit byte sum
    for (std::size_t k = k0; k < k1; ++k) touching += active[k];
    cost[b] = (k1 - k0) + 6 * std::uint64_t{touching};
  }
}

// Whole blocks are skipped up to the block that holds a split point, which is then walked pair by
// pair: the split is exactly that of the running sum over all pairs.
void split_from_block_costs(const std::uint8_t* active, std::size_t n, int nt,
                            const std::uint64_t* cost, std::vector<std::size_t>& at) {
  const auto threads = static_cast<std::uint64_t>(nt);
  at.assign(threads + 1, n);
  at[0] = 0;
  if (nt == 1) return;
  const std::size_t blocks = pair_split_blocks(n);
  std::uint64_t total = 0;
  for (std::size_t b = 0; b < blocks; ++b) total += cost[b];
  std::uint64_t sum = 0;
  std::uint64_t t = 1;
  for (std::size_t b = 0; b < blocks && t < threads; ++b) {
    const std::uint64_t c = cost[b];
    if ((sum + c) * threads < total * t) {  // no split point in this block
      sum += c;
      continue;
    }
    for (std::size_t k = b * kBlock, e = std::min(n, k + kBlock); k < e && t < threads; ++k) {
      sum += 1 + 6 * std::uint64_t{active[k]};
      while (t < threads && sum * threads >= total * t) at[t++] = k + 1;
    }
  }
}

}  // namespace comminute
