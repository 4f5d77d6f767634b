// `comminute check case.toml`: validates a case file without running it.
#include <fmt/format.h>

#include "case_loading.hpp"
#include "command.hpp"

namespace comminute::app {
namespace {

std::function<int()> setup_check(CLI::App& sub) {
  auto path = std::make_shared<std::string>();
  sub.add_option("case", *path, "case file (TOML)")->required();
  return [path] {
    LoadedCase c = load_dem_case(*path);
    check_output_directory(c);
    const Simulation& sim = *c.dem.sim;
    fmt::print(
        "{}: valid\n  {} material(s), {} wall(s), {} particle(s) placed so far, end time {} s\n  "
        "{}\n",
        *path, sim.materials.size(), sim.walls.size(), sim.particles.size(), c.dem.end_time,
        c.dem.time_step_note);
    for (const auto& w : c.dem.warnings) fmt::print("warning: {}\n", w);
    return 0;
  };
}

const bool registered =
    add_command({"check", "Validate a case file without running it", &setup_check});

}  // namespace
}  // namespace comminute::app
