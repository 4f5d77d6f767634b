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

// nx^3 spheres of radius r_min..1 mm on a cubic lattice of spacing `a` (lifted by `lift`) in an
// open-top box, with the given skin and time step.
struct Lattice {
  int nx;
  double a, lift, r_min, skin, dt;
  std::uint64_t seed;
};
std::unique_ptr<Simulation> lattice_bed(const Lattice& l) {
  auto sim = make_simulation(frictional_rolling_setup());
  Rng rng(l.seed);
  for (int k = 0; k < l.nx * l.nx * l.nx; ++k) {
    const int i = k % l.nx, j = (k / l.nx) % l.nx, h = k / (l.nx * l.nx);
    add_sphere(*sim, {(i + 0.5) * l.a + l.lift, (j + 0.5) * l.a + l.lift, (h + 0.5) * l.a + l.lift},
               rng.uniform(l.r_min, 0.001));
  }
  const double side = l.nx * l.a + 2 * l.lift;
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{side, side, 1.0});
  sim->options.skin = l.skin;
  sim->dt = l.dt;
  sim->setup();
  return sim;
}

// A compressed lattice of 8^3 spheres (spacing 1.9 mm: every neighbour overlaps): it springs
// apart, and the small skin (0.02 mm) gives a rebuild every few steps.
std::unique_ptr<Simulation> expanding_bed() {
  return lattice_bed({8, 0.0019, 0.00005, 0.00095, 0.00002, 2e-6, 5});
}

// 1000 spheres at rest on a loose lattice (spacing 2.2 mm) falling onto the floor of a box: at
// first every particle moves alike (the bound is nearly exact), then the bed's collisions jiggle
// them (it is not).
std::unique_ptr<Simulation> falling_bed() {
  return lattice_bed({10, 0.0022, 0.0001, 0.0009, 0.0002, 1e-5, 9});
}

// The timing of a bed's rebuilds on one thread, after checking that two threads rebuild at the
// same steps.
template <class Bed>
Timing on_one_and_two_threads(Bed&& bed, int steps) {
  const int saved = omp_get_max_threads();
  std::vector<Timing> t;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto sim = bed();
    t.push_back(check_rebuilds(*sim, steps));
  }
  omp_set_num_threads(saved);
  EXPECT_EQ(t[1].rebuild_steps, t[0].rebuild_steps);
  return t[0];
}

}  // namespace

TEST(RebuildTiming, AnExpandingBedIsRebuiltExactlyWhenAParticleMovedHalfTheSkin) {
  const Timing t = on_one_and_two_threads(expanding_bed, 300);
  // the test sees what it claims: many rebuilds, a few steps apart
  EXPECT_GE(t.rebuilds, 20u);
}

TEST(RebuildTiming, AFallingBedIsRebuiltExactlyWhenAParticleMovedHalfTheSkin) {
  const Timing t = on_one_and_two_threads(falling_bed, 3000);
  // rebuilds both tens of steps apart (decided by the bound in between) and in the settling bed
  EXPECT_GE(t.rebuilds, 5u);
  EXPECT_GE(t.longest_gap, 30u);
}
