// Sorting the particle store by grid cell at neighbour-list rebuilds (`[simulation] sort_every`)
// changes where each particle is stored, never the physics: the contact state (tangential spring,
// EPSD rolling spring), the wall contacts and the per-particle fields follow their particles, so
// a sorted run differs from an unsorted one only by the order in which forces are summed, and a
// run that sorts restarts from a checkpoint bit for bit (the sort falls on the same rebuilds).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "breakage_engine_fixture.hpp"
#include "comminute/core/rng.hpp"
#include "dem_fixture.hpp"
#include "restart_twin.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// A compressed lattice of 12^3 spheres (spacing 1.9 r, radii 0.95..1 r: every neighbour overlaps)
// with sliding friction and EPSD rolling springs, in a box with an open top, stored in a random
// order: a sort moves nearly every particle, and the touching pairs carry tangential and rolling
// springs through each rebuild. The small skin makes the expanding bed rebuild every few steps.
std::unique_ptr<Simulation> shuffled_bed(int sort_every) {
  omp_set_num_threads(1);
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 1.9 * r;
  const int nx = 12;
  std::vector<int> site(nx * nx * nx);
  std::iota(site.begin(), site.end(), 0);
  Rng rng(21);
  for (std::size_t k = site.size() - 1; k > 0; --k) std::swap(site[k], site[rng.below(k + 1)]);
  for (int q : site) {
    const int i = q % nx, j = (q / nx) % nx, k = q / (nx * nx);
    add_sphere(*sim, {(i + 0.5) * a + 0.05 * r, (j + 0.5) * a + 0.05 * r, (k + 0.5) * a + 0.05 * r},
               r * rng.uniform(0.95, 1.0), {rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01), 0});
  }
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{nx * a + 0.1 * r, nx * a + 0.1 * r, 1.0});
  sim->options.skin = 0.02 * r;
  sim->options.sort_every = sort_every;
  sim->dt = 2e-6;
  sim->setup();
  return sim;
}

// The breakage gas (breakage_engine_fixture.hpp, breakage_gas: weak 3 mm spheres at up to 3 m/s in
// a closed box) sorting every `sort_every` rebuilds: parents are replaced by fragments between
// sorts, so damage, the growing fragments' fields and the module's pending work must follow the
// permutations.
std::unique_ptr<Simulation> sorting_breakage_gas(breakage::BreakageModule** module,
                                                 int sort_every = 1) {
  omp_set_num_threads(1);
  auto sim = breakage_gas(module);
  sim->options.sort_every = sort_every;
  return sim;
}

// Whether one of the `n0` first particles (ids 1..n0) is stored at slot n0 or beyond. Unsorted, a
// store never moves a particle up: fragments take their parents' slots or are appended at the end,
// removals move the rest down. A cell sort mixes the fragments in.
bool first_particle_stored_beyond(const ParticleStore& p, std::uint64_t n0) {
  for (std::size_t i = n0; i < p.size(); ++i)
    if (p.id[i] <= n0) return true;
  return false;
}

// Slot of each id (ids are 1..n).
std::vector<std::size_t> slots_by_id(const ParticleStore& p) {
  std::vector<std::size_t> s(p.size() + 1);
  for (std::size_t i = 0; i < p.size(); ++i) s[p.id[i]] = i;
  return s;
}

}  // namespace

TEST(CellSort, SortingChangesOnlyTheSummationOrder) {
  const int steps = 200;
  auto plain = shuffled_bed(0);
  auto sorted = shuffled_bed(1);
  plain->run(steps);
  sorted->run(steps);
  omp_set_num_threads(omp_get_num_procs());
  const ParticleStore& a = plain->particles;
  const ParticleStore& b = sorted->particles;
  ASSERT_EQ(a.size(), b.size());
  // the test exercises what it claims: many rebuilds (each one a sort), most particles moved away
  // from their slot, and thousands of touching pairs carrying springs through the rebuilds
  EXPECT_GE(sorted->neighbor_rebuilds(), 10u);
  EXPECT_EQ(plain->neighbor_rebuilds(), sorted->neighbor_rebuilds());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.size(); ++i) moved += a.id[i] != b.id[i] ? 1 : 0;
  EXPECT_GT(moved, a.size() / 2);
  const Observables oa = plain->observe(), ob = sorted->observe();
  ASSERT_GT(oa.contacts, 3000u);
  // Contacts by count exactly: no pair is near enough to the touching threshold for rounding to
  // flip it (a lost or duplicated pair would change the count).
  EXPECT_EQ(oa.contacts, ob.contacts);
  EXPECT_EQ(oa.wall_contacts, ob.wall_contacts);
  // Positions and velocities by id: a sum of ~12 contact forces per particle taken in another order
  // differs by a few ulp (~1e-16 relative); 200 steps of the expanding bed amplify that without
  // reaching 1e-12 of the radius in position or 1e-9 of the largest speed (measured: 5e-18 m,
  // 3e-14 of 0.8 m/s, 3e-11 of 460 rad/s). Springs dropped at each sort (checked by breaking the
  // carry on purpose) give 8e-5 m, 0.2 m/s, 330 rad/s and 59 more contacts.
  const auto sb = slots_by_id(b);
  double dx = 0, dv = 0, dw = 0, vmax = 0, wmax = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = sb[a.id[i]];
    dx = std::max(dx, norm(a.x[i] - b.x[j]));
    dv = std::max(dv, norm(a.v[i] - b.v[j]));
    dw = std::max(dw, norm(a.w[i] - b.w[j]));
    vmax = std::max(vmax, norm(a.v[i]));
    wmax = std::max(wmax, norm(a.w[i]));
  }
  EXPECT_LT(dx, 1e-12 * 0.001);
  EXPECT_LT(dv, 1e-9 * vmax);
  EXPECT_LT(dw, 1e-9 * wmax);
  // Energies (sums over all particles and contacts in slot order): rounding only, 1e-9 relative.
  EXPECT_NEAR(oa.kinetic_translational, ob.kinetic_translational, 1e-9 * oa.kinetic_translational);
  EXPECT_NEAR(oa.kinetic_rotational, ob.kinetic_rotational, 1e-9 * oa.kinetic_rotational);
  EXPECT_NEAR(oa.elastic, ob.elastic, 1e-9 * oa.elastic);
}

TEST(CellSort, RestartOfASortingRunIsBitForBit) {
  // Checkpoint after 60 steps of a run that sorts at every third rebuild; the continuation from
  // the checkpoint must equal the uninterrupted run exactly, slot by slot (same sorts at the same
  // steps, same contact state), including the rebuilds (and sorts) after the restart.
  auto full = shuffled_bed(3);
  auto resumed = shuffled_bed(3);
  std::uint64_t rebuilds_at_save = 0;
  run_restart_twin(*full, *resumed, 60, 60, [&] { rebuilds_at_save = full->neighbor_rebuilds(); });
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_GE(full->neighbor_rebuilds(), rebuilds_at_save + 3);
  EXPECT_EQ(full->neighbor_rebuilds(), resumed->neighbor_rebuilds());
  EXPECT_EQ(full->particles.id, resumed->particles.id);
  EXPECT_EQ(full->particles.x, resumed->particles.x);
  EXPECT_EQ(full->particles.v, resumed->particles.v);
  EXPECT_EQ(full->particles.w, resumed->particles.w);
  EXPECT_EQ(full->pair_state().active, resumed->pair_state().active);
  EXPECT_EQ(full->observe().elastic, resumed->observe().elastic);
}

TEST(CellSort, BreakageRunThatSortsRestartsBitForBit) {
  breakage::BreakageModule *ma = nullptr, *mb = nullptr;
  auto a = sorting_breakage_gas(&ma);
  auto b = sorting_breakage_gas(&mb);
  a->setup();
  std::uint64_t rebuilds_at_save = 0, breakages_at_save = 0;
  run_restart_twin(*a, *b, 300, 300, [&] {
    rebuilds_at_save = a->neighbor_rebuilds();
    breakages_at_save = ma->breakages();
  });
  omp_set_num_threads(omp_get_num_procs());
  // sorts and breakages on both sides of the checkpoint
  EXPECT_GT(rebuilds_at_save, 2u);
  EXPECT_GT(a->neighbor_rebuilds(), rebuilds_at_save + 2);
  EXPECT_GT(breakages_at_save, 0u);
  EXPECT_GT(ma->breakages(), breakages_at_save);
  EXPECT_EQ(ma->breakages(), mb->breakages());
  EXPECT_EQ(ma->pending(), mb->pending());
  EXPECT_EQ(a->neighbor_rebuilds(), b->neighbor_rebuilds());
  EXPECT_EQ(a->particles.id, b->particles.id);
  EXPECT_EQ(a->particles.x, b->particles.x);
  EXPECT_EQ(a->particles.radius, b->particles.radius);
  for (std::size_t k = 0; k < a->particles.field_names().size(); ++k)
    EXPECT_EQ(a->particles.field(k), b->particles.field(k)) << a->particles.field_names()[k];
  EXPECT_EQ(ma->fines_mass(), mb->fines_mass());
  EXPECT_EQ(ma->log().size(), mb->log().size());
}

TEST(CellSort, FragmentsAreSortedInOnceTheyAreAnEighthOfTheStore) {
  // Fragments are appended at the end of the store (but for one per parent, in its slot). With
  // sort_every = 1000 the periodic rule sorts only at the first rebuild; the second rule sorts at
  // the first rebuild after the fragments appended since the last sort exceed an eighth of the
  // store, so they end up among the first particles, which move up. Without sorting
  // (sort_every = 0) the first particles stay in the first slots: the check can tell.
  breakage::BreakageModule *ma = nullptr, *mb = nullptr;
  auto never = sorting_breakage_gas(&ma, 0);
  auto rare = sorting_breakage_gas(&mb, 1000);
  const std::uint64_t n0 = never->particles.size();
  never->run(600);
  rare->run(600);
  omp_set_num_threads(omp_get_num_procs());
  // enough fragments for the rule to fire (the two runs differ by round-off, which in a breaking
  // gas is enough to change a breakage or two, so each is checked)
  ASSERT_GT(never->particles.size(), n0 + n0 / 8);
  ASSERT_GT(rare->particles.size(), n0 + n0 / 8);
  EXPECT_GT(rare->neighbor_rebuilds(), 1u);
  EXPECT_FALSE(first_particle_stored_beyond(never->particles, n0));
  EXPECT_TRUE(first_particle_stored_beyond(rare->particles, n0));
}

TEST(CellSort, RestartKeepsTheCountOfFragmentsAppendedSinceTheLastSort) {
  // The count is in the checkpoint, so a resumed run sorts at the same rebuild as the
  // uninterrupted one. Checkpoints at steps 300 and 400 fall after fragments were appended and
  // before the next sort by this rule: with the count dropped at loading (tried) the resumed runs
  // sort later and their slots differ.
  for (int save_at : {300, 400}) {
    breakage::BreakageModule *ma = nullptr, *mb = nullptr;
    auto a = sorting_breakage_gas(&ma, 1000);
    auto b = sorting_breakage_gas(&mb, 1000);
    a->setup();
    run_restart_twin(*a, *b, save_at, 600 - save_at, [] {});
    omp_set_num_threads(omp_get_num_procs());
    EXPECT_EQ(ma->breakages(), mb->breakages()) << save_at;
    EXPECT_EQ(a->particles.id, b->particles.id) << save_at;
    EXPECT_EQ(a->particles.x, b->particles.x) << save_at;
    EXPECT_EQ(a->particles.v, b->particles.v) << save_at;
  }
}
