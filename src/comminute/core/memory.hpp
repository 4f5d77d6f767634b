#pragma once
// Memory estimates: a case whose arrays cannot fit is refused when it is read, with the estimate,
// instead of failing later with std::bad_alloc.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

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

// Makes the whole pages inside [p, p + bytes) resident now, in one system call (Linux 5.14 and
// later: MADV_POPULATE_WRITE), instead of one page fault each when first written. On the 2-core VM
// of bench/RESULTS.md (bench/page_fault_cost) a fresh page's first write costs 11-14 us, made
// resident this way first 6-7 us (the call, and the host's share at the first write, which no call
// in the guest avoids), a reused page's 0.03 us. The contents do not change. Nothing for less than
// a page, on other systems or on older kernels.
void prefault(void* p, std::size_t bytes);

// Room for n elements in v, their pages resident (prefault) before they are written: for arrays
// that grow during a run (fragments appended to the particles, their pairs to the list) and for
// fresh ones about to be filled (the temporaries of a neighbour-list rebuild). A vector
// that must grow does so as push_back would (at least doubling), the pages of its first n
// elements made resident before they move in; else the pages between its size and n.
template <class T, class A>
void make_resident(std::vector<T, A>& v, std::size_t n) {
  if (n <= v.capacity()) {
    if (n > v.size()) prefault(v.data() + v.size(), (n - v.size()) * sizeof(T));
    return;
  }
  std::vector<T, A> bigger(v.get_allocator());
  bigger.reserve(std::max(n, 2 * v.capacity()));
  prefault(bigger.data(), n * sizeof(T));
  bigger.insert(bigger.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(bigger);
}

}  // namespace comminute
