// Walls (geometry of plane, box and cylinder contacts; a moving piston; a rotating drum), SJKR
// adhesion and the elastic–plastic rolling model, each against a closed-form result.
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/cylinder_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

TEST(Walls, CylinderContactGeometry) {
  std::vector<WallContact> c;
  // inside a drum of radius 0.1 along y: a sphere of r = 0.01 whose centre is 0.095 from the axis
  CylinderWall drum({0, 0, 0}, {0, 1, 0}, 0.1, 0.05, true, true);
  ASSERT_EQ(drum.contacts({0.095, 0.0, 0.0}, 0.01, 0.0, c), 1);
  EXPECT_NEAR(c[0].overlap, 0.005, 1e-15);
  EXPECT_NEAR(c[0].normal.x, -1.0, 1e-15);
  c.clear();
  // near the cap at y = -0.025 and the side at once
  ASSERT_EQ(drum.contacts({0.095, -0.02, 0.0}, 0.01, 0.0, c), 2);
  EXPECT_NEAR(c[1].overlap, 0.005, 1e-15);
  EXPECT_NEAR(c[1].normal.y, 1.0, 1e-15);
  c.clear();
  // outside a roll: the rim (edge) contact points from the edge circle to the centre
  CylinderWall roll({0, 0, 0}, {0, 0, 1}, 0.1, 0.2, false, false);
  ASSERT_EQ(roll.contacts({0.103, 0.0, 0.103}, 0.005, 0.0, c), 1);
  EXPECT_NEAR(c[0].overlap, 0.005 - 0.003 * std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(c[0].normal.x, std::sqrt(0.5), 1e-12);
}

TEST(Walls, BoxCornerTouchesThreeFaces) {
  BoxWall box({0, 0, 0}, {1, 1, 1}, {});
  std::vector<WallContact> c;
  EXPECT_EQ(box.contacts({0.005, 0.005, 0.005}, 0.01, 0.0, c), 3);
  for (const auto& w : c) EXPECT_NEAR(w.overlap, 0.005, 1e-15);
}

TEST(Walls, PistonForceIsTheReactionAndItsWorkIsBooked) {
  // A plane piston moving down at 1 mm/s presses a sphere onto a fixed floor (no gravity). The
  // wall reports the force the sphere exerts on it (equal and opposite to the floor's force at
  // quasi-static loading) and the ledger's wall work equals the elastic energy stored plus the
  // energy damped: ∫F v dt. Each contact closes at v/2, so each carries the Hertz force of
  // δ = 10 µm plus the Tsuji damping force γ_n v/2.
  DemSetup s;
  s.restitution = 0.5;
  s.friction = 0.0;
  auto sim = make_simulation(s);
  const double r = 0.005;
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 2 * r}, Vec3{0, 0, -1}));
  sim->walls[1]->kinematics.velocity = {0, 0, -1e-3};
  add_sphere(*sim, {0, 0, r}, r);
  sim->dt = 1e-6;
  sim->setup();
  sim->run(20000);  // 20 µm of travel
  const double top = sim->walls[1]->force.z, bottom = sim->walls[0]->force.z;
  // 20 µm of travel shared by two equal Hertz contacts: δ = 10 µm each (the sphere stays centred)
  const double estar = sim->materials.pair(0, 0).effective_modulus;
  const double m = sim->particles.mass[0], delta = 1e-5;
  const double gamma = -2 * std::sqrt(5.0 / 6.0) * sim->materials.pair(0, 0).damping_beta *
                       std::sqrt(2 * estar * std::sqrt(r * delta) * m);
  const double hertz = 4.0 / 3.0 * estar * std::sqrt(r) * std::pow(delta, 1.5) + gamma * 0.5e-3;
  EXPECT_NEAR(top, hertz, 0.002 * hertz);  // 0.2 %: the sphere's inertia at 1 mm/s is negligible
  EXPECT_NEAR(top, -bottom, 1e-3 * top);   // quasi-static: action = reaction
  const Observables o = sim->observe();
  const double booked = o.elastic + o.kinetic_translational + o.ledger.damping;
  EXPECT_NEAR(o.ledger.wall_work, booked, 0.01 * booked);  // 1 %: first-order work quadrature
}

TEST(Walls, RotatingDrumDragsASphereToTheWallSpeed) {
  // A sphere resting on the inside of a drum turning about its axis (no gravity along the drum,
  // centripetal push from an initial velocity is avoided: gravity pulls it onto the wall) is
  // carried along by friction: after a transient its contact point moves with the wall,
  // v_contact = ω × r (no slip).
  DemSetup s;
  s.friction = 0.8;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double R = 0.1, r = 0.005, omega = 0.5;
  sim->walls.push_back(
      std::make_unique<CylinderWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}, R, 0.05, true, false));
  sim->walls[0]->kinematics.angular_velocity = {0, omega, 0};
  add_sphere(*sim, {0, 0, -(R - r)}, r);
  sim->dt = 2e-6;
  sim->setup();
  sim->run(50000);  // 0.1 s: the sphere climbs a little and rolls with the wall
  const auto& c = sim->wall_contacts();
  ASSERT_EQ(c.size(), 1u);
  const Vec3 x = sim->particles.x[0];
  const Vec3 n = x / norm(x);  // outward radial direction
  const Vec3 contact_velocity = sim->particles.v[0] + cross(sim->particles.w[0], r * n);
  const Vec3 wall_velocity = cross(Vec3{0, omega, 0}, x + r * n);
  // 1e-3 m/s against a wall speed of 0.05 m/s: no-slip within the tangential spring's creep
  EXPECT_LT(norm(contact_velocity - wall_velocity), 1e-3);
}

TEST(Adhesion, SjkrSphereOnAPlaneRestsAtTheBalancedOverlap) {
  // Hertz + SJKR at rest on a plane under gravity: (4/3) E* sqrt(R) δ^1.5 − k_c 2π R δ = m g.
  // The balanced overlap is found by bisection and compared to the simulated one (0.1 %: the
  // damped oscillation has decayed to far below that after 0.05 s).
  DemSetup s;
  s.restitution = 0.3;
  s.friction = 0.5;
  s.cohesion = 2e5;  // J/m3
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double r = 0.002;
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  add_sphere(*sim, {0, 0, r}, r);
  sim->dt = 1e-6;
  sim->setup();
  sim->run(50000);
  const double m = sim->particles.mass[0], estar = sim->materials.pair(0, 0).effective_modulus;
  auto net = [&](double d) {
    return 4.0 / 3.0 * estar * std::sqrt(r) * std::pow(d, 1.5) - 2e5 * 2 * M_PI * r * d - m * 9.81;
  };
  double lo = 1e-12, hi = 1e-3;
  // the adhesive term dominates at small δ: start the bracket where the net force is negative
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (net(mid) < 0 ? lo : hi) = mid;
  }
  const double overlap = r - sim->particles.x[0].z;
  EXPECT_NEAR(overlap, lo, 1e-3 * lo);
  EXPECT_GT(lo, 1.2 * std::pow(m * 9.81 / (4.0 / 3.0 * estar * std::sqrt(r)),
                               2.0 / 3.0));  // adhesion matters
}

TEST(Rolling, EpsdStopsARollingSphereLikeFullyMobilisedResistance) {
  // Once the rolling spring is fully mobilised, the EPSD torque is μ_r R F_n, as the constant-
  // torque model: the stop distance 7 v0² / (10 μ_r g) holds up to the short elastic phase
  // (2 %).
  DemSetup s;
  s.friction = 0.8;
  s.rolling = "epsd";
  s.rolling_friction = 0.1;
  s.restitution = 0.3;
  s.youngs = 1e8;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double r = 0.005, v0 = 0.2;
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  add_sphere(*sim, {0, 0, r * 0.9999}, r);
  sim->dt = 2e-6;
  sim->setup();
  sim->run(2500);
  sim->particles.v[0] = {v0, 0, 0};
  sim->particles.w[0] = {0, v0 / r, 0};
  const double x0 = sim->particles.x[0].x;
  for (int k = 0; k < 500000 && sim->particles.v[0].x > 1e-4; ++k) sim->step();
  const double expected = 7.0 * v0 * v0 / (10.0 * 0.1 * 9.81);
  EXPECT_NEAR(sim->particles.x[0].x - x0, expected, 0.02 * expected);
}
