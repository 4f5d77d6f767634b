// The particle–wall loop takes its chunks of candidates on whichever thread is free and combines
// their sums in chunk order (engine/wall_force_loop.hpp): its forces, torques and the walls'
// reactions must not depend on the number of threads at all. The name starts with "Parallel" so
// that scripts/test runs it in the ThreadSanitizer build too.
#include <gtest/gtest.h>
#include <omp.h>

#include "comminute/core/rng.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

struct WallRun {
  std::vector<Vec3> f, t;
  Vec3 wall_force, wall_torque;
  EnergyLedger ledger;
};

// One layer of 64 x 64 spheres pressed into the floor of a box, apart from each other (spacing
// 2.1 r: no particle–particle contact, so every force is the wall's and gravity's), sliding and
// spinning at random: 4096 wall candidates, enough for the loop to run on all threads. 20 steps,
// so that the contacts' tangential springs are carried from step to step.
WallRun floor_layer(int threads) {
  omp_set_num_threads(threads);
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 2.1 * r;
  const int nx = 64;
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{nx * a, nx * a, 1.0});
  Rng rng(21);
  for (int j = 0; j < nx; ++j)
    for (int i = 0; i < nx; ++i)
      add_sphere(*sim, {(i + 0.5) * a, (j + 0.5) * a, r * rng.uniform(0.97, 0.999)}, r,
                 {rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), 0});
  for (auto& w : sim->particles.w) w = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
  sim->dt = 1e-5;
  sim->run(20);
  return {sim->particles.f, sim->particles.t, sim->walls[0]->force, sim->walls[0]->torque,
          sim->ledger};
}

}  // namespace

TEST(ParallelWalls, ForcesAndTalliesDoNotDependOnTheThreadCount) {
  const int saved = omp_get_max_threads();
  const WallRun one = floor_layer(1);
  const WallRun two = floor_layer(2);
  omp_set_num_threads(saved);
  // exact: the same sums in the same order on one thread and two (a split by thread would add
  // the walls' reactions and the energies in two partial sums, which differ in round-off)
  EXPECT_EQ(one.f, two.f);
  EXPECT_EQ(one.t, two.t);
  EXPECT_EQ(one.wall_force, two.wall_force);
  EXPECT_EQ(one.wall_torque, two.wall_torque);
  EXPECT_EQ(one.ledger.damping, two.ledger.damping);
  EXPECT_EQ(one.ledger.friction, two.ledger.friction);
  // the test has something to compare: the floor carries the layer's weight and friction works
  EXPECT_GT(one.wall_force.z, 0.0);
  EXPECT_GT(one.ledger.friction, 0.0);
}
