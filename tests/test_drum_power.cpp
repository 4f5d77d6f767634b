// A rotating drum at steady state: the mean shaft power equals the total dissipation rate
// (issue 14, rig test 4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "comminute/geometry/cylinder_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

double stored(const Observables& o) {
  return o.kinetic_translational + o.kinetic_rotational + o.potential_gravity + o.elastic;
}

double dissipated(const Observables& o) {
  return o.ledger.damping + o.ledger.friction;
}

}  // namespace

TEST(DrumPower, MeanShaftPowerEqualsTheDissipationRateAtSteadyState) {
  // 300 beads (r = 3.5 mm) in a capped drum (R = 50 mm, L = 40 mm, axis y) turning at 5 rad/s,
  // a third of the critical speed sqrt(g/R) = 14 rad/s: a rolling/cascading bed.
  DemSetup s;
  // The linear spring-dashpot law (k_n = 2000 N/m, contact time ~1.5 ms, overlaps ~1 % of r):
  // its tangential spring has a constant stiffness, so its stored energy 1/2 k_t xi^2 is a true
  // potential. With hertz_mindlin the same drum closes its energy balance only to about 4 %
  // (dissipation above the shaft work), the Mindlin stiffness 8 G* a changing under a loaded
  // spring as the overlap changes, an energy source no ledger entry books.
  s.law = "linear_spring_dashpot";
  s.linear_stiffness = 2000;
  s.friction = 0.5;
  s.restitution = 0.5;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double R = 0.05, L = 0.04, r = 0.0035, omega = 5.0;
  sim->walls.push_back(std::make_unique<CylinderWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}, R, L,
                                                      /*inside=*/true, /*caps=*/true));
  sim->walls[0]->kinematics.angular_velocity = {0, omega, 0};
  sim->walls[0]->kinematics.center = {0, 0, 0};
  // a loose lattice (spacing 2.3 r) filling the drum from the bottom up
  const double h = 2.3 * r;
  int n = 0;
  for (double z = -R + 1.2 * r; z < R && n < 300; z += h)
    for (double x = -R + 1.2 * r; x < R && n < 300; x += h)
      for (double y = -L / 2 + 1.2 * r; y < L / 2 - 1.2 * r && n < 300; y += h)
        if (std::hypot(x, z) < R - 1.2 * r) {
          add_sphere(*sim, {x, y, z}, r);
          ++n;
        }
  ASSERT_EQ(n, 300);
  sim->dt = 5e-5;  // a thirtieth of the contact time
  sim->setup();
  sim->run(30000);  // 1.5 s spin-up: about 1.2 turns, the bed has settled into its profile
  const Observables a = sim->observe();
  sim->run(100000);  // 5 s window
  const Observables b = sim->observe();
  const double window = b.time - a.time;
  const double power = (b.ledger.wall_work - a.ledger.wall_work) / window;
  const double dissipation = (dissipated(b) - dissipated(a)) / window;
  const double change = (stored(b) - stored(a)) / window;
  std::printf(
      "drum: shaft power %.6g W, dissipation rate %.6g W, stored-energy change rate %.4g W, "
      "balance residual %.3g W\n",
      power, dissipation, change, power - dissipation - change);
  ASSERT_GT(power, 0.0);
  // Energy balance: work in = dissipated + change of stored (kinetic + potential + elastic)
  // energy, up to the integration error. At steady state the stored energy only fluctuates, by
  // about the kinetic energy of the cascading layer (a few mJ here), while the work grows with
  // the window (about 0.07 W x 5 s = 0.36 J); the fluctuation over the window is about 1 % of
  // the work (measured 0.3-1.3 % in 3-5 s windows), and the integration error of the dashpot
  // work another 0.5-1 % at this step, so the 3 % holds with a margin.
  EXPECT_NEAR(dissipation, power, 0.03 * power);
  // the residual itself is the change of stored energy: bounded likewise
  EXPECT_LT(std::abs(change), 0.03 * power);
}
