#include "comminute/engine/pair_split.hpp"

#include <algorithm>

namespace comminute {

// The costs are summed as integers (exact, and a byte sum the compiler vectorises), whole blocks
// at a time up to the block that holds a split point: this is serial work in every step of a
// threaded run, so it must cost little against the loop it splits.
void balanced_pair_split(const std::uint8_t* active, std::size_t n, int nt,
                         std::vector<std::size_t>& at) {
  const auto threads = static_cast<std::uint64_t>(nt);
  at.assign(threads + 1, n);
  at[0] = 0;
  if (nt == 1) return;
  constexpr std::size_t kBlock = 4096;
  auto cost = [active](std::size_t b, std::size_t e) {  // of a block: a 32-bit byte sum
    std::uint32_t touching = 0;
    for (std::size_t k = b; k < e; ++k) touching += active[k];
    return (e - b) + 6 * std::uint64_t{touching};
  };
  std::uint64_t total = 0;
  for (std::size_t k = 0; k < n; k += kBlock) total += cost(k, std::min(n, k + kBlock));
  std::uint64_t sum = 0;
  std::uint64_t t = 1;
  for (std::size_t k = 0; k < n && t < threads;) {
    const std::size_t e = std::min(n, k + kBlock);
    const std::uint64_t c = cost(k, e);
    if ((sum + c) * threads < total * t) {  // no split point in this block
      sum += c;
      k = e;
      continue;
    }
    for (; k < e && t < threads; ++k) {
      sum += 1 + 6 * std::uint64_t{active[k]};
      while (t < threads && sum * threads >= total * t) at[t++] = k + 1;
    }
  }
}

}  // namespace comminute
