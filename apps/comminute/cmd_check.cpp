// `comminute check case.toml`: validates a case file without running it, whichever command runs
// it: a DEM case (`run`), a population balance (`pbm`), a fit (`calibrate`: of a population
// balance, or of a bonded grain's compression) or a chain (`couple`). The kind is read from the
// tables the case has (case_kind.hpp); each is read by the same code as its command, then unknown
// keys are refused.
#include <fmt/format.h>

#include "case_kind.hpp"
#include "case_loading.hpp"
#include "command.hpp"
#include "comminute/io/case/calibration_case.hpp"
#include "comminute/io/case/grain_compression_case.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "couple_command.hpp"

namespace comminute::app {
namespace {

int check_couple(const std::string& path) {
  const PreparedCouple pc = prepare_couple_case(path);
  fmt::print("{}: valid couple case\n  DEM case {}: end time {} s\n  pbm case {}: {}\n", path,
             pc.couple.dem.string(), pc.dem.dem.end_time, pc.couple.pbm.string(),
             pc.pbm_checked ? "valid" : "valid up to the files the DEM stage writes");
  return 0;
}

// A population balance (`comminute pbm`), or its fit to measured distributions (`comminute
// calibrate`) when it has [calibration].
int check_pbm(const CaseFile& cf) {
  const CaseTable root = cf.root();
  const pbm::Problem p = io::read_pbm_problem(root);
  io::read_pbm_output(root, cf.path());
  const bool fit = root.has("calibration");
  const std::size_t free = fit ? io::read_calibration(cf).space.size() : 0;
  cf.reject_unknown();
  fmt::print(
      "{}: valid population-balance case (comminute {})\n  {} size classes, {} output "
      "time(s) to {} s\n",
      cf.path().string(), fit ? "calibrate" : "pbm", p.grid.classes(), p.times.size(),
      p.times.empty() ? 0.0 : p.times.back());
  if (fit) fmt::print("  {} free parameter(s)\n", free);
  return 0;
}

// A bonded grain's compression fitted to a measured curve (`comminute calibrate`): reading it runs
// the compression once at the case's own values, which must reach the end of the curve.
int check_grain_calibration(const CaseFile& cf) {
  const CaseTable root = cf.root();
  if (const auto out = root.optional_table("output")) io::read_output_options(*out);
  const io::GrainCalibrationCase cc = io::read_grain_calibration(cf);
  cf.reject_unknown();
  fmt::print(
      "{}: valid grain compression calibration (comminute calibrate)\n  {} free "
      "parameter(s), {} measured point(s) to {} m; the compression at the case's values "
      "reaches it\n",
      cf.path().string(), cc.space.size(), cc.measured.displacement.size(),
      cc.measured.displacement.back());
  return 0;
}

int check_dem(const std::string& path) {
  LoadedCase c = load_dem_case(path);
  check_output_directory(c);
  const Simulation& sim = *c.dem.sim;
  fmt::print(
      "{}: valid\n  {} material(s), {} wall(s), {} particle(s) placed so far, end time {} s\n  "
      "{}\n",
      path, sim.materials.size(), sim.walls.size(), sim.particles.size(), c.dem.end_time,
      c.dem.time_step_note);
  for (const auto& w : c.dem.warnings) fmt::print("warning: {}\n", w);
  return 0;
}

std::function<int()> setup_check(CLI::App& sub) {
  auto path = std::make_shared<std::string>();
  sub.add_option("case", *path, "case file (TOML)")->required();
  return [path] {
    switch (case_kind(*path)) {
      case CaseKind::chain:  // its DEM and pbm cases too
        return check_couple(*path);
      case CaseKind::grain_fit:
        return check_grain_calibration(CaseFile::load(*path));
      case CaseKind::population_balance:
      case CaseKind::population_balance_fit:
        return check_pbm(CaseFile::load(*path));
      case CaseKind::dem:
        break;
    }
    return check_dem(*path);
  };
}

const bool registered = add_command(
    {"check", "Validate a case file (of run, pbm, calibrate or couple) without running it",
     &setup_check});

}  // namespace
}  // namespace comminute::app
