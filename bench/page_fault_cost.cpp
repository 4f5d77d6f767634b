// What a fresh page costs on this machine: the first write to each page of a fresh anonymous
// mapping (one page fault per page), against making the same pages resident first in one call
// (comminute::prefault, MADV_POPULATE_WRITE; the call is timed too) and then writing them, and
// against writing pages already written once (an array reused). The engine takes fresh pages
// wherever a large array is allocated or grows (large arrays are given back to the system when
// freed), so this says what core/memory.hpp's prefault saves per page, and what reuse would.
//   page_fault_cost [pages=16384] [repeats=5]
// One line per way, best and median of the repeats:
//   page_fault_cost way=W pages=P best_us_per_page=.. median_us_per_page=..
#include <fmt/format.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "comminute/core/memory.hpp"

namespace {

enum class Way { write_faulting, prefault_then_write, write_resident };

// Seconds to write one byte per page of a mapping of `pages` pages: fresh, fresh and made resident
// first in one call (timed too), or written once before (not timed).
double write_pages(std::size_t pages, Way way) {
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t bytes = pages * page;
  void* m = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) {
    fmt::print(stderr, "page_fault_cost: mmap of {} bytes failed\n", bytes);
    std::exit(1);
  }
  auto* base = static_cast<volatile unsigned char*>(m);
  if (way == Way::write_resident)
    for (std::size_t k = 0; k < pages; ++k) base[k * page] = 2;
  const auto t0 = std::chrono::steady_clock::now();
  if (way == Way::prefault_then_write) comminute::prefault(m, bytes);
  for (std::size_t k = 0; k < pages; ++k) base[k * page] = 1;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ::munmap(m, bytes);
  return s;
}

// The value of argv[k] as a count >= 1, or `fallback` when absent; exits with code 2 otherwise.
std::size_t count_arg(int argc, char** argv, int k, std::size_t fallback) {
  if (argc <= k) return fallback;
  char* end = nullptr;
  const long v = std::strtol(argv[k], &end, 10);
  if (end == argv[k] || *end != '\0' || v < 1) {
    fmt::print(stderr, "page_fault_cost: argument {} must be a count >= 1, not '{}'\n", k, argv[k]);
    std::exit(2);
  }
  return static_cast<std::size_t>(v);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t pages = count_arg(argc, argv, 1, 16384);
  const std::size_t repeats = count_arg(argc, argv, 2, 5);
  const std::pair<Way, const char*> ways[] = {{Way::write_faulting, "write_faulting"},
                                              {Way::prefault_then_write, "prefault_then_write"},
                                              {Way::write_resident, "write_resident"}};
  for (const auto& [way, name] : ways) {
    std::vector<double> us;
    for (std::size_t r = 0; r < repeats; ++r)
      us.push_back(1e6 * write_pages(pages, way) / static_cast<double>(pages));
    std::sort(us.begin(), us.end());
    fmt::print(
        "page_fault_cost way={} pages={} best_us_per_page={:.3f} median_us_per_page={:.3f}\n", name,
        pages, us.front(), us[us.size() / 2]);
  }
}
