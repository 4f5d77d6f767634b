// When the neighbour list is rebuilt: at the first step after which some particle lies more than
// skin/2 from where it was at the last build (Verlet's criterion), never sooner and never later.
// The engine decides it mostly from a bound (the drifts' largest steps summed since the build,
// measured exactly only when the bound passes skin/2); these tests keep their own copy of the
// positions at each build and check every step's decision against the exact displacement, on a
// bed that expands fast (a rebuild every few steps: the drift measures every step) and on one
// that falls and settles slowly (tens of steps between rebuilds: the bound decides most steps),
// on one and on two threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "comminute/core/rng.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

struct Timing {
  std::uint64_t rebuilds = 0;
  std::uint64_t longest_gap = 0;  // most steps between two rebuilds
  std::vector<std::uint64_t> rebuild_steps;
};

// Runs `steps` steps, checking each step's rebuild decision against the exact displacements.
Timing check_rebuilds(Simulation& sim, int steps) {
  const double limit = 0.5 * sim.options.skin;
  std::vector<Vec3> x_build(sim.particles.x);  // the set-up built the lists here
  Timing timing;
  std::uint64_t last = 0;
  for (int s = 0; s < steps; ++s) {
    const std::uint64_t before = sim.neighbor_rebuilds();
    // the positions the step's forces see are those at its end (the last half kick keeps them)
    sim.step();
    double worst = 0;
    for (std::size_t i = 0; i < sim.particles.size(); ++i)
      worst = std::max(worst, norm(sim.particles.x[i] - x_build[i]));
    const bool rebuilt = sim.neighbor_rebuilds() != before;
    if (rebuilt) {
      // (a rebuild may re-sort the store: the copy is taken after it)
      EXPECT_GT(worst, limit) << "rebuilt at step " << sim.step_count << " though no particle "
                              << "had moved skin/2 (largest " << worst << " m)";
      x_build = sim.particles.x;
      ++timing.rebuilds;
      timing.rebuild_steps.push_back(sim.step_count);
      timing.longest_gap = std::max(timing.longest_gap, sim.step_count - last);
      last = sim.step_count;
    } else {
      EXPECT_LE(worst, limit) << "not rebuilt at step " << sim.step_count << " though a particle "
                              << "had moved " << worst << " m > skin/2 = " << limit << " m";
    }
  }
  return timing;
}

// A compressed lattice of 8^3 spheres (spacing 1.9 r: every neighbour overlaps) in an open-top box:
// it springs apart, and the small skin gives a rebuild every few steps.
std::unique_ptr<Simulation> expanding_bed() {
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 1.9 * r;
  const int nx = 8;
  Rng rng(5);
  for (int k = 0; k < nx * nx * nx; ++k) {
    const int i = k % nx, j = (k / nx) % nx, l = k / (nx * nx);
    add_sphere(*sim, {(i + 0.5) * a + 0.05 * r, (j + 0.5) * a + 0.05 * r, (l + 0.5) * a + 0.05 * r},
               r * rng.uniform(0.95, 1.0));
  }
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{nx * a + 0.1 * r, nx * a + 0.1 * r, 1.0});
  sim->options.skin = 0.02 * r;
  sim->dt = 2e-6;
  sim->setup();
  return sim;
}

// 1000 spheres at rest on a loose grid falling onto the floor of a box: at first every particle
// moves alike (the bound is nearly exact), then the bed's collisions jiggle them (it is not).
std::unique_ptr<Simulation> falling_bed() {
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 2.2 * r;
  const int nx = 10;
  Rng rng(9);
  for (int k = 0; k < nx * nx * nx; ++k) {
    const int i = k % nx, j = (k / nx) % nx, l = k / (nx * nx);
    add_sphere(*sim, {(i + 0.5) * a, (j + 0.5) * a, (l + 0.5) * a + 0.1 * r},
               r * rng.uniform(0.9, 1.0));
  }
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{nx * a, nx * a, 1.0});
  sim->options.skin = 0.2 * r;
  sim->dt = 1e-5;
  sim->setup();
  return sim;
}

}  // namespace

TEST(RebuildTiming, AnExpandingBedIsRebuiltExactlyWhenAParticleMovedHalfTheSkin) {
  const int saved = omp_get_max_threads();
  std::vector<std::uint64_t> steps_on_one;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto sim = expanding_bed();
    const Timing t = check_rebuilds(*sim, 300);
    // the test sees what it claims: many rebuilds, a few steps apart
    EXPECT_GE(t.rebuilds, 20u);
    if (threads == 1)
      steps_on_one = t.rebuild_steps;
    else
      EXPECT_EQ(t.rebuild_steps, steps_on_one);  // the same decisions on any thread count
  }
  omp_set_num_threads(saved);
}

TEST(RebuildTiming, AFallingBedIsRebuiltExactlyWhenAParticleMovedHalfTheSkin) {
  const int saved = omp_get_max_threads();
  std::vector<std::uint64_t> steps_on_one;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto sim = falling_bed();
    const Timing t = check_rebuilds(*sim, 3000);
    // rebuilds both tens of steps apart (decided by the bound in between) and in the settling bed
    EXPECT_GE(t.rebuilds, 5u);
    EXPECT_GE(t.longest_gap, 30u);
    if (threads == 1)
      steps_on_one = t.rebuild_steps;
    else
      EXPECT_EQ(t.rebuild_steps, steps_on_one);
  }
  omp_set_num_threads(saved);
}
