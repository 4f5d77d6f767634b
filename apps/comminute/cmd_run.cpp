// `comminute run case.toml`: runs a DEM case to its end time, writing the outputs of [output],
// showing a progress line, and stopping cleanly (checkpoint, exit 130) on Ctrl-C.
// `--restart <checkpoint.h5>` continues a run from its checkpoint (same case file).
#include <fmt/format.h>
#include <omp.h>

#include <filesystem>

#include "case_loading.hpp"
#include "command.hpp"
#include "comminute/core/error.hpp"
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
  CLI::Option* output_given = nullptr;
  CLI::Option* threads_given = nullptr;
  CLI::Option* restart_given = nullptr;
};

// --threads: more than this is a typo (and large counts crash inside the OpenMP runtime).
constexpr int max_cli_threads = 1024;

bool sub_given(const CLI::Option* o) {
  return o != nullptr && o->count() > 0;
}

// Replaces the set-up state by the checkpoint's; warns when the thread count differs (the
// continuation is then not bit-for-bit identical to an uninterrupted run). A checkpoint that
// cannot be read, belongs to another case or does not hold a consistent state is an input error
// (exit 2) naming the checkpoint.
void restart_from(Simulation& sim, const std::string& path,
                  const std::vector<std::pair<std::string, std::string>>& fingerprint,
                  double end_time) {
  io::CheckpointInfo info;
  try {
    const Archive a = io::read_checkpoint(path, &info);
    io::check_case_fingerprint(a, fingerprint, path);
    sim.load(a);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, "--restart", 0, e.what());
  }
  if (!(sim.time < end_time))
    throw InputError(
        path, "--restart", 0,
        fmt::format("the checkpoint is at t = {:.9g} s, not before the end time {:.9g} "
                    "s: nothing to continue (raise simulation.end_time)",
                    sim.time, end_time));
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
  a->output_given =
      sub.add_option("-o,--output", a->output, "output folder (default: [output] directory)");
  a->threads_given =
      sub.add_option("-t,--threads", a->threads,
                     fmt::format("OpenMP threads, 1 to {} (default: all cores)", max_cli_threads));
  a->restart_given = sub.add_option("--restart", a->restart,
                                    "continue from this checkpoint (e.g. output/checkpoint.h5)");
  return [a] {
    // Every value given on the command line means something or is refused.
    auto refuse = [](const char* option, const std::string& message) {
      throw InputError("<command line>", option, 0, message);
    };
    if (a->case_path.empty()) refuse("case", "the case file path is empty");
    if (sub_given(a->output_given) && a->output.empty()) refuse("--output", "the path is empty");
    if (sub_given(a->restart_given) && a->restart.empty()) refuse("--restart", "the path is empty");
    if (sub_given(a->threads_given) && (a->threads < 1 || a->threads > max_cli_threads))
      refuse("--threads",
             fmt::format("{} threads: must be in [1, {}]", a->threads, max_cli_threads));
    if (a->threads > 0) omp_set_num_threads(a->threads);
    LoadedCase c = load_dem_case(a->case_path);
    Simulation& sim = *c.dem.sim;
    fmt::print(stderr, "{}\n", c.dem.time_step_note);
    for (const auto& w : c.dem.warnings) fmt::print(stderr, "warning: {}\n", w);
    if (!a->output.empty()) c.output.directory = a->output;
    check_output_directory(c, a->output.empty() ? "" : "--output");
    auto module = std::make_unique<io::OutputModule>(c.output, c.dem.end_time);
    io::OutputModule& output = *module;
    sim.modules.push_back(std::move(module));  // last: sees the step after every other module
    if (a->restart.empty())
      sim.setup();
    else
      restart_from(sim, a->restart, c.output.case_fingerprint, c.dem.end_time);

    run::StopRequest stop;
    run::ProgressReporter progress(sim.time, c.dem.end_time);
    int rc = 0;
    try {
      rc = run::run_until(sim, c.dem.end_time, &output, &progress, &stop);
    } catch (const SimulationError&) {
      throw;
    } catch (const InputError&) {
      throw;
    } catch (const Error& e) {
      // a full disk or an unwritable folder: name the folder, the key that set it, and what
      // is left (files are replaced atomically: the previous checkpoint is complete)
      const std::string checkpoint = output.checkpoint_path().string();
      throw Error(fmt::format(
          "{}\n  while writing the outputs to '{}' ({}); the last complete checkpoint: {}",
          e.what(), output.options().directory.string(),
          a->output.empty() ? fmt::format("key 'output.directory' of {}", a->case_path)
                            : std::string("option --output"),
          std::filesystem::exists(checkpoint) ? checkpoint : std::string("none yet")));
    }
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
