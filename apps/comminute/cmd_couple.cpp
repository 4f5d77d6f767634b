// `comminute couple case.toml`: one case, the whole DEM → population-balance chain
// (run/couple.hpp, docs/case-file.md "Coupled runs"): the DEM stage runs the [couple] dem case
// until its collision log's steady-state window is long enough (or to its end time), the pbm case
// then reads the spectra or grid statistics it wrote and is solved, or calibrated when it has
// [calibration]; couple.csv and the plots of the chain go to couple.directory.
#include <fmt/format.h>
#include <omp.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "case_kind.hpp"
#include "command.hpp"
#include "comminute/analysis/collision_log.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "comminute/io/output/output_module.hpp"
#include "comminute/run/couple.hpp"
#include "comminute/run/progress_reporter.hpp"
#include "comminute/run/run_loop.hpp"
#include "comminute/run/stop_request.hpp"
#include "couple_command.hpp"
#include "pbm_commands.hpp"

namespace comminute::app {
namespace {

// Runs `/usr/bin/python3 scripts/plot_couple.py <couple dir> <dem dir> <pbm dir>`; warns (never
// throws) on failure.
void plot_chain(const run::CoupleCase& c, const std::filesystem::path& dem,
                const std::filesystem::path& pbm) {
  const char* env = std::getenv("COMMINUTE_COUPLE_PLOT_SCRIPT");
  const std::string script =
      env ? env : std::string(COMMINUTE_SOURCE_DIR) + "/scripts/plot_couple.py";
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}' '{}'", script,
                                      c.directory.string(), dem.string(), pbm.string());
  if (std::system(cmd.c_str()) != 0)
    fmt::print(stderr, "warning: plotting failed ({}); the CSV files are complete\n", cmd);
}

// The DEM stage: like `comminute run`, stopping once the window is long enough. Returns the exit
// code (non-zero: stopped by a signal, with a checkpoint).
int run_dem_stage(LoadedCase& dem, const run::CoupleCase& c, const run::DemObservers& o) {
  Simulation& sim = *dem.dem.sim;
  fmt::print(stderr, "{}\n", dem.dem.time_step_note);
  for (const auto& w : dem.dem.warnings) fmt::print(stderr, "warning: {}\n", w);
  auto module = std::make_unique<io::OutputModule>(dem.output, dem.dem.end_time);
  io::OutputModule& output = *module;
  sim.modules.push_back(std::move(module));  // last: sees the step after every other module
  sim.setup();
  run::StopRequest stop;
  run::ProgressReporter progress(sim.time, dem.dem.end_time);
  std::function<bool(const Simulation&)> until;
  if (c.window) until = run::window_reached(*o.collisions, *c.window);
  const int rc = run::run_until(sim, dem.dem.end_time, &output, &progress, &stop, stderr, until);
  if (rc != 0) return rc;
  fmt::print(stderr, "couple: DEM stage done at t = {:.6g} s ({} steps, {:.3g} s wall)\n", sim.time,
             sim.step_count, progress.elapsed());
  return 0;
}

}  // namespace

PreparedCouple prepare_couple_case(const std::filesystem::path& file) {
  // Everything is read and checked before the DEM runs: the couple case, the DEM case, and the
  // pbm case as far as it does not need the files the DEM stage is to write.
  require_case_kind(file, {CaseKind::chain});
  const auto cf = CaseFile::load(file);
  run::CoupleCase c = run::read_couple_case(cf.root());
  cf.reject_unknown();
  omp_set_num_threads(c.threads);
  LoadedCase dem = load_dem_case(c.dem);
  check_output_directory(dem);
  const run::DemObservers o = run::require_observers(*dem.dem.sim, c);
  const bool checked = run::read_pbm_case(c.pbm, dem.output.directory, true).has_value();
  return {std::move(c), std::move(dem), o, checked};
}

namespace {

std::function<int()> setup_couple(CLI::App& sub) {
  auto file = std::make_shared<std::string>();
  auto no_plots = std::make_shared<bool>(false);
  sub.add_option("case", *file, "couple case file (TOML) with a [couple] table")->required();
  sub.add_flag("--no-plots", *no_plots, "write CSV files only");
  return [file, no_plots] {
    PreparedCouple pc = prepare_couple_case(*file);
    const run::CoupleCase& c = pc.couple;
    LoadedCase& dem = pc.dem;
    const run::DemObservers& observers = pc.observers;
    const std::filesystem::path dem_dir = dem.output.directory;
    if (!pc.pbm_checked)
      fmt::print(stderr, "couple: the pbm case reads files the DEM stage has yet to write\n");

    fmt::print(stderr, "couple: [1/2] DEM stage: {} ({} thread(s)){}\n", c.dem.string(), c.threads,
               c.window ? fmt::format(", until {:g} s of steady-state collisions", *c.window)
                        : std::string());
    std::filesystem::create_directories(c.directory);
    const std::filesystem::path marker = c.directory / "dem_stage_started";
    std::filesystem::remove(marker);
    std::ofstream(marker).close();  // its time stamp: what the DEM stage writes is newer
    if (const int rc = run_dem_stage(dem, c, observers); rc != 0) return rc;
    const double end = dem.dem.sim->time;
    run::check_dem_stage(observers, c, *dem.dem.sim);

    run::CoupleSummary summary;
    summary.dem_end_time = end;
    if (observers.collisions && observers.collisions->window_open()) {
      summary.window_start = observers.collisions->window_start();
      summary.window_length = observers.collisions->window_length(end);
      fmt::print(stderr, "couple: steady-state window {:.6g} s to {:.6g} s\n", summary.window_start,
                 summary.window_start + summary.window_length);
    }

    const auto pbm = run::read_pbm_case(c.pbm, dem_dir, false);
    run::check_pbm_reads_dem(c, pbm->file, dem_dir, marker);
    std::filesystem::remove(marker);
    summary.calibrated = pbm->calibrates;
    summary.links = run::dem_inputs(pbm->file, dem_dir);
    for (const auto& [key, path] : summary.links)
      fmt::print(stderr, "couple: {} of the pbm case reads {}\n", key, path.string());
    fmt::print(stderr, "couple: [2/2] population balance{}: {}\n",
               pbm->calibrates ? " (calibration)" : "", c.pbm.string());
    const int rc =
        pbm->calibrates ? calibrate_pbm_case(c.pbm, *no_plots) : solve_pbm_case(c.pbm, *no_plots);
    if (rc != 0) return rc;
    run::couple_table(summary).write(c.directory);
    const auto pbm_dir = io::read_pbm_output(pbm->file.root(), pbm->file.path()).directory;
    if (c.plots && !*no_plots) plot_chain(c, dem_dir, pbm_dir);
    fmt::print(stderr, "couple: wrote {}\n", (c.directory / "couple.csv").string());
    return 0;
  };
}

const bool registered = add_command(
    {"couple", "Run a DEM case and the population balance fed by it (case.toml)", &setup_couple});

}  // namespace
}  // namespace comminute::app
