#include "comminute/run/run_loop.hpp"

#include <fmt/format.h>

#include "comminute/engine/simulation.hpp"
#include "comminute/engine/stop_condition.hpp"
#include "comminute/io/output/output_module.hpp"
#include "comminute/run/progress_reporter.hpp"
#include "comminute/run/stop_request.hpp"

namespace comminute::run {

int run_until(Simulation& sim, double end_time, OutputModule* output, ProgressReporter* progress,
              const StopRequest* stop, std::FILE* log,
              const std::function<bool(const Simulation&)>& until) {
  if (output) output->start(sim);
  if (progress) progress->update(sim);  // the starting step, so every step is counted
  const StopConditionModule* conditions = find_stop_conditions(sim);
  while (sim.time < end_time - 0.5 * sim.dt) {
    if (conditions && conditions->reached()) {  // a [[stop]] condition: a normal end
      fmt::print(log, "stop condition reached, {}\n", conditions->describe(sim));
      break;
    }
    if (stop && stop->requested()) {
      if (progress) progress->finish(sim);
      if (output) output->write_checkpoint(sim);
      fmt::print(log, "stopped by {} at t = {:.9g} s (step {}){}\n", stop->signal_name(), sim.time,
                 sim.step_count,
                 output
                     ? fmt::format("; checkpoint written to {}", output->checkpoint_path().string())
                     : std::string());
      return stop->exit_code();
    }
    sim.step();
    if (progress) progress->update(sim);
    if (until && until(sim)) break;
  }
  if (progress) progress->finish(sim);
  if (output) output->finish(sim);
  return 0;
}

}  // namespace comminute::run
