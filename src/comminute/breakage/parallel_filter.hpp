#pragma once
// The breakage module's scans of the whole pair list or particle store: comminute::parallel_filter
// (core/parallel.hpp) for those with few hits (the slots of this step's broken parents), threaded
// from the engine's size; parallel_select for those with many.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute::breakage {

template <class Keep>
std::vector<std::uint32_t> parallel_filter(std::size_t n, Keep&& keep) {
  return comminute::parallel_filter(n, std::forward<Keep>(keep), 2 * kParallelMin);
}

// The same list, into `out`, for scans where many indices qualify in no predictable pattern (the
// pairs and slots of growing fragments, a third or more): each thread writes every index of its
// range into its part of `parts` and advances past those that qualify, without a branch; the
// parts only grow (scratch kept between calls) and are joined in range order.
template <class Keep>
void parallel_select(std::size_t n, Keep&& keep, std::vector<std::uint32_t>& out,
                     std::vector<std::vector<std::uint32_t>>& parts) {
  const int nt = n >= 2 * kParallelMin ? max_threads() : 1;
  parts.resize(static_cast<std::size_t>(nt));
  std::vector<std::size_t> offset(static_cast<std::size_t>(nt) + 1, 0);
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    const std::size_t k0 = n * t / static_cast<std::size_t>(nt),
                      k1 = n * (t + 1) / static_cast<std::size_t>(nt);
    std::vector<std::uint32_t>& mine = parts[t];
    if (mine.size() < k1 - k0) mine.resize(k1 - k0);
    std::size_t c = 0;
    for (std::size_t k = k0; k < k1; ++k) {
      mine[c] = static_cast<std::uint32_t>(k);
      c += keep(k) ? 1 : 0;
    }
    offset[t + 1] = c;
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t u = 0; u < parts.size(); ++u) offset[u + 1] += offset[u];
      out.resize(offset.back());
    }
    std::copy_n(mine.begin(), offset[t + 1] - offset[t],
                out.begin() + static_cast<std::ptrdiff_t>(offset[t]));
  }
}

}  // namespace comminute::breakage
