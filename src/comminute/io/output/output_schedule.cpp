#include "comminute/io/output/output_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::io {

namespace {
// floor(v) as an output index, checked before the conversion (a NaN or a huge ratio of a time to
// a tiny interval must not overflow the integer).
std::uint64_t index_of(double v) {
  const double f = std::floor(v);
  return std::isfinite(f) && f > 0 ? static_cast<std::uint64_t>(std::min(f, 1e18)) : 0;
}
}  // namespace

// A time-based output is due at the step nearest to k * interval (within half a step).
bool OutputSchedule::due(double time, std::uint64_t step, double dt) const {
  if (step == last_step_) return false;
  if (cadence_.steps > 0) return step % cadence_.steps == 0;
  if (cadence_.interval > 0)
    return time >= static_cast<double>(next_index_) * cadence_.interval - 0.5 * dt;
  return false;
}

void OutputSchedule::done(double time, std::uint64_t step, double dt) {
  last_step_ = step;
  if (cadence_.interval > 0)  // skip outputs missed when the interval is shorter than a step
    next_index_ = index_of((time + 0.5 * dt) / cadence_.interval) + 1;
}

}  // namespace comminute::io
