#pragma once
// Thread helpers. OpenMP is used with static schedules, or with dynamic ones whose pieces are
// fixed in advance and joined in piece order, so that a run with the same thread count is
// bit-for-bit reproducible (needed for checkpoint/restart).
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <utility>
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

// A loop over [0, n) whose body scatters into an array: body(k, acc) updates acc, which is `out`
// itself for the first thread and a copy filled with `identity` for each other one; the copies
// are then folded into `out` with combine(a, b) in thread order, so the same thread count always
// gives the same result. For small arrays (a few tallies): each thread copies all of `out`, which
// for per-particle arrays costs more than the loop (owner_scatter below). Thread t of nt takes
// [n t / nt, n (t + 1) / nt); nt = 1 below kScatterMin iterations.
inline constexpr std::size_t kScatterMin = 8192;
template <class T, class Body, class Combine>
void parallel_scatter(std::size_t n, std::vector<T>& out, const T& identity, Body&& body,
                      Combine&& combine) {
  const int nt = n >= kScatterMin ? max_threads() : 1;
  if (nt == 1) {
    for (std::size_t k = 0; k < n; ++k) body(k, out);
    return;
  }
  std::vector<std::vector<T>> copies(static_cast<std::size_t>(nt - 1));
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    if (t > 0) copies[static_cast<std::size_t>(t - 1)].assign(out.size(), identity);
    std::vector<T>& acc = t == 0 ? out : copies[static_cast<std::size_t>(t - 1)];
    const std::size_t k1 = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(nt);
    for (std::size_t k = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(nt); k < k1;
         ++k)
      body(k, acc);
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    for (const auto& c : copies) out[i] = combine(out[i], c[i]);
}

// Per-thread queues of owner_scatter, kept between calls by a caller that scatters every step.
template <class T>
using OwnerScatterQueues = std::vector<std::vector<std::pair<std::uint32_t, T>>>;

// A loop over items [0, n), each belonging to a slot of `out` (owner(k) ascending with k when the
// items are grouped by owner, as a half neighbour list is by its first particle), whose body
// scatters values: body(k, add) calls add(slot, value), which merges value into out[slot] as
// out[slot] = combine(out[slot], value). `out` is first reset to `identity`. Thread t of nt takes
// the items [n t / nt, n (t + 1) / nt) and owns the slots from its first item's owner to the next
// thread's: it resets them, merges into them directly and queues what goes to another thread's
// slots; after the loop each thread merges the values queued for its slots, queue by queue in
// thread order. The same thread count gives the same result and one thread gives the serial
// loop's; no thread copies `out` (parallel_scatter's copies cost a pass over `out` per thread,
// which is most of the work when a minority of slots receive anything). Items out of owner order
// are still merged into the right slots, only more of them through the queues (the order in which
// a slot's values are combined then differs). nt = 1 below kScatterMin items.
template <class T, class Owner, class Body, class Combine>
void owner_scatter(std::size_t n, Owner&& owner, std::vector<T>& out, const T& identity,
                   Body&& body, Combine&& combine, OwnerScatterQueues<T>& queues) {
  const int nt = n >= kScatterMin ? max_threads() : 1;
  const std::size_t m = out.size();
  if (nt == 1) {
    std::fill(out.begin(), out.end(), identity);
    auto add = [&](std::size_t s, const T& v) { out[s] = combine(out[s], v); };
    for (std::size_t k = 0; k < n; ++k) body(k, add);
    return;
  }
  const auto nts = static_cast<std::size_t>(nt);
  std::vector<std::size_t> from(nts + 1, m);  // thread t owns slots [from[t], from[t + 1])
  from[0] = 0;
  for (std::size_t t = 1; t < nts; ++t)
    from[t] = std::clamp<std::size_t>(owner(n * t / nts), from[t - 1], m);
  queues.resize(nts);
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    const std::size_t s0 = from[t], s1 = from[t + 1];
    auto& queue = queues[t];
    queue.clear();
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(s0),
              out.begin() + static_cast<std::ptrdiff_t>(s1), identity);
    auto add = [&](std::size_t s, const T& v) {
      if (s >= s0 && s < s1)
        out[s] = combine(out[s], v);
      else
        queue.emplace_back(static_cast<std::uint32_t>(s), v);
    };
    const std::size_t k1 = n * (t + 1) / nts;
    for (std::size_t k = n * t / nts; k < k1; ++k) body(k, add);
#pragma omp barrier
    for (std::size_t u = 0; u < nts; ++u)
      if (u != t)
        for (const auto& [s, v] : queues[u])
          if (s >= s0 && s < s1) out[s] = combine(out[s], v);
  }
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
