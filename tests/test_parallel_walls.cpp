// The particle–wall loop takes its chunks of candidates on whichever thread is free and combines
// their sums in chunk order (engine/wall_force_loop.hpp): its forces, torques and the walls'
// reactions must not depend on the number of threads at all. The name starts with "Parallel" so
// that scripts/test runs it in the ThreadSanitizer build too.
#include <gtest/gtest.h>
#include <omp.h>

#include "comminute/core/rng.hpp"
#include "comminute/engine/pair_tracker.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"
#include "mesh_fixture.hpp"

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

// The wall candidates and the mesh's element lists of a neighbour-list build are searched on all
// threads, each over a range of the particles, and joined in range order: they must be those of
// one thread, record for record and list for list (a list joined out of order would hand a
// particle another's triangles). 6000 spheres (threaded: 4096 or more) above a tiled mesh floor
// and beside a plane.
TEST(ParallelWalls, CandidatesOfABuildOnTwoThreadsAreThoseOfOne) {
  const double r = 0.001, skin = 0.0004, side = 0.2;
  ParticleStore p;
  Rng rng(5);
  for (int k = 0; k < 6000; ++k) {
    ParticleInit init;
    init.radius = r * (0.5 + 0.5 * rng.uniform());
    init.x = {side * rng.uniform(), side * rng.uniform(),
              3 * r * rng.uniform()};  // many within reach of the floor
    init.density = 2500;
    p.add(init);
  }
  PairTracker::Walls walls;
  walls.push_back(mesh_wall(tiled_square(40, side / 40)));
  walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
  struct Built {
    std::vector<WallContactRecord> candidates;
    std::vector<std::vector<std::uint32_t>> lists;  // the floor's, per particle
  };
  auto build = [&](int threads) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    PairTracker tracker;
    SimulationOptions options;
    options.skin = skin;
    options.sort_every = 0;
    ContactStateStore pair_state, wall_state;
    EXPECT_TRUE(tracker.update(p, walls, options, pair_state, wall_state));
    omp_set_num_threads(saved);
    Built b{tracker.wall_candidates().records(), {}};
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      const auto list = tracker.wall_candidates().elements().find(0, i);
      EXPECT_TRUE(list.has_value());
      if (list) b.lists.emplace_back(list->begin(), list->end());
    }
    return b;
  };
  const Built one = build(1), two = build(2);
  std::size_t on_floor = 0, listed = 0;
  for (const auto& c : one.candidates) on_floor += c.wall == 0 ? 1 : 0;
  for (const auto& l : one.lists) listed += l.empty() ? 0 : 1;
  EXPECT_GT(on_floor, 1000u);  // a real search: many candidates and lists on both walls
  EXPECT_GT(one.candidates.size(), on_floor + 10);
  EXPECT_GT(listed, 1000u);
  ASSERT_EQ(one.candidates.size(), two.candidates.size());
  for (std::size_t q = 0; q < one.candidates.size(); ++q) {
    const WallContactRecord &a = one.candidates[q], &b = two.candidates[q];
    EXPECT_TRUE(a.particle == b.particle && a.wall == b.wall && a.feature == b.feature &&
                a.id == b.id)
        << "candidate " << q;
  }
  EXPECT_EQ(one.lists, two.lists);
}
