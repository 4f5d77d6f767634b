// A light pre-load held before the ramp (servo walls, `preload_force` / `preload_time`): a
// servo piston closes on a sphere resting on the floor, holds the pre-load until the hold's end
// and only then drives on to its target.
#include <gtest/gtest.h>

#include <fstream>

#include "case_sections.hpp"
#include "comminute/engine/wall_control.hpp"
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
  {
    using namespace comminute::testing;
    std::ofstream(dir.path() / "hold.toml")
        << dem_sections({1, 1.0, 1e-6, 0.0}, {"rock", 2500.0, 1.0e8, 0.25, 0.3, 0.0})
        << plane_wall("floor", 0.0, 1.0, "rock")
        << plane_wall("piston", 0.00205, -1.0, "rock",
                      "control = { mode = \"servo\", target_force = 10.0, gain = 5e-2, "
                      "max_speed = 0.05" +
                          preload + " }")
        << data_file_insert("rock", "sphere.data");
  }
  comminute::testing::LoadedCase loaded = comminute::testing::load_case(dir.path() / "hold.toml");
  Simulation& sim = *loaded.dem.sim;
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
