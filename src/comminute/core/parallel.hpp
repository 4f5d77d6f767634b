#pragma once
// Thread helpers. OpenMP is used with static schedules only, so that a run with the same thread
// count is bit-for-bit reproducible (needed for checkpoint/restart).
#include <omp.h>

namespace comminute {
inline int max_threads() {
  return omp_get_max_threads();
}
inline int thread_id() {
  return omp_get_thread_num();
}
}  // namespace comminute
