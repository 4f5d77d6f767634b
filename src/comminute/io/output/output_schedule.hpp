#pragma once
// When an output series is next due, the one cadence scheme of the output module: every
// `cadence.steps` steps, or at the step nearest to each k * `cadence.interval` (within half a
// step); never twice at the same step. Its state (next_index, last_step) is checkpointed.
#include <cstdint>
#include <vector>

#include "comminute/core/cadence.hpp"

namespace comminute::io {

class OutputSchedule {
 public:
  OutputSchedule() = default;
  explicit OutputSchedule(Cadence cadence, std::uint64_t first_index = 0)
      : cadence_(cadence), next_index_(first_index) {}

  bool due(double time, std::uint64_t step, double dt) const;
  // Records an output at this step; skips outputs missed when the interval is shorter than a step.
  void done(double time, std::uint64_t step, double dt);
  // Whether the last output was at this step (the run's end needs one more otherwise).
  bool written_at(std::uint64_t step) const { return last_step_ == step; }

  std::vector<std::uint64_t> state() const { return {next_index_, last_step_}; }
  void set_state(std::uint64_t next_index, std::uint64_t last_step) {
    next_index_ = next_index;
    last_step_ = last_step;
  }

 private:
  Cadence cadence_;
  std::uint64_t next_index_ = 0;                 // time-based
  std::uint64_t last_step_ = ~std::uint64_t{0};  // step of the last output
};

}  // namespace comminute::io
