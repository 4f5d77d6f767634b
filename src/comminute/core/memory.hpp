#pragma once
// Memory estimates: a case whose arrays cannot fit is refused when it is read, with the estimate,
// instead of failing later with std::bad_alloc.
#include <cstdint>

namespace comminute {

// Physical memory of this machine in bytes (sysconf); 0 when unknown.
double physical_memory_bytes();
// True when `bytes` exceeds the physical memory (never when that is unknown).
bool exceeds_memory(double bytes);
// Large arrays (>= 256 KiB) get their own pages, given back to the system when freed (glibc: a
// fixed mmap threshold instead of the dynamic one, which after the first large free serves later
// large arrays from the heap, whose freed holes then stay resident). Call once at the start of a
// program that rebuilds large arrays (the neighbour list): its peak memory stays that of the live
// arrays. No effect with other C libraries.
void give_back_freed_arrays();

}  // namespace comminute
