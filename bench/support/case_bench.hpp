#pragma once
// What the benches that step a case file share (bench_dem_throughput, bench_memory_probe): the
// command line `CASE.toml [count ...]`, the allocator set-up of the comminute program, the case
// built and set up, an error reported as exit code 2; and resident memory read from /proc.
// (A header beside the benches, not bench_*.cpp: every bench_*.cpp is built as its own program.)
#include <fmt/format.h>

#include <cstddef>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "comminute/core/memory.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::bench {

// A field of /proc/self/status in kB ("VmRSS": resident now, "VmHWM": peak); -1 when absent.
inline long status_kb(const std::string& key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key + ":", 0) == 0) return std::atol(line.c_str() + key.size() + 1);
  return -1;
}

// Runs body(sim, counts) on the case argv[1], set up, as the comminute program would run it;
// counts[k] is argv[k + 2] when given, else defaults[k]. `optional_args` names them in the usage
// line. Returns the exit code: 2 on a usage error or an exception, else 0.
template <class Body>
int run_case_bench(int argc, char** argv, const char* optional_args, std::vector<long> counts,
                   Body body) {
  if (argc < 2) {
    fmt::print(stderr, "usage: {} CASE.toml {}\n", argv[0], optional_args);
    return 2;
  }
  give_back_freed_arrays();  // as the comminute program does
  for (std::size_t k = 0; k < counts.size() && k + 2 < static_cast<std::size_t>(argc); ++k)
    counts[k] = std::atol(argv[k + 2]);
  try {
    io::DemCase c = io::load_plain_dem_case(argv[1]);
    c.sim->setup();
    body(*c.sim, counts);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace comminute::bench
