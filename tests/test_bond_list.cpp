// The bond list follows its particles by id through the store's reorders (cell sort) and
// compactions, and reports the bonds whose particle was removed.
#include <gtest/gtest.h>

#include <cstring>
#include <numeric>

#include "comminute/bonds/bond_list.hpp"

using namespace comminute;
using namespace comminute::bonds;

namespace {

ParticleStore chain(int n) {
  ParticleStore p;
  for (int k = 0; k < n; ++k) {
    ParticleInit q;
    q.x = {2.0 * k, 0, 0};
    q.radius = 1;
    q.density = 1;
    p.add(q);
  }
  return p;
}

// Bonds k -- k+1 of the chain, each tagged by its rest length (k + 1) to tell them apart.
BondList bond_chain(const ParticleStore& p) {
  BondList b;
  for (std::uint32_t k = 0; k + 1 < p.size(); ++k) {
    BondState s;
    s.length0 = k + 1.0;
    b.add(p.id[k], k, p.id[k + 1], k + 1, s);
  }
  return b;
}

void expect_slots_match_ids(const BondList& b, const ParticleStore& p) {
  for (std::size_t k = 0; k < b.size(); ++k) {
    ASSERT_LT(b.slot_i[k], p.size());
    ASSERT_LT(b.slot_j[k], p.size());
    EXPECT_EQ(p.id[b.slot_i[k]], b.id_i[k]);
    EXPECT_EQ(p.id[b.slot_j[k]], b.id_j[k]);
  }
}

}  // namespace

TEST(BondList, FollowsParticlesThroughPermutationAndCompaction) {
  ParticleStore p = chain(6);
  BondList b = bond_chain(p);
  EXPECT_TRUE(b.locate(p).empty());  // nothing moved: slots valid as they are
  // a cell sort: reverse the order
  std::vector<std::size_t> order(p.size());
  std::iota(order.rbegin(), order.rend(), std::size_t{0});
  p.permute(order);
  EXPECT_TRUE(b.locate(p).empty());
  expect_slots_match_ids(b, p);
  // remove particle id 3 (the bonds 2--3 and 3--4 lose it)
  for (std::size_t s = 0; s < p.size(); ++s)
    if (p.id[s] == 3) p.flags[s] |= pflag::remove;
  p.compact();
  const auto lost = b.locate(p);
  ASSERT_EQ(lost.size(), 2u);
  EXPECT_EQ(b.state.length0[lost[0]], 2.0);
  EXPECT_EQ(b.state.length0[lost[1]], 3.0);
  std::vector<std::uint8_t> gone(b.size(), 0);
  for (auto k : lost) gone[k] = 1;
  b.remove(gone);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b.state.length0[0], 1.0);
  EXPECT_EQ(b.state.length0[1], 4.0);
  EXPECT_EQ(b.state.length0[2], 5.0);
  expect_slots_match_ids(b, p);
}

TEST(BondList, CheckpointRoundTripAndRefusesBadState) {
  ParticleStore p = chain(3);
  BondList b = bond_chain(p);
  for (std::size_t k = 0; k < b.size(); ++k) {  // every field of the record its own value
    BondState s = b.state.get(k);
    const double u = 1.0 + static_cast<double>(k);
    s.normal = {0.6, 0.8 * u, 0}, s.shear_force = {1.5 * u, -2, 3}, s.moment = {4, 5 * u, -6};
    s.slip = {7e-6, -8e-6 * u, 9e-6}, s.radius = 1 + u, s.tensile_strength = 10 * u;
    s.shear_strength = 11 * u, s.damage = 0.125 * u, s.dissipated = 12 * u, s.strain_energy = u;
    b.state.set(k, s);
  }
  Archive a;
  b.save(a, "bonds/list/");
  BondList c;
  c.load(a, "bonds/list/");
  ASSERT_EQ(c.size(), 2u);
  // the hot/cold split of the states is not in the file: the whole records come back, byte for
  // byte (their padding is zero)
  for (std::size_t k = 0; k < c.size(); ++k) {
    const BondState saved = b.state.get(k), loaded = c.state.get(k);
    EXPECT_EQ(std::memcmp(&saved, &loaded, sizeof(BondState)), 0);
  }
  EXPECT_TRUE(c.locate(p).empty());
  expect_slots_match_ids(c, p);
  b.state.rest[1].damage = 1.5;  // not a damage
  Archive bad;
  b.save(bad, "bonds/list/");
  EXPECT_THROW(c.load(bad, "bonds/list/"), Error);
}
