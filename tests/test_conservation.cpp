// Issue 2, tests 3-5: energy conservation without dissipation, momentum conservation, the weight
// of a settled column on the floor, and contact history across neighbour-list rebuilds and
// particle reordering.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "comminute/core/rng.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

double total_energy(const Simulation& sim) {
  const Observables o = sim.observe();
  return o.kinetic_translational + o.kinetic_rotational + o.potential_gravity + o.elastic;
}

// n spheres of radius r at random non-overlapping places in [0, L]^3 with random velocities.
void scatter(Simulation& sim, int n, double r, double L, double speed, std::uint64_t seed) {
  Rng rng(seed);
  while (static_cast<int>(sim.particles.size()) < n) {
    Vec3 x{rng.uniform(r, L - r), rng.uniform(r, L - r), rng.uniform(r, L - r)};
    bool free = true;
    for (const auto& y : sim.particles.x) free = free && norm(x - y) > 2.05 * r;
    if (free)
      add_sphere(
          sim, x, r,
          {rng.uniform(-speed, speed), rng.uniform(-speed, speed), rng.uniform(-speed, speed)});
  }
}

// 30 spheres of 3 mm radius flying at up to 0.5 m/s in a closed 5 cm box.
std::unique_ptr<Simulation> closed_box_of_bouncing_spheres(const DemSetup& s, double dt) {
  auto sim = make_simulation(s);
  const double L = 0.05, r = 0.003;
  sim->walls.push_back(
      std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{L, L, L}, std::array<bool, 6>{}));
  scatter(*sim, 30, r, L, 0.5, 11);
  sim->dt = dt;
  sim->setup();
  return sim;
}

}  // namespace

TEST(Conservation, EnergyWithoutDampingOrFriction) {
  // e = 1, μ = 0: the only forces are conservative (Hertz springs, gravity). Velocity Verlet
  // does not conserve energy exactly during a contact but has no secular drift; with 40 steps
  // per contact the error of each collision is ~ (dt/tc)^2 ~ 1e-3 of the contact energy, which
  // returns when the contact ends. We assert |ΔE| < 1e-3 E_kin,0 over 10^5 steps, 100+ collisions.
  DemSetup s;
  s.restitution = 1.0;
  s.friction = 0.0;
  s.gravity = {0, 0, -9.81};
  auto sim = closed_box_of_bouncing_spheres(s, 2e-6);
  const double e0 = total_energy(*sim);
  const double k0 = sim->observe().kinetic_translational;
  double worst = 0;
  for (int k = 0; k < 100000; ++k) {
    sim->step();
    if (k % 100 == 0) worst = std::max(worst, std::abs(total_energy(*sim) - e0));
  }
  EXPECT_LT(worst, 1e-3 * k0);
  EXPECT_EQ(sim->ledger.damping, 0.0);
  EXPECT_EQ(sim->ledger.friction, 0.0);
}

TEST(Conservation, LinearMomentumWithoutWallsOrGravity) {
  // Pair forces obey Newton's third law exactly (the same vector is added and subtracted), so the
  // momentum of a free cloud changes only by round-off: |ΔP| < 1e-12 of Σ m|v|.
  DemSetup s;
  s.restitution = 0.4;
  s.friction = 0.5;
  s.rolling = "constant_torque";
  s.rolling_friction = 0.1;
  auto sim = make_simulation(s);
  scatter(*sim, 200, 0.002, 0.04, 0.3, 5);
  // converge on the centre so that everything collides
  for (std::size_t i = 0; i < sim->particles.size(); ++i)
    sim->particles.v[i] += (Vec3{0.02, 0.02, 0.02} - sim->particles.x[i]) * 10.0;
  sim->dt = 2e-6;
  sim->setup();
  const Vec3 p0 = sim->particles.total_momentum();
  double scale = 0;
  for (std::size_t i = 0; i < sim->particles.size(); ++i)
    scale += sim->particles.mass[i] * norm(sim->particles.v[i]);
  sim->run(20000);
  EXPECT_GT(sim->ledger.damping, 0.0);  // there were collisions
  EXPECT_LT(norm(sim->particles.total_momentum() - p0), 1e-12 * scale);
}

TEST(Conservation, SettledColumnWeighsOnTheFloor) {
  // Frictionless side walls carry no vertical load, so once the bed is at rest the floor carries
  // the whole weight. 0.5 % (the tolerance) is far above the residual kinetic effects
  // once the kinetic energy has decayed to 1e-6 of the potential energy scale.
  DemSetup s;
  s.restitution = 0.3;
  s.friction = 0.5;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  sim->materials.add({"wall", 7800, 1e7, 0.3});
  PairInput slick;
  slick.restitution = 0.3;
  slick.friction = 0.0;
  sim->materials.set_pair(0, 1, slick);
  const double L = 0.02;
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{L, L, 0.1});
  sim->walls[0]->material = 1;
  scatter(*sim, 150, 0.0015, L, 0.0, 3);
  sim->dt = 5e-6;
  sim->setup();
  double weight = 0;
  for (double m : sim->particles.mass) weight += m * 9.81;
  sim->run(60000);  // 0.3 s
  double fz = 0;
  const int avg = 2000;
  for (int k = 0; k < avg; ++k) {
    sim->step();
    fz += sim->walls[0]->force.z;
  }
  fz /= avg;
  EXPECT_LT(sim->observe().kinetic_translational, 1e-6 * weight * L);
  EXPECT_NEAR(-fz, weight, 0.005 * weight);
}

TEST(ContactHistory, SurvivesRebuildAndReorder) {
  // Two identical runs; in one, the neighbour list is rebuilt and the particle order reversed in
  // the middle of a sticking contact. The tangential force must continue unchanged: the history
  // moves with the particle ids (and flips sign when the pair's owner changes).
  auto make = [] {
    DemSetup s;
    s.friction = 0.8;
    s.gravity = {3.0, 0, -9.81};  // pushes the top sphere sideways: a loaded tangential spring
    auto sim = make_simulation(s);
    add_sphere(*sim, {0, 0, 0}, 0.005);
    add_sphere(*sim, {0.0005, 0, 0.00995}, 0.005);
    sim->particles.flags[0] |= pflag::fixed;
    sim->gravity = {3.0, 0, -9.81};
    sim->dt = 2e-6;
    sim->setup();
    return sim;
  };
  auto a = make(), b = make();
  a->run(5000);
  b->run(5000);
  // reorder b and force a rebuild
  std::vector<std::size_t> reverse(b->particles.size());
  std::iota(reverse.rbegin(), reverse.rend(), 0);
  b->particles.permute(reverse);
  b->particles_changed();
  a->run(3);
  b->run(3);
  const std::size_t ia = slot_of(*a, 2), ib = slot_of(*b, 2);
  const auto& state = a->pair_state();
  ASSERT_GT(norm(state.at(0).vec3(state.vec3_slot("tangential_spring"))), 0.0);  // loaded spring
  EXPECT_EQ(a->particles.x[ia], b->particles.x[ib]);
  EXPECT_EQ(a->particles.v[ia], b->particles.v[ib]);
  EXPECT_EQ(a->particles.f[ia], b->particles.f[ib]);
  EXPECT_EQ(a->particles.t[ia], b->particles.t[ib]);
}

class EnergyBalance : public ::testing::TestWithParam<std::string> {};

TEST_P(EnergyBalance, BalancesWithDampingAndFriction) {
  // With damping and friction, kinetic + potential + elastic + dissipated energy stays at its
  // initial value. Linear law: the ledger integrates the dissipation with the mid-step velocities
  // of velocity Verlet; measured closure 0.1-0.6 %, asserted 2 %. Hertz–Mindlin: the tangential
  // spring force k_t(δ)·ξ with a stiffness that changes with the overlap (the total-displacement
  // form LIGGGHTS also uses) is not exactly conservative; measured 3 %, asserted 6 %.
  DemSetup s;
  s.law = GetParam();
  s.linear_stiffness = 2000;
  s.restitution = 0.5;
  s.friction = 0.5;
  s.gravity = {0, 0, -9.81};
  auto sim = closed_box_of_bouncing_spheres(s, 5e-7);
  const double e0 = total_energy(*sim);
  sim->run(400000);
  const double dissipated = sim->ledger.damping + sim->ledger.friction;
  ASSERT_GT(sim->ledger.friction, 0.05 * dissipated);  // both mechanisms were active
  ASSERT_GT(sim->ledger.damping, 0.05 * dissipated);
  const double tol = s.law == "linear_spring_dashpot" ? 0.02 : 0.06;
  EXPECT_NEAR(total_energy(*sim) + dissipated, e0, tol * dissipated);
}

INSTANTIATE_TEST_SUITE_P(Laws, EnergyBalance,
                         ::testing::Values("linear_spring_dashpot", "hertz_mindlin"));
