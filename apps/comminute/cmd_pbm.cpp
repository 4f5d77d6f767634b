// `comminute pbm case.toml`: solves a population balance of breakage and writes the size
// distributions at the requested times (CSV, PNG).
#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "case_kind.hpp"
#include "command.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "pbm_commands.hpp"
#include "pbm_output.hpp"

namespace comminute::app {

namespace {

// A negative amount is never reported: one beyond round-off (1e-9 of the total) means the
// solution is wrong (an RK4 step too large for the rates, a model outside its range) and stops
// the command; round-off below zero is reported as 0.
void check_non_negative(pbm::Solution& s, const pbm::Problem& p) {
  for (std::size_t k = 0; k < s.number.size(); ++k) {
    auto& n = s.number[k];
    double total = 0;
    for (Eigen::Index i = 0; i < n.size(); ++i)
      total += std::abs(n[i]) * p.grid.pivot_volume(static_cast<std::size_t>(i));
    for (Eigen::Index i = 0; i < n.size(); ++i) {
      const double v = n[i] * p.grid.pivot_volume(static_cast<std::size_t>(i));
      if (v >= 0) continue;
      if (v < -1e-9 * total || !std::isfinite(v))
        throw SimulationError(fmt::format(
            "class {} at t = {} s has a negative amount ({:.3g} of the total mass): the solution "
            "is not valid (with integrator = \"rk4\", use a smaller solver.time_step or the "
            "adaptive integrator)",
            i, s.times[k], v / total));
      n[i] = 0;
    }
  }
}

}  // namespace

int solve_pbm_case(const std::filesystem::path& file, bool no_plots) {
  require_case_kind(file, {CaseKind::population_balance});
  const auto cf = CaseFile::load(file);
  const auto root = cf.root();
  const pbm::Problem p = io::read_pbm_problem(root);
  const io::PbmOutput out = io::read_pbm_output(root, cf.path());
  cf.reject_unknown();

  const auto t0 = std::chrono::steady_clock::now();
  pbm::Solution s = pbm::solve(p);
  check_non_negative(s, p);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  write_distributions(out.directory / "distributions.csv", p, s.times, s.number);
  write_models(out.directory, p, s);
  const auto first = distribution(p, p.initial_number), last = distribution(p, s.number.back());
  const double drift =
      last.total(analysis::Basis::volume) / first.total(analysis::Basis::volume) - 1;
  fmt::print("pbm: {} classes, {} output times to {} s in {:.2f} ms ({} steps, {} rejected)\n",
             p.grid.classes(), s.times.size(), s.times.back(), ms, s.stats.steps, s.stats.rejected);
  fmt::print("pbm: relative change of total mass {:.3e}; particles {:.6g} -> {:.6g}\n", drift,
             first.total(analysis::Basis::number), last.total(analysis::Basis::number));
  if (p.function && !p.function->summary().empty())
    fmt::print("pbm: breakage function: {}\n", p.function->summary());
  fmt::print("pbm: wrote {}\n", (out.directory / "distributions.csv").string());
  if (out.plots && !no_plots) plot("pbm", out.directory);
  return 0;
}

namespace {

std::function<int()> setup_pbm(CLI::App& sub) {
  auto file = std::make_shared<std::string>();
  auto no_plots = std::make_shared<bool>(false);
  sub.add_option("case", *file, "case file (TOML)")->required();
  sub.add_flag("--no-plots", *no_plots, "write CSV files only");
  return [file, no_plots] { return solve_pbm_case(*file, *no_plots); };
}

const bool registered =
    add_command({"pbm", "Solve a population balance of breakage (case.toml)", &setup_pbm});

}  // namespace

}  // namespace comminute::app
