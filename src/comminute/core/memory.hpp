#pragma once
// Memory estimates: a case whose arrays cannot fit is refused when it is read, with the estimate,
// instead of failing later with std::bad_alloc.
#include <cstdint>

namespace comminute {

// Physical memory of this machine in bytes (sysconf); 0 when unknown.
double physical_memory_bytes();
// True when `bytes` exceeds the physical memory (never when that is unknown).
bool exceeds_memory(double bytes);

}  // namespace comminute
