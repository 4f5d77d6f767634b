// Neighbour list: every pair closer than r_i + r_j + skin is found exactly once, for monodisperse
// and for polydisperse beds with a size ratio of 10 (checked against brute force), and the list
// stays linear in size.
#include <gtest/gtest.h>

#include <algorithm>
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
