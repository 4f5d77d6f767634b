// Force-controlled walls: a servo piston holds its target stress on a static bed; a dead-weight
// piston falls freely at g and comes to rest on a bed carrying its weight m g; the displacement
// and velocity survive a checkpoint.
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/core/rng.hpp"
#include "comminute/engine/wall_control.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double kSide = 0.01;  // m, the box is 10 mm × 10 mm: area 1e-4 m²
constexpr double kArea = kSide * kSide;

// A 5 × 5 × 5 stack of spheres of radius 1 mm − spread·u (u uniform in [0, 1)) in a box open at
// the top, and a plane piston (normal −z, into the bed) touching the top layer. Returns the index
// of the piston wall.
std::size_t build_bed(Simulation& sim, std::uint64_t seed, double spread = 0.03e-3) {
  Rng rng(seed, 0);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        add_sphere(sim, {1e-3 + 2e-3 * i, 1e-3 + 2e-3 * j, 1e-3 + 2e-3 * k},
                   1e-3 - spread * rng.uniform());
  std::array<bool, 6> open{};
  open[5] = true;  // +z
  sim.walls.push_back(std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{kSide, kSide, 0.02}, open));
  sim.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0.01}, Vec3{0, 0, -1}));
  sim.walls.back()->name = "piston";
  return sim.walls.size() - 1;
}

DemSetup bed_setup() {
  DemSetup d;
  d.youngs = 1e8;
  d.restitution = 0.3;
  d.friction = 0.3;
  return d;
}

}  // namespace

TEST(WallControl, ServoHoldsItsTargetStressOnAStaticBed) {
  auto sim = make_simulation(bed_setup());
  WallControlSpec s;
  s.wall = build_bed(*sim, 1);
  s.direction = {0, 0, -1};
  s.area = kArea;
  const double target_stress = 1e5;  // Pa: 10 N on the piston, overlaps about 4 % of a radius
  s.target_force = target_stress * kArea;
  // bed stiffness seen by the piston ~ 25 columns of 5 Hertz contacts, k ≈ 8e4 N/m: the loop's
  // time constant 1 / (G k) ≈ 2.5 ms is 20 times the bed's wave transit (~0.13 ms): quasi-static
  s.gain = 5e-3;       // m/(N s)
  s.max_speed = 0.02;  // m/s
  auto m = std::make_unique<WallControlModule>(std::vector<WallControlSpec>{s});
  WallControlModule* servo = m.get();
  sim->modules.push_back(std::move(m));
  sim->dt = 4e-6;  // 0.15 of the Rayleigh time
  sim->setup();
  sim->run(10000);  // 0.04 s: about 16 time constants
  double worst = 0, mean = 0;
  const int window = 5000;  // 0.02 s, every step
  for (int k = 0; k < window; ++k) {
    sim->step();
    const double stress = servo->force(*sim, 0) / kArea;
    worst = std::max(worst, std::abs(stress / target_stress - 1));
    mean += stress / window;
  }
  // the requirement: within 2 % at every step of the window, not only on average
  EXPECT_LT(worst, 0.02) << "mean stress " << mean;
  EXPECT_NEAR(mean, target_stress, 0.005 * target_stress);
  EXPECT_GT(servo->displacement(0), 0.0);  // it moved into the bed
}

TEST(WallControl, DeadWeightFallsFreelyAtG) {
  auto sim = make_simulation({});
  sim->gravity = {0, 0, -9.81};
  add_sphere(*sim, {1, 1, 1}, 1e-3);  // far away, never touched
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  WallControlSpec s;
  s.mode = WallControlSpec::Mode::dead_weight;
  s.direction = {0, 0, 1};
  s.mass = 2.0;
  auto m = std::make_unique<WallControlModule>(std::vector<WallControlSpec>{s});
  WallControlModule* weight = m.get();
  sim->modules.push_back(std::move(m));
  sim->dt = 1e-4;
  sim->setup();
  const int n = 2000;
  sim->run(n);
  const double t = n * sim->dt;
  // leapfrog is exact for a constant acceleration: z = −g t²/2 to rounding of 2000 sums
  const double z = dynamic_cast<PlaneWall&>(*sim->walls[0]).point().z;
  EXPECT_NEAR(z, -0.5 * 9.81 * t * t, 1e-12);
  EXPECT_NEAR(weight->displacement(0), -0.5 * 9.81 * t * t, 1e-12);
  // the velocity over the next step is the mid-step velocity −g (t + dt/2)
  EXPECT_NEAR(sim->walls[0]->kinematics.velocity.z, -9.81 * (t + 0.5 * sim->dt), 1e-12);
}

TEST(WallControl, DeadWeightComesToRestCarriedByTheBed) {
  DemSetup d = bed_setup();
  // linear contacts with strong damping (restitution 0.1): their damping does not vanish at the
  // small overlaps of a light load as Hertz damping does, so the weight's bounce on the bed dies
  d.law = "linear_spring_dashpot";
  d.linear_stiffness = 1e4;  // N/m
  d.restitution = 0.1;
  d.gravity = {0, 0, -9.81};
  auto sim = make_simulation(d);
  // frictionless walls: the bottom carries the whole weight (the spheres keep their friction)
  sim->materials.add({"wall", 7800, 2e11, 0.3});
  PairInput smooth;
  smooth.restitution = d.restitution;
  smooth.friction = 0.0;
  sim->materials.set_pair(0, 1, smooth);
  WallControlSpec s;
  s.wall = build_bed(*sim, 2, 0.0);  // equal spheres: the weight starts on all 25 columns
  for (auto& w : sim->walls) w->material = 1;
  s.mode = WallControlSpec::Mode::dead_weight;
  s.direction = {0, 0, -1};
  s.area = kArea;
  s.mass = 0.01;  // kg: m g / A = 981 Pa, 8 times the bed's own weight per area
  auto m = std::make_unique<WallControlModule>(std::vector<WallControlSpec>{s});
  WallControlModule* weight = m.get();
  sim->modules.push_back(std::move(m));
  sim->dt = 4e-6;  // 0.15 of the Rayleigh time
  sim->setup();
  double bed_mass = 0;
  for (double mass : sim->particles.mass) bed_mass += mass;
  sim->run(20000);          // 0.08 s: the weight's oscillation on the bed has decayed
  const int window = 5000;  // 0.02 s
  double stress = 0, bottom = 0;
  for (int k = 0; k < window; ++k) {
    sim->step();
    stress += weight->force(*sim, 0) / kArea / window;
    bottom += -sim->walls[0]->force.z / kArea / window;
  }
  const double expected = s.mass * 9.81 / kArea;
  // Time averages over the window differ from m g by m (v_end − v_start) / T: a weight at rest
  // (below 1 mm/s: m Δv / T < 1e-3 N, 1 % of m g) has settled to m g / A within 1 %, the stated
  // tolerance; the bottom carries that plus the bed's own weight (frictionless side walls).
  EXPECT_NEAR(stress, expected, 0.01 * expected);
  EXPECT_NEAR(bottom, expected + bed_mass * 9.81 / kArea, 0.01 * expected);
  EXPECT_LT(std::abs(sim->walls[1]->kinematics.velocity.z), 1e-3);  // at rest (m/s)
}

TEST(WallControl, StateSurvivesACheckpoint) {
  auto build = [](std::unique_ptr<Simulation>& sim) {
    sim = make_simulation(bed_setup());
    WallControlSpec s;
    s.wall = build_bed(*sim, 3);
    s.direction = {0, 0, -1};
    s.area = kArea;
    s.target_force = 5;
    s.gain = 5e-3;
    s.max_speed = 0.02;
    sim->modules.push_back(std::make_unique<WallControlModule>(std::vector<WallControlSpec>{s}));
    sim->dt = 4e-6;  // 0.15 of the Rayleigh time
  };
  std::unique_ptr<Simulation> a, b;
  build(a);
  a->setup();
  a->run(3000);
  Archive ar;
  a->save(ar);
  build(b);
  b->load(ar);
  a->run(1000);
  b->run(1000);
  const auto& wa = dynamic_cast<const WallControlModule&>(*a->modules.back());
  const auto& wb = dynamic_cast<const WallControlModule&>(*b->modules.back());
  EXPECT_EQ(wa.displacement(0), wb.displacement(0));
  EXPECT_EQ(a->walls[1]->kinematics.velocity.z, b->walls[1]->kinematics.velocity.z);
  EXPECT_EQ(wa.force(*a, 0), wb.force(*b, 0));
  EXPECT_GT(wa.displacement(0), 0.0);
}
