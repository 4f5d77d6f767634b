#pragma once
// Which particle slots each thread takes in the step's per-particle loops: the integration, the
// pair forces and the wall contacts. The ranges are contiguous and the same in every loop, so that
// a particle's values stay in the cache of the core that works on them from one loop to the next
// (handed between cores, a cache line costs hundreds of nanoseconds on some machines). The pair
// force loop places them each step by the cost of the particles' pairs and the threads' measured
// speeds (pair_split.hpp); the loops that come before it in a step take the last step's ranges.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "comminute/core/parallel.hpp"

namespace comminute {

class ParticleRanges {
 public:
  // Thread t of `threads` takes slots [n t / threads, n (t + 1) / threads).
  void split_evenly(std::size_t n, int threads) {
    seconds_.assign(static_cast<std::size_t>(threads), 0.0);
    begin_.resize(static_cast<std::size_t>(threads) + 1);
    const auto nt = static_cast<std::size_t>(threads);
    for (std::size_t t = 0; t <= nt; ++t) begin_[t] = static_cast<std::uint32_t>(n * t / nt);
  }
  // The first slot of each thread's range and, last, the end of the last range (written by the
  // pair force loop).
  std::vector<std::uint32_t>& begin() { return begin_; }
  int threads() const { return begin_.empty() ? 0 : static_cast<int>(begin_.size()) - 1; }
  // The seconds each thread spent in the loops over these ranges since they were placed: each
  // loop adds its threads' own (a thread its own entry; a clock, not state of the run), and the
  // pair force loop reads them to learn the threads' speeds before it places the next ranges.
  void add_seconds(int t, double s) const {
    if (static_cast<std::size_t>(t) < seconds_.size()) seconds_[static_cast<std::size_t>(t)] += s;
  }
  std::vector<double>& seconds() const { return seconds_; }
  // Thread t's range among n slots: the ranges as placed, cut at n, the last one reaching n (the
  // slots may have changed in number since: particles inserted, removed, ghosts dropped).
  std::pair<std::size_t, std::size_t> of(int t, std::size_t n) const {
    const auto ut = static_cast<std::size_t>(t);
    const std::size_t b = std::min<std::size_t>(begin_[ut], n);
    const std::size_t e = t + 1 == threads() ? n : std::min<std::size_t>(begin_[ut + 1], n);
    return {b, std::max(b, e)};
  }

 private:
  std::vector<std::uint32_t> begin_;
  mutable std::vector<double> seconds_;
};

// Runs body(begin, end, t) for the range of each of `threads` threads over n slots, in parallel:
// the ranges placed last when they are for as many threads, else an even split.
template <class Body>
void for_each_range(const ParticleRanges& ranges, std::size_t n, int threads, Body&& body) {
  if (threads <= 1) {
    body(std::size_t{0}, n, 0);
    return;
  }
  ParticleRanges even;
  const ParticleRanges* use = &ranges;
  if (ranges.threads() != threads) {
    even.split_evenly(n, threads);
    use = &even;
  }
#pragma omp parallel num_threads(threads)
  {  // (fewer threads than asked for, as inside another parallel region: each takes several)
    for (int t = thread_id(); t < threads; t += omp_get_num_threads()) {
      const double start = omp_get_wtime();
      const auto [b, e] = use->of(t, n);
      body(b, e, t);
      use->add_seconds(t, omp_get_wtime() - start);
    }
  }
}

}  // namespace comminute
