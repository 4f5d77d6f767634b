// DEM throughput on a case file: `bench_dem_throughput CASE [warmup] [steps]` builds the case,
// runs `warmup` steps, then times `steps` steps (the same window the peer decks time) and prints
// one line: N, threads, seconds, particle-steps per second, contacts, peak RSS.
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

#include "comminute/io/case/dem_case.hpp"

namespace {
// Resident set size now (MB), from /proc/self/statm.
double rss_mb() {
  std::ifstream f("/proc/self/statm");
  double pages = 0, resident = 0;
  f >> pages >> resident;
  return resident * 4096.0 / (1024.0 * 1024.0);
}
}  // namespace

int main(int argc, char** argv) {
  using namespace comminute;
  if (argc < 2) {
    fmt::print(stderr, "usage: {} CASE.toml [warmup=1000] [steps=2000]\n", argv[0]);
    return 2;
  }
  const long warm = argc > 2 ? std::atol(argv[2]) : 1000;
  const long steps = argc > 3 ? std::atol(argv[3]) : 2000;
  try {
    io::DemCase c = io::load_plain_dem_case(argv[1]);
    Simulation& sim = *c.sim;
    sim.setup();
    const double rss_setup = rss_mb();
    sim.run(static_cast<std::uint64_t>(warm));
    const auto t0 = std::chrono::steady_clock::now();
    sim.run(static_cast<std::uint64_t>(steps));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    const Observables o = sim.observe();
    const double n = static_cast<double>(sim.particles.size());
    fmt::print(
        "N={} threads={} steps={} seconds={:.3f} particle_steps_per_s={:.4g} contacts={} "
        "pairs={} rebuilds={} rss_setup_MB={:.0f} rss_end_MB={:.0f} peak_rss_MB={:.0f} "
        "bytes_per_particle={:.0f}\n",
        sim.particles.size(), omp_get_max_threads(), steps, s, n * static_cast<double>(steps) / s,
        o.contacts, sim.pairs().size(), sim.neighbor_rebuilds(), rss_setup, rss_mb(),
        static_cast<double>(ru.ru_maxrss) / 1024.0, static_cast<double>(ru.ru_maxrss) * 1024.0 / n);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  return 0;
}
