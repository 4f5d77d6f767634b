// `comminute run case.toml`: runs a DEM case to its end time.
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>

#include "case_loading.hpp"
#include "command.hpp"

namespace comminute::app {
namespace {

struct RunArgs {
  std::string case_path;
  std::string output;
  int threads = 0;
};

std::function<int()> setup_run(CLI::App& sub) {
  auto a = std::make_shared<RunArgs>();
  sub.add_option("case", a->case_path, "case file (TOML)")->required();
  sub.add_option("-o,--output", a->output, "output folder (default: [output] directory)");
  sub.add_option("-t,--threads", a->threads, "OpenMP threads (default: all cores)");
  return [a] {
    if (a->threads > 0) omp_set_num_threads(a->threads);
    LoadedCase c = load_dem_case(a->case_path);
    Simulation& sim = *c.dem.sim;
    fmt::print(stderr, "{}\n", c.dem.time_step_note);
    for (const auto& w : c.dem.warnings) fmt::print(stderr, "warning: {}\n", w);
    sim.setup();
    const auto steps = static_cast<std::uint64_t>(std::ceil((c.dem.end_time - sim.time) / sim.dt));
    const auto t0 = std::chrono::steady_clock::now();
    std::uint64_t particle_steps = 0;
    for (std::uint64_t s = 0; s < steps; ++s) {
      particle_steps += sim.particles.size();
      sim.step();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Observables o = sim.observe();
    fmt::print(stderr, "done: t = {:.6g} s, {} steps, {} particles, {} contacts, {:.3g} s wall, {:.3g} particle-steps/s\n",
               o.time, o.step, o.particles, o.contacts, wall, static_cast<double>(particle_steps) / wall);
    return 0;
  };
}

const bool registered = add_command({"run", "Run a DEM case", &setup_run});

}  // namespace
}  // namespace comminute::app
