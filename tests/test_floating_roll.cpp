// The floating roll of a roll press (`hpgr` walls with a `floating` table): roll 2 is a free body
// on the line of centres pushed towards roll 1 by a constant force, stopped at `min_gap`. Empty,
// it runs onto its stop as a body under constant force and stays there; pressing a static chain
// of spheres in the pinch it comes to rest where the particles' force balances the push.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "comminute/core/archive.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/wall_control.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "dem_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// A press with D = 0.5 m, W = 0.05 m, gap 60 mm, rolls all but at rest (speed_rpm = 1e-9: the
// facets move 4e-12 m in a second), no gravity, no chute; `floating` is the floating table. One
// 10 mm sphere floats at rest 0.3 m beyond roll 2, far from everything (a case needs an
// [[insert]]).
std::string press(const std::string& floating, double friction = 0.5) {
  return "[simulation]\nend_time = 1.0\ngravity = [0.0, 0.0, 0.0]\n[contact]\n"
         "model = \"hertz_mindlin\"\n"
         "[materials.ore]\ndensity = 2700.0\nyoungs_modulus = 5.0e7\npoisson_ratio = 0.25\n"
         "[interaction]\nrestitution = 0.3\nfriction = " +
         std::to_string(friction) +
         "\n"
         "[[walls]]\nname = \"press\"\ntype = \"hpgr\"\nmaterial = \"ore\"\ndiameter = 0.5\n"
         "width = 0.05\ngap = 0.06\nspeed_rpm = 1e-9\nsegments = 360\nchute = false\n"
         "side_plates = false\noverhang = 0.1\nfloating = { " +
         floating +
         " }\n"
         "[[insert]]\ntype = \"fill\"\nmaterial = \"ore\"\ncount = 1\n"
         "region = { shape = \"box\", lo = [0.8, -0.02, -0.004], hi = [0.9, 0.02, 0.004] }\n"
         "size = { distribution = \"fixed\", diameter = 0.01 }\n";
}

struct Press {
  io::DemCase c;
  WallControlModule* control = nullptr;
  Wall* roll2 = nullptr;
};

Press build(const TestDir& dir, const std::string& floating, double friction = 0.5) {
  const CaseFile f = CaseFile::parse(press(floating, friction), (dir / "press.toml").string());
  Press p{io::build_dem_case(f.root())};
  for (auto& m : p.c.sim->modules)
    if (auto* w = dynamic_cast<WallControlModule*>(m.get())) p.control = w;
  for (auto& w : p.c.sim->walls)
    if (w->name == "press_roll2") p.roll2 = w.get();
  return p;
}

double gap(const Press& p) {
  return 0.06 - p.control->displacement(0);
}

}  // namespace

TEST(FloatingRoll, EmptyRollAgainstItsStopStaysThere) {
  const TestDir dir;
  Press p = build(dir, "force = 1.0e4, mass = 100.0");  // min_gap = gap: starts on its stop
  ASSERT_NE(p.control, nullptr);
  ASSERT_EQ(p.control->specs().size(), 1u);
  EXPECT_EQ(p.control->specs()[0].name, "press_roll2");
  Simulation& sim = *p.c.sim;
  sim.dt = 1e-5;
  sim.setup();
  const Vec3 c0 = p.roll2->kinematics.center;
  sim.run(2000);
  // exactly: at the stop the roll's velocity is set to zero every step
  EXPECT_EQ(gap(p), 0.06);
  EXPECT_EQ(p.roll2->kinematics.center.x, c0.x);
  // the gap is a column of wall_control.csv
  bool has_gap = false;
  for (const auto& t : p.control->tables(sim))
    for (const auto& col : t.columns()) has_gap |= col.name == "press_roll2_gap" && col.unit == "m";
  EXPECT_TRUE(has_gap);
}

TEST(FloatingRoll, OpenRollClosesUnderItsForceOntoTheStop) {
  // Started 20 mm open of its 40 mm stop: a free body under F (no damping) travels
  // F t² / (2 m); it reaches the stop at t = sqrt(2 m d / F) = 45 ms and stays.
  const TestDir dir;
  Press p = build(dir, "specific_force = 8.0e4, mass = 100.0, min_gap = 0.04");
  const double F = 8.0e4 * 0.5 * 0.05;  // N: specific force × D × W = 2 kN
  ASSERT_EQ(p.control->specs()[0].push, F);
  Simulation& sim = *p.c.sim;
  sim.dt = 1e-5;
  sim.setup();
  sim.run(1000);  // 10 ms: d = F t²/(2 m) = 1 mm
  // the leapfrog is exact for a constant force: 1e-12 m is round-off of the summed steps
  EXPECT_NEAR(0.06 - gap(p), F * 0.01 * 0.01 / (2 * 100.0), 1e-12);
  sim.run(4000);                     // 50 ms: past 45 ms
  EXPECT_NEAR(gap(p), 0.04, 1e-15);  // on the stop, to the round-off of the sum
  sim.run(1000);
  EXPECT_NEAR(gap(p), 0.04, 1e-15);
}

TEST(FloatingRoll, RollOnAStaticBedBalancesItsForce) {
  // Three 20 mm spheres in a row along the line of centres fill the 60 mm gap; the roll, pushed
  // with 100 N and damped near critically, squeezes them until their force balances the push.
  // A row under compression buckles, so two frictionless plates touching it from above and below
  // (z = ±r) hold it straight; without friction they take no force along the line of centres.
  const TestDir dir;
  Press p = build(dir, "force = 100.0, mass = 5.0, damping = 800.0, min_gap = 0.03", 0.0);
  Simulation& sim = *p.c.sim;
  for (double x : {-0.02, 0.0, 0.02}) add_sphere(sim, {x, 0, 0}, 0.01);
  sim.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, -0.01}, Vec3{0, 0, 1}));
  sim.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0.01}, Vec3{0, 0, -1}));
  sim.dt = 4e-5;  // 1/10 of the spheres' Rayleigh time (4e-4 s)
  sim.setup();
  // chain stiffness ~3e4 N/m with m = 5 kg: period 0.08 s; c = 800 N s/m is about critical, so
  // 0.6 s is ~7 decay times
  sim.run(15000);
  const double push = 100.0;
  // force balance of the roll at rest: the particles' force along the line of centres equals the
  // push. 2 % (the bound); what is left after 7 decay times is far below it.
  EXPECT_NEAR(p.roll2->force.x, push, 0.02 * push);
  EXPECT_NEAR(p.control->force(sim, 0), push, 0.02 * push);  // compressive, as a servo's
  EXPECT_LT(gap(p), 0.06);                                   // the chain is squeezed
  EXPECT_GT(gap(p), 0.055);  // by a few Hertz overlaps (~1 mm each), not flattened
  std::printf("floating roll on the chain: gap %.6g m, particles' force %.6g N (push %g N)\n",
              gap(p), p.roll2->force.x, push);
}

TEST(FloatingRoll, MotionContinuesFromACheckpoint) {
  // a roll closing (mid-travel, moving) saved and continued ends where the straight run does,
  // to the bit: its position and velocity are the wall's checkpointed pose and kinematics, its
  // travel the control's
  const TestDir dir;
  const std::string floating = "force = 2000.0, mass = 100.0, damping = 50.0, min_gap = 0.04";
  Press a = build(dir, floating), b = build(dir, floating);
  a.c.sim->dt = b.c.sim->dt = 1e-5;
  a.c.sim->setup();
  a.c.sim->run(1500);
  Archive ar;
  a.c.sim->save(ar);
  b.c.sim->load(ar);
  a.c.sim->run(1500);
  b.c.sim->run(1500);
  EXPECT_GT(gap(a), 0.04);  // still travelling
  EXPECT_LT(gap(a), 0.06);
  EXPECT_EQ(gap(a), gap(b));
  EXPECT_EQ(a.roll2->kinematics.center.x, b.roll2->kinematics.center.x);
  EXPECT_EQ(a.roll2->kinematics.velocity.x, b.roll2->kinematics.velocity.x);
}

TEST(FloatingRoll, BadKeysAreRefused) {
  const TestDir dir;
  const std::pair<std::string, std::string> cases[] = {
      {"mass = 1.0", "floating"},
      {"force = 1.0, specific_force = 1.0, mass = 1.0", "floating"},
      {"force = 1.0, mass = 1.0, min_gap = 0.07", "min_gap"},
      {"force = 1.0, mass = 0.0", "mass"},
      {"force = 1.0, mass = 1.0, stiffness = 3.0", "stiffness"}};
  for (const auto& [bad, key] : cases) {
    const CaseFile f = CaseFile::parse(press(bad), (dir / "press.toml").string());
    try {
      io::build_dem_case(f.root());
      f.reject_unknown();
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(e.key().find(key), std::string::npos) << bad << ": " << e.what();
    }
  }
}
