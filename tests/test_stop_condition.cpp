// Stop conditions: the run loop ends a run after the first step at which a wall force (or stress)
// reaches the condition's value, returns 0, and records when; `after` delays the check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "comminute/core/units.hpp"
#include "comminute/engine/stop_condition.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/run/run_loop.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// One sphere on a fixed floor, pressed by a plane piston that descends at 0.05 m/s: the force on
// the piston grows with every step once it touches.
std::unique_ptr<Simulation> pressed_sphere() {
  DemSetup d;
  d.youngs = 1e8;
  auto sim = make_simulation(d);
  add_sphere(*sim, {0, 0, 1e-3}, 1e-3);
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 2.05e-3}, Vec3{0, 0, -1}));
  sim->walls[1]->name = "piston";
  sim->walls[1]->kinematics.velocity = {0, 0, -0.05};
  sim->dt = 2e-6;  // 0.08 of the Rayleigh time
  return sim;
}

// Runs `sim` with the one condition `c` on the piston until the condition ends the run (exit
// status 0); returns the module.
const StopConditionModule* run_to_stop(Simulation& sim, StopConditionSpec c) {
  c.label = "stop[0]";
  c.wall = 1;
  auto m = std::make_unique<StopConditionModule>(std::vector<StopConditionSpec>{c});
  const StopConditionModule* stop = m.get();
  sim.modules.push_back(std::move(m));
  sim.setup();
  std::FILE* log = std::tmpfile();
  EXPECT_EQ(run::run_until(sim, 1.0, nullptr, nullptr, nullptr, log), 0);
  std::fclose(log);
  return stop;
}

}  // namespace

TEST(StopCondition, EndsTheRunAfterTheFirstStepThatReachesTheForce) {
  const double limit = 2.0;  // N
  // reference: the same run stepped by hand, watching the piston force
  auto ref = pressed_sphere();
  ref->setup();
  std::uint64_t first = 0;
  while (first == 0) {
    ref->step();
    if (norm(ref->walls[1]->force) >= limit) first = ref->step_count;
    ASSERT_LT(ref->step_count, 100000u);
  }
  ASSERT_GT(first, 100u);  // a real approach, not the first step
  auto sim = pressed_sphere();
  StopConditionSpec c;
  c.value = limit;
  const StopConditionModule* stop = run_to_stop(*sim, c);
  EXPECT_EQ(sim->step_count, first);
  ASSERT_TRUE(stop->reached().has_value());
  EXPECT_EQ(stop->reached()->step, first);
  EXPECT_GE(stop->reached()->quantity, limit);
  EXPECT_NE(stop->describe(*sim).find("wall 'piston' force"), std::string::npos);
}

TEST(StopCondition, BelowWithADelayAndAStressQuantity) {
  // 'below 1 Pa' holds from the first step (no contact yet); `after` defers it to t ≥ 1e-4 s
  auto sim = pressed_sphere();
  StopConditionSpec c;
  c.label = "stop[0]";
  c.wall = 1;
  c.area = 1e-6;
  c.value = 1.0;
  c.above = false;
  c.after = 1e-4;
  sim->modules.push_back(std::make_unique<StopConditionModule>(std::vector<StopConditionSpec>{c}));
  sim->setup();
  std::FILE* log = std::tmpfile();
  EXPECT_EQ(run::run_until(*sim, 1.0, nullptr, nullptr, nullptr, log), 0);
  std::fclose(log);
  // the first step with t ≥ 1e-4 s: step 50 (to rounding of 50 additions of 2e-6)
  EXPECT_NEAR(static_cast<double>(sim->step_count), 50.0, 1.0);
  EXPECT_GE(sim->time, 1e-4);
}

TEST(StopCondition, ADirectionComparesTheCompressiveForceAlongIt) {
  // The piston's force is along its normal; a direction at 60 degrees to the normal (into the
  // particles, -z) sees half of it, −F·n = |F| cos 60°, so the condition on 2 N is reached at the
  // first step with |F| >= 4 N (to the round-off of the cosine), later than |F| >= 2 N would be.
  const double limit = 2.0;  // N
  const Vec3 n{std::sin(units::pi / 3), 0, -std::cos(units::pi / 3)};
  auto ref = pressed_sphere();
  ref->setup();
  std::uint64_t first = 0, magnitude_first = 0;
  while (first == 0) {
    ref->step();
    if (magnitude_first == 0 && norm(ref->walls[1]->force) >= limit)
      magnitude_first = ref->step_count;
    if (-dot(ref->walls[1]->force, n) >= limit) first = ref->step_count;
    ASSERT_LT(ref->step_count, 100000u);
  }
  ASSERT_GT(first, magnitude_first);
  // the force on the piston is normal to it: half of it lies along n
  EXPECT_NEAR(-dot(ref->walls[1]->force, n), 0.5 * norm(ref->walls[1]->force),
              1e-12 * norm(ref->walls[1]->force));
  auto sim = pressed_sphere();
  StopConditionSpec c;
  c.value = limit;
  c.direction = n;
  const StopConditionModule* stop = run_to_stop(*sim, c);
  EXPECT_EQ(sim->step_count, first);
  ASSERT_TRUE(stop->reached().has_value());
  EXPECT_GE(stop->reached()->quantity, limit);
  EXPECT_NE(stop->describe(*sim).find("wall 'piston' force along ["), std::string::npos);
}
