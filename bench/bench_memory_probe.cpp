// Where peak memory is set: `bench_memory_probe CASE [steps=3000]` builds the case and steps it one
// step at a time, printing a line at set-up, at every neighbour rebuild and whenever the peak
// resident memory (VmHWM) grew: step, rebuilds, resident and peak kB, list pairs, and glibc's heap
// (arena in use and free, mmapped). Used to find what grows at rebuilds (docs/ARCHITECTURE.md,
// "Memory per particle").
#include <fmt/format.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <string>

#include "support/case_bench.hpp"

namespace {
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
  using bench::status_kb;
  return bench::run_case_bench(
      argc, argv, "[steps=3000]", {3000}, [](Simulation& sim, const std::vector<long>& counts) {
        const long steps = counts[0];
        long peak = -1;
        std::uint64_t rebuilds = sim.neighbor_rebuilds();
        for (long s = 0; s <= steps; ++s) {
          if (s > 0) sim.step();
          const long hwm = status_kb("VmHWM");
          if (hwm == peak && sim.neighbor_rebuilds() == rebuilds) continue;
          fmt::print("step={} rebuilds={} rss_kB={} peak_kB={} pairs={} {}\n", s,
                     sim.neighbor_rebuilds(), status_kb("VmRSS"), hwm, sim.pairs().size(),
                     heap_line());
          peak = hwm;
          rebuilds = sim.neighbor_rebuilds();
        }
      });
}
