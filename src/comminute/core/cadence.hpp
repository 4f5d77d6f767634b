#pragma once
// How often a series is written: every `interval` seconds of simulated time or every `steps`
// steps; neither set = the series' default (a fraction of the run, or never for checkpoints).
#include <cstdint>

namespace comminute {

struct Cadence {
  double interval = 0;      // s
  std::uint64_t steps = 0;  // steps
  bool is_set() const { return interval > 0 || steps > 0; }
  // Every `seconds` when positive, else every `default_steps` steps.
  static Cadence interval_or_steps(double seconds, std::uint64_t default_steps) {
    Cadence c;
    if (seconds > 0)
      c.interval = seconds;
    else
      c.steps = default_steps;
    return c;
  }
};

}  // namespace comminute
