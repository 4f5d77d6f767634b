// A light pre-load held before the ramp (servo walls, `preload_force` / `preload_time`): a
// servo piston closes on a sphere resting on the floor, holds the pre-load until the hold's end
// and only then drives on to its target.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "comminute/engine/wall_control.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

constexpr double kHold = 0.02;  // s

// The piston's compressive force at t = 0.019 s (in the hold) and t = 0.04 s, and its
// displacement over the last 5 ms of the hold.
struct Seen {
  double in_hold = 0, after = 0, hold_travel = 0;
};

Seen press(const std::string& preload) {
  comminute::testing::TestDir dir;
  std::ofstream(dir.path() / "sphere.data")
      << "# one sphere on the floor\n\n1 atoms\n1 atom types\n\nAtoms # sphere\n\n"
      << "1 1 0.002 2500 0 0 0.001\n";
  std::ofstream(dir.path() / "hold.toml") << fmt::format(R"(
[simulation]
seed = 1
end_time = 1.0
time_step = 1e-6
[contact]
model = "hertz_mindlin"
[materials.rock]
density = 2500.0
youngs_modulus = 1.0e8
poisson_ratio = 0.25
[interaction]
restitution = 0.3
friction = 0.0
[[walls]]
name = "floor"
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "rock"
[[walls]]
name = "piston"
type = "plane"
point = [0.0, 0.0, 0.00205]
normal = [0.0, 0.0, -1.0]
material = "rock"
control = {{ mode = "servo", target_force = 10.0, gain = 5e-2, max_speed = 0.05{} }}
[[insert]]
type = "data_file"
material = "rock"
file = "sphere.data"
)",
                                                         preload);
  const CaseFile file = CaseFile::load(dir.path() / "hold.toml");
  io::DemCase dem = io::build_dem_case(file.root());
  io::decide_time_step(dem);
  file.reject_unknown();
  Simulation& sim = *dem.sim;
  const WallControlModule* control = nullptr;
  for (const auto& m : sim.modules)
    if (auto* c = dynamic_cast<const WallControlModule*>(m.get())) control = c;
  sim.setup();
  Seen seen;
  sim.run(15000);
  const double d0 = control->displacement(0);
  sim.run(4000);  // t = 0.019 s
  seen.in_hold = control->force(sim, 0);
  seen.hold_travel = control->displacement(0) - d0;
  sim.run(21000);  // t = 0.04 s
  seen.after = control->force(sim, 0);
  return seen;
}

}  // namespace

TEST(PreloadHold, ServoHoldsThePreloadThenRampsToTheTarget) {
  const Seen held = press(", preload_force = 1.0, preload_time = 0.02");
  const Seen plain = press("");
  RecordProperty("held_in_hold", std::to_string(held.in_hold));
  RecordProperty("held_travel_last_5ms", std::to_string(held.hold_travel));
  RecordProperty("held_after", std::to_string(held.after));
  RecordProperty("plain_in_hold", std::to_string(plain.in_hold));
  // The loop's time constant is 1/(G k) ≈ 1.5 ms (k ≈ 1.3e4 N/m at 1 N: the two Hertz contacts
  // in series, E* = 5.3e7 Pa, 58 um overlap each): by 19 ms, 18 ms after closing (~1 ms at
  // 0.05 m/s), the force error is e^-12 of the pre-load: within 1 % of it, and the wall has
  // stopped (under 0.1 um in the last 5 ms, of the ~0.1 mm travelled into the contacts)
  EXPECT_NEAR(held.in_hold, 1.0, 0.01);
  EXPECT_LT(std::abs(held.hold_travel), 1e-7);
  // after the hold it drives on to the target: 20 ms later (more than 13 time constants; stiffer
  // at 10 N: faster), within 1 %
  EXPECT_NEAR(held.after, 10.0, 0.1);
  // without the pre-load the same piston is at the target already at 0.019 s
  EXPECT_NEAR(plain.in_hold, 10.0, 0.1);
}
