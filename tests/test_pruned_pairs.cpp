// The pruned pair list (neighbor/pruned_pairs.hpp, `[simulation] prune_buffer`): the force loop
// visits only the listed pairs within the prune buffer of touching, pruned again once particles may
// have moved half the buffer (a growing particle keeps all its pairs). A pair left out cannot touch
// before then, so a run with pruning gives the same bits as one that visits every listed pair: the
// checks below are exact, and a pair wrongly left out (tried: a trigger that ignores the travel
// since the prune, a pruned list kept through a replacement, a prune that drops a growing
// particle's pairs) changes them.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "breakage_engine_fixture.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/neighbor/pruned_pairs.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// Spheres on a jittered lattice with random speeds up to `speed` per axis, friction and rolling
// springs, under gravity in a closed box: pairs come into contact and leave it all the time.
std::unique_ptr<Simulation> colliding_bed(int nx, double speed, double prune_buffer) {
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 2.05 * r;
  Rng rng(7);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nx; ++j)
      for (int k = 0; k < nx; ++k)
        add_sphere(
            *sim, {(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a}, r * rng.uniform(0.9, 1.0),
            {speed * rng.uniform(-1, 1), speed * rng.uniform(-1, 1), speed * rng.uniform(-1, 1)});
  sim->walls.push_back(std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{nx * a, nx * a, nx * a},
                                                 std::array<bool, 6>{}));
  sim->options.skin = 0.4 * r;
  sim->options.prune_buffer = prune_buffer;
  sim->dt = 1e-6;
  sim->setup();
  return sim;
}

void expect_same_bits(const Simulation& a, const Simulation& b) {
  EXPECT_EQ(a.particles.id, b.particles.id);
  EXPECT_EQ(a.particles.x, b.particles.x);
  EXPECT_EQ(a.particles.v, b.particles.v);
  EXPECT_EQ(a.particles.w, b.particles.w);
  EXPECT_EQ(a.particles.radius, b.particles.radius);
  EXPECT_EQ(a.pair_state().active, b.pair_state().active);
  EXPECT_EQ(a.observe().elastic, b.observe().elastic);
  EXPECT_EQ(a.ledger.friction, b.ledger.friction);
}

}  // namespace

TEST(PrunedPairs, KeepsExactlyThePairsWithinTheBufferAndTheFlaggedOnes) {
  // A row of spheres 1 mm in radius at growing gaps: the list (skin 0.5 mm) holds the pairs with a
  // gap below 0.5 mm, the pruned list (buffer 0.2 mm) those below 0.2 mm, plus a flagged pair.
  ParticleStore p;
  const double r = 0.001;
  const double gaps[] = {-1e-5, 1e-4, 1.9e-4, 2.1e-4, 3e-4, 4.9e-4, 6e-4, 5e-5};
  double x = 0;
  p.add({{x, 0, 0}, {}, {}, r, 2500, 0, 0});
  for (double g : gaps) {
    x += 2 * r + g;
    p.add({{x, 0, 0}, {}, {}, r, 2500, 0, 0});
  }
  NeighborList list;
  list.build(p, 5e-4);
  ASSERT_EQ(list.size(), 7u);  // the gaps below the skin: all but 6e-4
  std::vector<std::uint8_t> keep(list.size(), 0);
  std::size_t flagged = 0;  // the pair of gap 3e-4
  for (std::size_t k = 0; k < list.size(); ++k)
    if (std::abs(norm(p.x[list.first[k]] - p.x[list.second[k]]) - (2 * r + 3e-4)) < 1e-9)
      flagged = k;
  keep[flagged] = 1;
  PrunedPairs near;
  near.prune(p, list, 2e-4, keep.data());
  std::vector<std::uint32_t> expected;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const double gap = norm(p.x[list.first[k]] - p.x[list.second[k]]) - 2 * r;
    if (gap < 2e-4 || k == flagged) expected.push_back(static_cast<std::uint32_t>(k));
  }
  EXPECT_EQ(near.pairs(), expected);
  EXPECT_EQ(expected.size(), 5u);  // -1e-5, 1e-4, 1.9e-4, 5e-5 and the flagged 3e-4
  // a growing particle keeps all its pairs: particle 4 brings its pairs at gaps 2.1e-4 and 3e-4 in
  p.flags[4] |= pflag::growing;
  near.prune(p, list, 2e-4, nullptr);
  EXPECT_EQ(near.pairs().size(), 6u);  // -1e-5, 1e-4, 1.9e-4, 2.1e-4, 3e-4, 5e-5
  // range(): positions of the kept pairs among the list's pairs [k0, k1)
  const auto [m0, m1] = near.range(0, list.size());
  EXPECT_EQ(m0, 0u);
  EXPECT_EQ(m1, near.pairs().size());
}

TEST(PrunedPairs, CollidingBedGivesTheSameBitsAsTheWholeList) {
  omp_set_num_threads(1);
  auto pruned = colliding_bed(10, 0.5, -1);  // buffer: a quarter of the skin, 0.1 mm
  auto whole = colliding_bed(10, 0.5, 0);
  pruned->run(600);
  whole->run(600);
  omp_set_num_threads(omp_get_num_procs());
  // what the test exercises: the list pruned again many times between rebuilds (speeds to 0.87
  // m/s move a sphere a buffer's half in ~60 steps), thousands of contacts made and ended
  EXPECT_GT(pruned->pair_prunes(), 3 * pruned->neighbor_rebuilds());
  EXPECT_EQ(whole->pair_prunes(), 0u);
  EXPECT_GT(pruned->observe().contacts, 300u);
  expect_same_bits(*pruned, *whole);
}

TEST(PrunedPairs, TwoThreadsGiveTheSameBitsAsTheWholeList) {
  // 24^3 spheres: enough pairs for the force loop and the prune to split between two threads
  omp_set_num_threads(2);
  auto pruned = colliding_bed(24, 0.5, -1);
  auto whole = colliding_bed(24, 0.5, 0);
  pruned->run(150);
  whole->run(150);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_GT(pruned->pair_prunes(), 1u);
  expect_same_bits(*pruned, *whole);
}

TEST(PrunedPairs, BreakageWithGrowingFragmentsGivesTheSameBitsAsTheWholeList) {
  // Fragments replace their parents in place and grow to their final size. Pruning pauses at a
  // replacement until the next rebuild (tried: keeping the pruned list through the update leaves
  // the fragments' new pairs out and changes the bits), and resumes after each rebuild.
  omp_set_num_threads(1);
  breakage::BreakageModule *ma = nullptr, *mb = nullptr;
  auto pruned = breakage_gas(&ma);
  auto whole = breakage_gas(&mb);
  whole->options.prune_buffer = 0;
  pruned->run(500);
  whole->run(500);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_GT(ma->breakages(), 10u);
  EXPECT_GT(pruned->pair_prunes(), 10u);
  EXPECT_EQ(ma->breakages(), mb->breakages());
  expect_same_bits(*pruned, *whole);
}

namespace {
// Grows particle slot 0 by `step` (m) per step before the forces, as fragment growth does (the
// particle is flagged growing, so the neighbour list's rebuild trigger tracks it).
class Inflate final : public Module {
 public:
  explicit Inflate(double step) : step_(step) {}
  std::string name() const override { return "inflate"; }
  void pre_force(Simulation& sim) override { sim.particles.radius[0] += step_; }

 private:
  double step_;
};

std::unique_ptr<Simulation> growing_pair(double prune_buffer) {
  auto sim = make_simulation(DemSetup{});
  const double r = 0.001;
  add_sphere(*sim, {0, 0, 0}, r);
  add_sphere(*sim, {2 * r + 1.5e-4, 0, 0}, r);
  sim->particles.flags[0] |= pflag::growing;
  sim->modules.push_back(std::make_unique<Inflate>(2e-6));
  sim->options.skin = 4e-4;
  sim->options.prune_buffer = prune_buffer;
  sim->dt = 1e-6;
  sim->setup();
  return sim;
}
}  // namespace

TEST(PrunedPairs, AGrowingParticleKeepsItsPairs) {
  // Two spheres at rest 0.15 mm apart: listed (skin 0.4 mm), but farther than the prune buffer
  // (0.1 mm). The first grows 2 um per step and touches the other after 75 steps, before its growth
  // reaches half the skin (the rebuild). Nothing moves, so no prune follows the first: only the
  // rule that a growing particle keeps all its pairs keeps the contact (tried: without it the
  // contact is missed and the bits differ).
  omp_set_num_threads(1);
  auto pruned = growing_pair(1e-4);
  auto whole = growing_pair(0);
  pruned->run(95);
  whole->run(95);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_EQ(pruned->neighbor_rebuilds(), 1u);  // the first build only
  EXPECT_EQ(pruned->pair_prunes(), 1u);
  EXPECT_EQ(whole->observe().contacts, 1u);
  expect_same_bits(*pruned, *whole);
}
