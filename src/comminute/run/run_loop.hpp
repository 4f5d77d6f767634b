#pragma once
// The loop of `comminute run`: steps a set-up simulation to its end time with outputs, the
// progress line and a clean stop on SIGINT/SIGTERM.
#include <cstdio>
#include <functional>

namespace comminute {
class Simulation;
}
namespace comminute::io {
class OutputModule;
}

namespace comminute::run {

using io::OutputModule;
class ProgressReporter;
class StopRequest;

// Steps `sim` (already set up, or loaded from a checkpoint) until its time reaches end_time (s)
// to within half a step. Any of the helpers may be null. Between steps it checks `stop`; on a
// request it writes a checkpoint (only: so that a restart from it continues every series exactly
// as an uninterrupted run would), says so on `log` and returns stop->exit_code() (130 for
// SIGINT). When a [[stop]] condition (engine/stop_condition.hpp) is reached it ends after that
// step, says which on `log`, and finishes like at the end time. Otherwise it finishes the outputs
// at the end (last snapshot, row, checkpoint). Both return 0. A SimulationError (NaN, ...)
// propagates; the rows written so far are already on disk. `until`, when given, is asked after
// every step: true ends the run there like a [[stop]] condition (`comminute couple` stops its DEM
// stage once the steady-state window it waits for is long enough).
int run_until(Simulation& sim, double end_time, OutputModule* output, ProgressReporter* progress,
              const StopRequest* stop, std::FILE* log = stderr,
              const std::function<bool(const Simulation&)>& until = {});

}  // namespace comminute::run
