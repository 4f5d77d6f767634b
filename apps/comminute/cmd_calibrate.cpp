// `comminute calibrate case.toml`: fits free parameters of a population balance to measured
// size distributions by multi-start Nelder–Mead, with a progress line while it works.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <limits>

#include "command.hpp"
#include "comminute/core/csv_table.hpp"
#include "comminute/io/case/calibration_case.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "pbm_commands.hpp"
#include "pbm_output.hpp"

namespace comminute::app {

namespace {

// Parameters are in the unit of their case key: the header says so with the unit "case".
void write_results(const std::filesystem::path& dir, const io::CalibrationCase& cc,
                   const calibrate::MultiStartResult& r) {
  const auto& space = cc.space;
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
  Table t("fit",
          {{"dataset", "-"}, {"time", "s"}, {"size", "m"}, {"measured", "-"}, {"simulated", "-"}});
  for (const auto& p : cc.fit(best.best))
    t.add_row({p.dataset, p.time, p.size, p.measured, p.simulated});
  t.write(dir);
}

}  // namespace

int calibrate_pbm_case(const std::filesystem::path& file, bool no_plots) {
  const auto cf = CaseFile::load(file);
  const auto root = cf.root();
  io::read_pbm_problem(root);  // validates the pbm part (and marks its keys used)
  const io::PbmOutput out = io::read_pbm_output(root, cf.path());
  const io::CalibrationCase cc = io::read_calibration(cf);
  cf.reject_unknown();

  const bool tty = isatty(fileno(stderr)) != 0;
  const auto t0 = std::chrono::steady_clock::now();
  double best_f = std::numeric_limits<double>::infinity();
  auto progress = [&](std::size_t done, std::size_t total, const calibrate::StartResult& s) {
    best_f = std::min(best_f, s.f);
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print(stderr,
               "{}calibrate: {}/{} starts done, this start {:.4e} ({} evaluations), "
               "best {:.4e}, {:.1f} s{}",
               tty ? "\r" : "", done, total, s.f, s.run.evaluations, best_f, el,
               tty && done < total ? "" : "\n");
  };
  const auto r = calibrate::multistart(cc.space, cc.objective, cc.options, progress);
  const auto& best = r.starts[r.best];
  write_results(out.directory, cc, r);
  // The size distributions of the best fit at the case's output times.
  const auto best_case = cc.case_with(best.best);
  pbm::Problem p = io::read_pbm_problem(best_case.root());
  const pbm::Solution s = pbm::solve(p);
  write_distributions(out.directory / "distributions.csv", p, s.times, s.number);
  write_models(out.directory, p, s);

  fmt::print("calibrate: best squared error {:.6e} (start {} of {})\n", best.f, best.index,
             r.starts.size());
  for (std::size_t i = 0; i < cc.space.size(); ++i)
    fmt::print("  {} = {:.6g}   [{:g}, {:g}]\n", cc.space[i].name, best.best[i], cc.space[i].lower,
               cc.space[i].upper);
  fmt::print("calibrate: wrote {}\n", out.directory.string());
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
  sub.add_flag("--no-plots", *no_plots, "write CSV files only");
  return [file, no_plots] { return calibrate_pbm_case(*file, *no_plots); };
}

const bool registered = add_command(
    {"calibrate", "Fit population-balance parameters to measured distributions (case.toml)",
     &setup_calibrate});

}  // namespace

}  // namespace comminute::app
