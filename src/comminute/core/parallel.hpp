#pragma once
// Thread helpers. OpenMP is used with static schedules only, so that a run with the same thread
// count is bit-for-bit reproducible (needed for checkpoint/restart).
#include <omp.h>
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
}  // namespace comminute
