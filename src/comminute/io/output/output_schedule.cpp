#include "comminute/io/output/output_schedule.hpp"

#include <cmath>

namespace comminute::io {

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
    next_index_ = static_cast<std::uint64_t>(std::floor((time + 0.5 * dt) / cadence_.interval)) + 1;
}

}  // namespace comminute::io
