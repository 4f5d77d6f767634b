// Where peak memory is set: `bench_memory_probe CASE [steps=3000]` builds the case and steps it one
// step at a time, printing a line at set-up, at every neighbour rebuild and whenever the peak
// resident memory (VmHWM) grew: step, rebuilds, resident and peak kB, list pairs, and glibc's heap
// (arena in use and free, mmapped). Used to find what grows at rebuilds (docs/ARCHITECTURE.md,
// "Memory per particle").
#include <fmt/format.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdlib>
#include <fstream>
#include <string>

#include "comminute/core/memory.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace {
// A "VmRSS"-style field of /proc/self/status in kB (-1 when absent).
long status_kb(const std::string& key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key + ":", 0) == 0) return std::atol(line.c_str() + key.size() + 1);
  return -1;
}

std::string heap_line() {
#ifdef __GLIBC__
  const auto mi = mallinfo2();
  return fmt::format("heap_inuse_kB={} heap_free_kB={} mmapped_kB={}", mi.uordblks / 1024,
                     mi.fordblks / 1024, mi.hblkhd / 1024);
#else
  return {};
#endif
}
}  // namespace

int main(int argc, char** argv) {
  using namespace comminute;
  if (argc < 2) {
    fmt::print(stderr, "usage: {} CASE.toml [steps=3000]\n", argv[0]);
    return 2;
  }
  give_back_freed_arrays();  // as the comminute program does
  const long steps = argc > 2 ? std::atol(argv[2]) : 3000;
  try {
    io::DemCase c = io::load_plain_dem_case(argv[1]);
    Simulation& sim = *c.sim;
    sim.setup();
    long peak = -1;
    std::uint64_t rebuilds = sim.neighbor_rebuilds();
    for (long s = 0; s <= steps; ++s) {
      if (s > 0) sim.step();
      const long hwm = status_kb("VmHWM");
      if (hwm == peak && sim.neighbor_rebuilds() == rebuilds) continue;
      fmt::print("step={} rebuilds={} rss_kB={} peak_kB={} pairs={} {}\n", s,
                 sim.neighbor_rebuilds(), status_kb("VmRSS"), hwm, sim.pairs().size(), heap_line());
      peak = hwm;
      rebuilds = sim.neighbor_rebuilds();
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  return 0;
}
