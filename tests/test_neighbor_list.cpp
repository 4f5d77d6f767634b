// Neighbour list: every pair closer than r_i + r_j + skin is found exactly once, for monodisperse
// and for polydisperse beds with a size ratio of 10 (checked against brute force), and the list
// stays linear in size.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "comminute/core/rng.hpp"
#include "comminute/neighbor/neighbor_list.hpp"

using namespace comminute;

namespace {

ParticleStore random_bed(int n, double r_small, double r_large, double large_fraction, double box,
                         std::uint64_t seed) {
  ParticleStore p;
  Rng rng(seed);
  for (int k = 0; k < n; ++k) {
    ParticleInit init;
    init.radius = rng.uniform() < large_fraction ? r_large : r_small * rng.uniform(1.0, 1.2);
    init.x = {rng.uniform(0, box), rng.uniform(0, box), rng.uniform(0, box)};
    init.density = 1000;
    p.add(init);
  }
  return p;
}

std::set<std::pair<std::uint64_t, std::uint64_t>> brute_force(const ParticleStore& p, double skin) {
  std::set<std::pair<std::uint64_t, std::uint64_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double cut = p.radius[i] + p.radius[j] + skin;
      if (norm2(p.x[i] - p.x[j]) < cut * cut) out.insert(std::minmax(p.id[i], p.id[j]));
    }
  return out;
}

std::set<std::pair<std::uint64_t, std::uint64_t>> listed(const NeighborList& nl,
                                                         const ParticleStore& p) {
  std::set<std::pair<std::uint64_t, std::uint64_t>> out;
  for (std::size_t k = 0; k < nl.size(); ++k) {
    auto pr = std::minmax(p.id[nl.first[k]], p.id[nl.second[k]]);
    EXPECT_TRUE(out.insert(pr).second) << "pair listed twice";
  }
  return out;
}

// Appends a sphere of radius r at a random place in the cube [0, box]^3.
void add_sphere(ParticleStore& p, double r, double box, Rng& rng) {
  ParticleInit init;
  init.radius = r;
  init.x = {rng.uniform(0, box), rng.uniform(0, box), rng.uniform(0, box)};
  init.density = 1000;
  p.add(init);
}

// rows() must be the CSR offsets of `first`: row i holds exactly the pairs owned by slot i (the
// pair force loop splits its threads' work by these offsets).
void expect_rows_match(const NeighborList& nl, std::size_t n) {
  const auto& rows = nl.rows();
  ASSERT_EQ(rows.size(), n + 1);
  EXPECT_EQ(rows[0], 0u);
  EXPECT_EQ(rows[n], nl.size());
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_LE(rows[i], rows[i + 1]) << "slot " << i;
    for (std::uint32_t k = rows[i]; k < rows[i + 1]; ++k) ASSERT_EQ(nl.first[k], i) << "pair " << k;
  }
}

}  // namespace

TEST(NeighborList, MonodisperseMatchesBruteForce) {
  ParticleStore p = random_bed(3000, 0.001, 0.001, 0.0, 0.04, 1);
  NeighborList nl;
  nl.build(p, 0.0002);
  EXPECT_EQ(listed(nl, p), brute_force(p, 0.0002));
}

TEST(NeighborList, SizeRatioTenMatchesBruteForceAndStaysSmall) {
  // 3 % of the particles are 10x larger: they go to the second grid
  ParticleStore p = random_bed(4000, 0.0005, 0.005, 0.03, 0.06, 2);
  NeighborList nl;
  nl.build(p, 0.0001);
  const auto expected = brute_force(p, 0.0001);
  EXPECT_EQ(listed(nl, p), expected);
  // No spurious candidates: the list holds exactly the pairs within reach.
  EXPECT_EQ(nl.size(), expected.size());
}

TEST(NeighborList, CellOrderIsAPermutation) {
  ParticleStore p = random_bed(500, 0.001, 0.001, 0.0, 0.02, 3);
  auto order = NeighborList::cell_order(p, 0.0025);
  std::sort(order.begin(), order.end());
  for (std::size_t k = 0; k < order.size(); ++k) ASSERT_EQ(order[k], k);
}

// In-place update (breakage replacement): remove a quarter of a size-ratio-10 bed, append new
// spheres, some larger than any at the build and some twice (a second update on top of the
// first, with the appended spheres of the first in the index's overflow cells). With the build
// positions unchanged, the updated list must equal a fresh build exactly, with no pair twice;
// rebuild_index() (checkpoints) must give the same list.
// Rows after a build and after an in-place update, on a store large enough for the rows to be
// made on all threads (16384 slots and more), with empty rows among them, on 1, 2 and 3
// threads. Slots 6000-13999 sit in a lattice apart from the bed (5 mm apart, more than
// 2 r_max + skin): a long run of owners without pairs across the threads' shares of the slots,
// whose rows must come from the first owner with pairs after the run.
TEST(NeighborList, RowsAreTheOffsetsOfEachOwnersPairs) {
  const int saved = omp_get_max_threads();
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    const double skin = 0.0001;
    ParticleStore p = random_bed(20000, 0.0005, 0.002, 0.02, 0.03, 8);
    for (std::size_t s = 6000; s < 14000; ++s) {
      const auto q = static_cast<double>(s - 6000);
      p.x[s] = {0.05 + 0.005 * std::fmod(q, 20), 0.005 * std::fmod(std::floor(q / 20), 20),
                0.005 * std::floor(q / 400)};
    }
    NeighborList nl;
    nl.build(p, skin);
    EXPECT_GT(nl.size(), p.size() / 4);  // the bed (12000 spheres) is dense enough for content
    expect_rows_match(nl, p.size());
    for (std::size_t i = 0; i < p.size(); i += 7) p.flags[i] |= pflag::remove;
    p.compact();
    const std::vector<std::uint32_t> to_new = nl.slots_after_removal(p);
    EXPECT_FALSE(to_new.empty());
    if (to_new.empty()) break;  // (the thread count is restored below)
    Rng rng(9);
    for (int k = 0; k < 500; ++k) add_sphere(p, 0.0005, 0.03, rng);
    nl.update_in_place(p, to_new, p.x, p.radius);
    expect_rows_match(nl, p.size());
  }
  omp_set_num_threads(saved);
}

TEST(NeighborList, InPlaceUpdateEqualsAFreshBuild) {
  const double skin = 0.0001;
  ParticleStore p = random_bed(3000, 0.0005, 0.005, 0.03, 0.05, 4);
  NeighborList nl, restored;
  nl.build(p, skin);
  Rng rng(5);
  for (int round = 0; round < 2; ++round) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (rng.uniform() < 0.25) p.flags[i] |= pflag::remove;
    p.compact();
    const std::vector<std::uint32_t> to_new = nl.slots_after_removal(p);
    ASSERT_FALSE(to_new.empty());
    for (int k = 0; k < 300; ++k)
      add_sphere(p, k % 50 == 0 ? 0.007 : 0.0005 * rng.uniform(0.3, 1.0), 0.05, rng);
    nl.update_in_place(p, to_new, p.x, p.radius);
    EXPECT_EQ(listed(nl, p), brute_force(p, skin)) << "round " << round;
  }
  // a list restored from a checkpoint re-creates its index and continues identically
  restored.restore(nl.first, nl.second, nl.ids_at_build(), nl.large());
  restored.rebuild_index(p.x, p.radius, skin);
  for (std::size_t i = 0; i < p.size(); i += 3) p.flags[i] |= pflag::remove;
  p.compact();
  const auto to_new = nl.slots_after_removal(p);
  for (int k = 0; k < 100; ++k) add_sphere(p, 0.0004, 0.05, rng);
  nl.update_in_place(p, to_new, p.x, p.radius);
  restored.update_in_place(p, restored.slots_after_removal(p), p.x, p.radius);
  EXPECT_EQ(nl.first, restored.first);
  EXPECT_EQ(nl.second, restored.second);
  EXPECT_EQ(listed(restored, p), brute_force(p, skin));
}

// Appended particles are recognised by their new ids: a store whose kept particles changed order
// cannot be updated in place.
TEST(NeighborList, ReorderedStoreIsNotUpdatedInPlace) {
  ParticleStore p = random_bed(200, 0.001, 0.001, 0.0, 0.02, 6);
  NeighborList nl;
  nl.build(p, 0.0002);
  std::vector<std::size_t> order(p.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = order.size() - 1 - k;
  p.permute(order);
  EXPECT_TRUE(nl.slots_after_removal(p).empty());
}
