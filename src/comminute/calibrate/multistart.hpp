#pragma once
// Multi-start Nelder–Mead in a bounded, preconditioned parameter space: starts drawn uniformly in
// the unit box from Rng(seed, calibration stream) before any run (so results do not depend on
// the thread count), each start minimised independently, in parallel threads (OpenMP, static
// schedule). Outside the box the objective is the value at the nearest box point plus a penalty
// growing with the squared distance, so the model only ever sees parameters within the bounds.
#include <cstdint>
#include <functional>
#include <vector>

#include "comminute/calibrate/nelder_mead.hpp"
#include "comminute/calibrate/parameter_space.hpp"

namespace comminute::calibrate {

struct MultiStartOptions {
  std::size_t starts = 15;
  std::uint64_t seed = 1;
  int threads = 0;            // 0 = OpenMP default
  double simplex_step = 0.1;  // initial simplex edge in unit-box coordinates
  NelderMeadOptions nelder_mead{};
};

struct StartResult {
  std::size_t index = 0;
  std::vector<double> start;  // parameter values
  std::vector<double> best;   // parameter values
  double f = 0;
  NelderMeadResult run;
};

struct MultiStartResult {
  std::vector<StartResult> starts;  // in start order
  std::size_t best = 0;             // index of the lowest f (first on ties)
};

// f(parameter values) must be thread-safe; it may return +inf for an invalid model.
// progress(done, total, result) is called (serialised) after each start finishes.
MultiStartResult multistart(
    const ParameterSpace& space, const std::function<double(const std::vector<double>&)>& f,
    const MultiStartOptions& options,
    const std::function<void(std::size_t, std::size_t, const StartResult&)>& progress = {});

}  // namespace comminute::calibrate
