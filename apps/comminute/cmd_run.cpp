// `comminute run case.toml`: runs a DEM case to its end time, writing the outputs of [output],
// showing a progress line, and stopping cleanly (checkpoint, exit 130) on Ctrl-C.
// `--restart <checkpoint.h5>` continues a run from its checkpoint (same case file).
#include <fmt/format.h>
#include <omp.h>

#include "case_loading.hpp"
#include "command.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/io/output/checkpoint.hpp"
#include "comminute/io/output/output_module.hpp"
#include "comminute/run/progress_reporter.hpp"
#include "comminute/run/run_loop.hpp"
#include "comminute/run/stop_request.hpp"

namespace comminute::app {
namespace {

struct RunArgs {
  std::string case_path;
  std::string output;
  std::string restart;
  int threads = 0;
};

// Replaces the set-up state by the checkpoint's; warns when the thread count differs (the
// continuation is then not bit-for-bit identical to an uninterrupted run).
void restart_from(Simulation& sim, const std::string& path) {
  io::CheckpointInfo info;
  sim.load(io::read_checkpoint(path, &info));
  fmt::print(stderr, "continuing from {}: t = {:.9g} s, step {} (written by comminute {})\n", path,
             info.time, info.step, info.comminute_version);
  if (info.threads != max_threads())
    fmt::print(stderr,
               "warning: the checkpoint was written with {} thread(s), this run uses {}; the "
               "continuation will not be bit-for-bit identical (use --threads {})\n",
               info.threads, max_threads(), info.threads);
}

std::function<int()> setup_run(CLI::App& sub) {
  auto a = std::make_shared<RunArgs>();
  sub.add_option("case", a->case_path, "case file (TOML)")->required();
  sub.add_option("-o,--output", a->output, "output folder (default: [output] directory)");
  sub.add_option("-t,--threads", a->threads, "OpenMP threads (default: all cores)");
  sub.add_option("--restart", a->restart,
                 "continue from this checkpoint (e.g. output/checkpoint.h5)");
  return [a] {
    if (a->threads > 0) omp_set_num_threads(a->threads);
    LoadedCase c = load_dem_case(a->case_path);
    Simulation& sim = *c.dem.sim;
    fmt::print(stderr, "{}\n", c.dem.time_step_note);
    for (const auto& w : c.dem.warnings) fmt::print(stderr, "warning: {}\n", w);
    if (!a->output.empty()) c.output.directory = a->output;
    auto module = std::make_unique<io::OutputModule>(c.output, c.dem.end_time);
    io::OutputModule& output = *module;
    sim.modules.push_back(std::move(module));  // last: sees the step after every other module
    if (a->restart.empty())
      sim.setup();
    else
      restart_from(sim, a->restart);

    run::StopRequest stop;
    run::ProgressReporter progress(sim.time, c.dem.end_time);
    const int rc = run::run_until(sim, c.dem.end_time, &output, &progress, &stop);
    const double wall = progress.elapsed();
    const Observables o = sim.observe();
    fmt::print(stderr,
               "{}: t = {:.6g} s, {} steps, {} particles, {} contacts, {:.3g} s wall, {:.3g} "
               "particle-steps/s\noutputs in {}\n",
               rc == 0 ? "done" : "stopped", o.time, o.step, o.particles, o.contacts, wall,
               progress.total_particle_steps() / wall, output.options().directory.string());
    return rc;
  };
}

const bool registered = add_command({"run", "Run a DEM case", &setup_run});

}  // namespace
}  // namespace comminute::app
