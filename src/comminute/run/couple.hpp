#pragma once
// The chain of `comminute couple case.toml` (docs/case-file.md, "Coupled runs"): a DEM case with
// a collision log ([collisions]) and/or grid statistics ([grid_statistics]) runs first, until its
// steady-state window has lasted `window` seconds (or to its end time); then a population-balance
// case whose data files name what the DEM wrote (a collision spectrum, a contact-frequency
// spectrum) is solved, or calibrated when it has [calibration]. Both cases are ordinary
// `comminute run` and `comminute pbm`/`calibrate` cases, read by their own readers: running the
// two stages by hand gives the same files. This file holds what the chain adds: the [couple]
// table, the steady-state wait, and the checks that the population balance really reads this DEM
// run's outputs (not stale files of an earlier run).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/core/csv_table.hpp"

namespace comminute {
class Simulation;
class InputError;
namespace analysis {
class CollisionLogModule;
class GridStatistics;
}  // namespace analysis
}  // namespace comminute

namespace comminute::run {

struct CoupleCase {
  CaseTable table;                  // [couple], for messages naming its keys
  std::filesystem::path dem;        // the DEM case file
  std::filesystem::path pbm;        // the population-balance case file
  std::filesystem::path directory;  // the chain's own outputs (couple.csv, plots)
  int threads = 1;                  // OpenMP threads of the DEM stage
  std::optional<double> window;     // s of steady-state window the DEM stage waits for
  bool plots = true;
};

// Reads [couple] of a couple case (every key in docs/case-file.md); call reject_unknown() after.
CoupleCase read_couple_case(const CaseTable& root);

// The DEM case's observers whose outputs the chain passes on.
struct DemObservers {
  const analysis::CollisionLogModule* collisions = nullptr;
  const analysis::GridStatistics* grid = nullptr;
};
// Finds them among the simulation's modules; refuses (InputError on couple.dem) a DEM case with
// neither, and couple.window without a collision log (the window is the log's).
DemObservers require_observers(const Simulation& sim, const CoupleCase& c);

// For run_until: true once the collision log's window has lasted `window` seconds.
std::function<bool(const Simulation&)> window_reached(const analysis::CollisionLogModule& log,
                                                      double window);
// After the DEM stage: the collision log's window must have opened (a steady state was detected,
// or its start passed) and, with couple.window, lasted that long (to within half a step, as
// window_reached() asks); otherwise an Error saying what to change.
void check_dem_stage(const DemObservers& o, const CoupleCase& c, const Simulation& sim);

// The population-balance case read whole, as `comminute pbm` (or `calibrate`, when it has
// [calibration]) reads it, unknown keys refused. With `dem_pending`, an error about a data file
// that lies in the DEM output folder and does not exist yet is not one: the case is checked again
// after the DEM stage, and nullopt is returned.
struct PbmCase {
  CaseFile file;
  bool calibrates = false;
};
std::optional<PbmCase> read_pbm_case(const std::filesystem::path& path,
                                     const std::filesystem::path& dem_output, bool dem_pending);

// The data files of the pbm case that lie in the DEM output folder, by key path.
std::vector<std::pair<std::string, std::filesystem::path>> dem_inputs(
    const CaseFile& pbm, const std::filesystem::path& dem_output);
// Refuses (InputError on couple.pbm) a pbm case that reads no file of the DEM output folder, and
// one that reads a file there that the DEM stage did not write: older than `stage_marker`, a file
// the stage created when it began.
void check_pbm_reads_dem(const CoupleCase& c, const CaseFile& pbm,
                         const std::filesystem::path& dem_output,
                         const std::filesystem::path& stage_marker);

// couple.csv: what the chain did (docs/outputs.md, "Coupled runs"); nothing that depends on the
// wall clock, so that the same case gives the same file.
struct CoupleSummary {
  double dem_end_time = 0;   // s, where the DEM stage stopped
  double window_start = -1;  // s, start of the collision log's window (< 0: none)
  double window_length = 0;  // s
  bool calibrated = false;
  std::vector<std::pair<std::string, std::filesystem::path>> links;  // pbm key -> DEM file
};
Table couple_table(const CoupleSummary& s);

}  // namespace comminute::run
