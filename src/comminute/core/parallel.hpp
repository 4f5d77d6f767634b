#pragma once
// Thread helpers. OpenMP is used with static schedules, or with dynamic ones whose pieces are
// fixed in advance and joined in piece order, so that a run with the same thread count is
// bit-for-bit reproducible (needed for checkpoint/restart).
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace comminute {
inline int max_threads() {
  return omp_get_max_threads();
}
inline int thread_id() {
  return omp_get_thread_num();
}

// Flushes denormal numbers to zero on every OpenMP thread: velocities of a bed at rest decay
// through the denormal range, where x86 arithmetic is ~100x slower. Results differ from IEEE only
// below 2.2e-308.
inline void flush_denormals_to_zero() {
#if defined(__SSE__)
#pragma omp parallel
  _mm_setcsr(_mm_getcsr() | 0x8040);  // FTZ | DAZ
#endif
}

// A loop over [0, n) whose body scatters into an array (a pair loop writing both particles):
// body(k, acc) updates acc, which is `out` itself for the first thread and a copy filled with
// `identity` for each other one; the copies are then folded into `out` with combine(a, b) in
// thread order, so the same thread count always gives the same result. Small loops run serially.
// Each thread allocates and fills its own copy inside the parallel region: the fill (and the
// first touch of its pages) is not a serial pass of the calling thread.
// Thread t of nt takes [n t / nt, n (t + 1) / nt); nt = 1 below kScatterMin iterations. A caller
// that scatters every step passes `kept`, where the copies stay between calls (no fresh pages to
// fault in each step). With `fresh`, `out` is first filled with `identity` (by the first thread,
// while the others fill their copies).
inline constexpr std::size_t kScatterMin = 8192;
template <class T, class Body, class Combine>
void parallel_scatter(std::size_t n, std::vector<T>& out, const T& identity, Body&& body,
                      Combine&& combine, std::vector<std::vector<T>>* kept = nullptr,
                      bool fresh = false) {
  const int nt = n >= kScatterMin ? max_threads() : 1;
  if (nt == 1) {
    if (fresh) std::fill(out.begin(), out.end(), identity);
    for (std::size_t k = 0; k < n; ++k) body(k, out);
    return;
  }
  std::vector<std::vector<T>> local;
  std::vector<std::vector<T>>& copies = kept ? *kept : local;
  copies.resize(static_cast<std::size_t>(nt - 1));
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    if (t > 0) copies[static_cast<std::size_t>(t - 1)].assign(out.size(), identity);
    if (t == 0 && fresh) std::fill(out.begin(), out.end(), identity);
    std::vector<T>& acc = t == 0 ? out : copies[static_cast<std::size_t>(t - 1)];
    const std::size_t k1 = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(nt);
    for (std::size_t k = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(nt); k < k1;
         ++k)
      body(k, acc);
  }
  const std::size_t m = out.size();
#pragma omp parallel for schedule(static) num_threads(nt) if (m >= 4096)
  for (std::size_t i = 0; i < m; ++i)
    for (const auto& c : copies) out[i] = combine(out[i], c[i]);
}

// The indices k in [0, n) for which keep(k) holds, ascending, found by the threads in contiguous
// ranges and joined in range order: the same list as a serial scan, for any thread count. For
// scans with few hits; serial below `threaded_from` indices.
template <class Keep>
std::vector<std::uint32_t> parallel_filter(std::size_t n, Keep&& keep, std::size_t threaded_from) {
  const int nt = n >= threaded_from ? max_threads() : 1;
  std::vector<std::vector<std::uint32_t>> found(static_cast<std::size_t>(nt));
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    const std::size_t k0 = n * t / static_cast<std::size_t>(nt),
                      k1 = n * (t + 1) / static_cast<std::size_t>(nt);
    for (std::size_t k = k0; k < k1; ++k)
      if (keep(k)) found[t].push_back(static_cast<std::uint32_t>(k));
  }
  for (std::size_t t = 1; t < found.size(); ++t)
    found[0].insert(found[0].end(), found[t].begin(), found[t].end());
  return std::move(found[0]);
}

// body(k) for every k in [0, n), handed out one at a time to the threads as they come free: for
// a few unequal pieces of work each writing only a result of its own, so the results do not
// depend on the thread count. An exception a body throws is rethrown after the loop, that of the
// lowest k (the one a serial loop would have met first).
template <class Body>
void parallel_for_each(std::size_t n, Body&& body) {
  std::vector<std::exception_ptr> error(n);
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(dynamic, 1) if (n > 1)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    try {
      body(static_cast<std::size_t>(k));
    } catch (...) {
      error[static_cast<std::size_t>(k)] = std::current_exception();
    }
  }
  for (const auto& e : error)
    if (e) std::rethrow_exception(e);
}
}  // namespace comminute
