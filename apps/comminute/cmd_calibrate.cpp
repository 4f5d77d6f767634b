// `comminute calibrate case.toml`: fits free parameters of a population balance to measured
// size distributions, or bond parameters of a bonded grain to a measured single-grain
// compression curve ([calibration.compression]), by multi-start Nelder–Mead, with a progress
// line while it works.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <limits>

#include "case_kind.hpp"
#include "command.hpp"
#include "comminute/core/csv_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/calibration_case.hpp"
#include "comminute/io/case/grain_compression_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "pbm_commands.hpp"
#include "pbm_output.hpp"

namespace comminute::app {

namespace {

// Parameters are in the unit of their case key: the header says so with the unit "case".
// starts.csv and best_parameters.csv, common to both modes.
void write_starts(const std::filesystem::path& dir, const calibrate::ParameterSpace& space,
                  const calibrate::MultiStartResult& r) {
  {
    std::vector<Column> cols = {{"start", "-"},
                                {"squared_error", "-"},
                                {"evaluations", "-"},
                                {"iterations", "-"},
                                {"converged", "-"}};
    for (std::size_t i = 0; i < space.size(); ++i)
      cols.push_back({"start:" + space[i].name, "case"});
    for (std::size_t i = 0; i < space.size(); ++i)
      cols.push_back({"best:" + space[i].name, "case"});
    Table t("starts", cols);
    for (const auto& s : r.starts) {
      std::vector<Cell> row = {s.index, s.f, s.run.evaluations, s.run.iterations,
                               s.run.converged ? 1 : 0};
      for (double v : s.start) row.emplace_back(v);
      for (double v : s.best) row.emplace_back(v);
      t.add_row(row);
    }
    t.write(dir);
  }
  const auto& best = r.starts[r.best];
  {
    Table t("best_parameters",
            {{"key", "-"}, {"value", "case"}, {"min", "case"}, {"max", "case"}, {"scale", "-"}});
    for (std::size_t i = 0; i < space.size(); ++i)
      t.add_row({space[i].name, best.best[i], space[i].lower, space[i].upper,
                 space[i].scale == calibrate::Scale::log ? "log" : "linear"});
    t.write(dir);
  }
}

void write_results(const std::filesystem::path& dir, const io::CalibrationCase& cc,
                   const calibrate::MultiStartResult& r) {
  write_starts(dir, cc.space, r);
  const auto& best = r.starts[r.best];
  Table t("fit",
          {{"dataset", "-"}, {"time", "s"}, {"size", "m"}, {"measured", "-"}, {"simulated", "-"}});
  for (const auto& p : cc.fit(best.best))
    t.add_row({p.dataset, p.time, p.size, p.measured, p.simulated});
  t.write(dir);
}

// The progress line: one report per finished start.
struct Progress {
  bool tty = isatty(fileno(stderr)) != 0;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  std::shared_ptr<double> best_f =
      std::make_shared<double>(std::numeric_limits<double>::infinity());
  void operator()(std::size_t done, std::size_t total, const calibrate::StartResult& s) const {
    *best_f = std::min(*best_f, s.f);
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print(stderr,
               "{}calibrate: {}/{} starts done, this start {:.4e} ({} evaluations), "
               "best {:.4e}, {:.1f} s{}",
               tty ? "\r" : "", done, total, s.f, s.run.evaluations, *best_f, el,
               tty && done < total ? "" : "\n");
  }
};

void print_best(const calibrate::ParameterSpace& space, const calibrate::MultiStartResult& r,
                const std::filesystem::path& dir) {
  const auto& best = r.starts[r.best];
  fmt::print("calibrate: best squared error {:.6e} (start {} of {})\n", best.f, best.index,
             r.starts.size());
  for (std::size_t i = 0; i < space.size(); ++i)
    fmt::print("  {} = {:.6g}   [{:g}, {:g}]\n", space[i].name, best.best[i], space[i].lower,
               space[i].upper);
  fmt::print("calibrate: wrote {}\n", dir.string());
}

// Bond parameters of a bonded grain against a measured single-grain compression curve.
// With `evaluate`, no fit: the compression at the case's own values.
int calibrate_grain(const CaseFile& cf, bool evaluate) {
  const auto root = cf.root();
  const auto out_table = root.optional_table("output");
  const std::filesystem::path dir = out_table ? io::read_output_options(*out_table).directory
                                              : io::default_output_options(cf.path()).directory;
  const io::GrainCalibrationCase cc = io::read_grain_calibration(cf);
  cf.reject_unknown();
  std::filesystem::create_directories(dir);
  std::vector<double> values = cc.case_values;
  calibrate::MultiStartResult r;
  if (!evaluate) {
    r = calibrate::multistart(cc.space, cc.objective, cc.options, Progress{});
    values = r.starts[r.best].best;
    write_starts(dir, cc.space, r);
  }
  const io::ForceDisplacement sim = cc.simulate(values);
  Table fit("fit", {{"displacement", "m"}, {"measured", "N"}, {"simulated", "N"}});
  for (std::size_t i = 0; i < cc.measured.displacement.size(); ++i)
    fit.add_row({cc.measured.displacement[i], cc.measured.force[i],
                 io::force_at(sim, cc.measured.displacement[i])});
  fit.write(dir);
  Table curve("compression", {{"displacement", "m"}, {"force", "N"}});
  for (std::size_t k = 0; k < sim.displacement.size(); ++k)
    curve.add_row({sim.displacement[k], sim.force[k]});
  curve.write(dir);
  if (evaluate) {
    fmt::print("calibrate: objective {:.6e} at the case's values; wrote {}\n", cc.objective(values),
               dir.string());
    return 0;
  }
  print_best(cc.space, r, dir);
  return 0;
}

}  // namespace

int calibrate_pbm_case(const std::filesystem::path& file, bool no_plots) {
  return calibrate_pbm_case(CaseFile::load(file), no_plots);
}

int calibrate_pbm_case(const CaseFile& cf, bool no_plots) {
  const auto root = cf.root();
  io::read_pbm_problem(root);  // validates the pbm part (and marks its keys used)
  const io::PbmOutput out = io::read_pbm_output(root, cf.path());
  const io::CalibrationCase cc = io::read_calibration(cf);
  cf.reject_unknown();

  const auto r = calibrate::multistart(cc.space, cc.objective, cc.options, Progress{});
  const auto& best = r.starts[r.best];
  write_results(out.directory, cc, r);
  // The size distributions of the best fit at the case's output times.
  const auto best_case = cc.case_with(best.best);
  pbm::Problem p = io::read_pbm_problem(best_case.root());
  const pbm::Solution s = pbm::solve(p);
  write_distributions(out.directory / "distributions.csv", p, s.times, s.number);
  write_models(out.directory, p, s);

  print_best(cc.space, r, out.directory);
  if (out.plots && !no_plots) {
    plot("calibrate", out.directory);
    plot("pbm", out.directory);
  }
  return 0;
}

namespace {

std::function<int()> setup_calibrate(CLI::App& sub) {
  auto file = std::make_shared<std::string>();
  auto no_plots = std::make_shared<bool>(false);
  sub.add_option("case", *file, "case file (TOML) with a [calibration] table")->required();
  auto evaluate = std::make_shared<bool>(false);
  sub.add_flag("--no-plots", *no_plots, "write CSV files only");
  sub.add_flag("--evaluate", *evaluate,
               "grain compression mode: no fit, run the compression at the case's own values");
  return [file, no_plots, evaluate] {
    // (a population balance without [calibration] is refused by its reader: [calibration] missing)
    require_case_kind(*file, {CaseKind::grain_fit, CaseKind::population_balance_fit,
                              CaseKind::population_balance});
    // loaded once: the mode is read from it, then the chosen mode reads the rest
    const auto cf = CaseFile::load(*file);
    if (io::is_grain_calibration(cf.root())) return calibrate_grain(cf, *evaluate);
    if (*evaluate)
      throw InputError(cf.path().string(), "calibration", 0,
                       "--evaluate is for a grain compression ([calibration.compression])");
    return calibrate_pbm_case(cf, *no_plots);
  };
}

const bool registered = add_command(
    {"calibrate",
     "Fit population-balance parameters to measured distributions, or bond parameters to a "
     "single-grain compression curve (case.toml)",
     &setup_calibrate});

}  // namespace

}  // namespace comminute::app
