// `comminute check case.toml`: validates a case file without running it.
#include <fmt/format.h>

#include "case_loading.hpp"
#include "command.hpp"
#include "couple_command.hpp"

namespace comminute::app {
namespace {

std::function<int()> setup_check(CLI::App& sub) {
  auto path = std::make_shared<std::string>();
  sub.add_option("case", *path, "case file (TOML)")->required();
  return [path] {
    if (CaseFile::load(*path).root().has("couple")) {  // a chain: its DEM and pbm cases too
      const PreparedCouple pc = prepare_couple_case(*path);
      fmt::print("{}: valid couple case\n  DEM case {}: end time {} s\n  pbm case {}: {}\n", *path,
                 pc.couple.dem.string(), pc.dem.dem.end_time, pc.couple.pbm.string(),
                 pc.pbm_checked ? "valid" : "valid up to the files the DEM stage writes");
      return 0;
    }
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
