#include "comminute/run/couple.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "comminute/analysis/collision_log.hpp"
#include "comminute/analysis/grid_statistics.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/io/case/calibration_case.hpp"
#include "comminute/io/case/pbm_case.hpp"

namespace comminute::run {

namespace {

// Whether `p` lies in the folder `dir` (both made absolute and normalised; nothing is resolved on
// disk, so a folder that does not exist yet works).
bool inside(const std::filesystem::path& p, const std::filesystem::path& dir) {
  const auto a = std::filesystem::absolute(p).lexically_normal();
  const auto d = std::filesystem::absolute(dir).lexically_normal();
  auto ai = a.begin();
  for (auto di = d.begin(); di != d.end(); ++di, ++ai) {
    if (di->empty()) continue;  // the trailing "" of a path ending in a separator
    if (ai == a.end() || *ai != *di) return false;
  }
  return ai != a.end();
}

// The pbm case's output folder is a path it names too, but an output, not an input.
bool is_input_key(const std::string& key) {
  return key != "output.directory";
}

// Line of a dotted key ("mill.spectrum_file") in the case; 0 when it is not a plain table path.
long line_of(const CaseTable& root, const std::string& key) {
  std::optional<CaseTable> t = root;
  std::string rest = key;
  for (auto dot = rest.find('.'); dot != std::string::npos && t; dot = rest.find('.')) {
    t = t->optional_table(rest.substr(0, dot));
    rest = rest.substr(dot + 1);
  }
  return t ? t->line(rest) : 0;
}

}  // namespace

CoupleCase read_couple_case(const CaseTable& root) {
  const CaseTable t = root.table("couple");
  CoupleCase c{t, t.input_file("dem"), t.input_file("pbm"), {}, 1, std::nullopt, true};
  c.directory = t.has("directory") ? t.file_path("directory")
                                   : root.file().parent_path() / "output" / "couple";
  c.threads = static_cast<int>(t.integer("threads", 1, 1024, 1));
  if (t.has("window")) c.window = t.number("window", Limits::positive());
  c.plots = t.boolean("plots", true);
  return c;
}

DemObservers require_observers(const Simulation& sim, const CoupleCase& c) {
  DemObservers o;
  for (const auto& m : sim.modules) {
    if (const auto* l = dynamic_cast<const analysis::CollisionLogModule*>(m.get()))
      o.collisions = l;
    if (const auto* g = dynamic_cast<const analysis::GridStatistics*>(m.get())) o.grid = g;
  }
  if (!o.collisions && !o.grid)
    c.table.fail("dem", fmt::format("the DEM case '{}' has neither [collisions] nor "
                                    "[grid_statistics]: it writes nothing a population balance "
                                    "reads",
                                    c.dem.string()));
  if (c.window && !o.collisions)
    c.table.fail("window", fmt::format("the window is the collision log's, and the DEM case '{}' "
                                       "has no [collisions]",
                                       c.dem.string()));
  return o;
}

std::function<bool(const Simulation&)> window_reached(const analysis::CollisionLogModule& log,
                                                      double window) {
  // half a step of slack: the window grows by whole steps
  return [&log, window](const Simulation& sim) {
    return log.window_open() && log.window_length(sim.time) >= window - 0.5 * sim.dt;
  };
}

void check_dem_stage(const DemObservers& o, const CoupleCase& c, const Simulation& sim) {
  if (!o.collisions) return;
  const double now = sim.time;
  if (!o.collisions->window_open())
    throw Error(fmt::format(
        "the DEM stage ended at t = {:.6g} s before its collision log's window opened (no steady "
        "state detected, or [collisions] start not reached): the spectra are empty. Raise "
        "simulation.end_time of '{}', or loosen [collisions.steady_state] (tolerance, blocks)",
        now, c.dem.string()));
  const double length = o.collisions->window_length(now);
  if (c.window && length < *c.window - 0.5 * sim.dt)
    throw Error(fmt::format(
        "the DEM stage ended at t = {:.6g} s with {:.6g} s of steady-state window (from "
        "{:.6g} s), less than couple.window = {:.6g} s of '{}': raise simulation.end_time of '{}'",
        now, length, o.collisions->window_start(), *c.window, c.table.file().string(),
        c.dem.string()));
}

std::optional<PbmCase> read_pbm_case(const std::filesystem::path& path,
                                     const std::filesystem::path& dem_output, bool dem_pending) {
  PbmCase p{CaseFile::load(path), false};
  const CaseTable root = p.file.root();
  p.calibrates = root.has("calibration");
  try {
    io::read_pbm_problem(root);
    io::read_pbm_output(root, p.file.path());
    if (p.calibrates) io::read_calibration(p.file);
  } catch (const InputError& e) {
    if (!dem_pending) throw;
    const auto files = p.file.data_files();
    const auto f = files.find(e.key());
    std::error_code ec;
    if (f == files.end() || !is_input_key(f->first) || !inside(f->second, dem_output) ||
        std::filesystem::exists(f->second, ec))
      throw;
    return std::nullopt;  // a file the DEM stage writes: read again after it
  }
  p.file.reject_unknown();
  return p;
}

std::vector<std::pair<std::string, std::filesystem::path>> dem_inputs(
    const CaseFile& pbm, const std::filesystem::path& dem_output) {
  std::vector<std::pair<std::string, std::filesystem::path>> out;
  for (const auto& [key, path] : pbm.data_files())
    if (is_input_key(key) && inside(path, dem_output)) out.emplace_back(key, path);
  return out;
}

void check_pbm_reads_dem(const CoupleCase& c, const CaseFile& pbm,
                         const std::filesystem::path& dem_output,
                         const std::filesystem::path& stage_marker) {
  const auto inputs = dem_inputs(pbm, dem_output);
  if (inputs.empty())
    c.table.fail("pbm", fmt::format("the population-balance case '{}' reads no file of the DEM "
                                    "case's output folder '{}': point its spectrum or frequency "
                                    "file (e.g. mill.spectrum_file, rate.frequency_file) there",
                                    c.pbm.string(), dem_output.string()));
  const auto started = std::filesystem::last_write_time(stage_marker);
  for (const auto& [key, path] : inputs)
    if (std::filesystem::last_write_time(path) < started)
      throw InputError(pbm.path().string(), key, line_of(pbm.root(), key),
                       fmt::format("'{}' was not written by the DEM stage of this run (it is "
                                   "older): the DEM case '{}' does not write it; check the "
                                   "contact type in its name",
                                   path.string(), c.dem.string()));
}

Table couple_table(const CoupleSummary& s) {
  Table t("couple", {{"quantity", "-"}, {"value", "-"}, {"unit", "-"}});
  t.add_row({"dem_end_time", s.dem_end_time, "s"});
  t.add_row({"window_start", s.window_start, "s"});
  t.add_row({"window_length", s.window_length, "s"});
  t.add_row({"calibrated", s.calibrated ? 1 : 0, "-"});
  for (const auto& [key, path] : s.links) t.add_row({"link:" + key, path.filename().string(), "-"});
  return t;
}

}  // namespace comminute::run
