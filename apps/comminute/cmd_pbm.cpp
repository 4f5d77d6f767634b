// `comminute pbm case.toml`: solves a population balance of breakage and writes the size
// distributions at the requested times (CSV, PNG).
#include <fmt/format.h>

#include <chrono>

#include "command.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "pbm_output.hpp"

namespace comminute::app {

namespace {

std::function<int()> setup_pbm(CLI::App& sub) {
  auto file = std::make_shared<std::string>();
  auto no_plots = std::make_shared<bool>(false);
  sub.add_option("case", *file, "case file (TOML)")->required();
  sub.add_flag("--no-plots", *no_plots, "write CSV files only");
  return [file, no_plots] {
    const auto cf = CaseFile::load(*file);
    const auto root = cf.root();
    const pbm::Problem p = io::read_pbm_problem(root);
    const io::PbmOutput out = io::read_pbm_output(root, cf.path());
    cf.reject_unknown();

    const auto t0 = std::chrono::steady_clock::now();
    const pbm::Solution s = pbm::solve(p);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    write_distributions(out.directory / "distributions.csv", p, s.times, s.number);
    write_models(out.directory, p, s);
    const auto first = distribution(p, p.initial_number), last = distribution(p, s.number.back());
    const double drift =
        last.total(analysis::Basis::volume) / first.total(analysis::Basis::volume) - 1;
    fmt::print("pbm: {} classes, {} output times to {} s in {:.2f} ms ({} steps, {} rejected)\n",
               p.grid.classes(), s.times.size(), s.times.back(), ms, s.stats.steps,
               s.stats.rejected);
    fmt::print("pbm: relative change of total mass {:.3e}; particles {:.6g} -> {:.6g}\n", drift,
               first.total(analysis::Basis::number), last.total(analysis::Basis::number));
    if (p.function && !p.function->summary().empty())
      fmt::print("pbm: breakage function: {}\n", p.function->summary());
    fmt::print("pbm: wrote {}\n", (out.directory / "distributions.csv").string());
    if (out.plots && !*no_plots) plot("pbm", out.directory);
    return 0;
  };
}

const bool registered =
    add_command({"pbm", "Solve a population balance of breakage (case.toml)", &setup_pbm});

}  // namespace

}  // namespace comminute::app
