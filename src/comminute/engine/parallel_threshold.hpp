#pragma once
#include <cstddef>

namespace comminute {
// Below this many particles (pairs: twice as many) the engine's loops run serially: an OpenMP
// region costs microseconds, more than the work of a small system.
inline constexpr std::size_t kParallelMin = 4096;
}  // namespace comminute
