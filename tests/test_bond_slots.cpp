// The bonds module caches each bond's particle slots and re-resolves them only when the store's
// ids moved (a cell sort, an insertion, a compaction): after a reorder of the particles between
// two steps, every bond still acts on its own two particles, with the same loads bit for bit as
// in a twin run that was not reordered.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <numeric>
#include <vector>

#include "comminute/bonds/bonds_module.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// A bonded 3 x 3 x 2 block of spheres, stretched by 0.1 % after bonding, every particle moving
// and spinning differently: each bond carries its own load.
struct Block {
  std::unique_ptr<Simulation> sim;
  bonds::BondsModule* module = nullptr;

  Block() {
    sim = make_simulation(DemSetup{});
    const double r = 1e-3, spacing = 2 * r + 1e-7;
    int k = 0;
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x, ++k)
          add_sphere(*sim, {x * spacing, y * spacing, z * spacing}, r,
                     {1e-3 * k, -2e-4 * (k % 5), 3e-4 * (k % 3)},
                     {0.1 * (k % 4), -0.05 * k, 0.2 * (k % 2)});
    const CaseFile f = CaseFile::parse(
        "normal_stiffness = 1e9\nshear_stiffness = 4e8\ntensile_strength = 1e12\n"
        "shear_strength = 1e12\n");
    bonds::BondOptions opt;
    opt.gap_tolerance = 1e-6;
    auto m = std::make_unique<bonds::BondsModule>(
        bonds::BondLawRegistry::create("parallel_bond", f.root()), opt);
    module = m.get();
    sim->modules.push_back(std::move(m));
    sim->dt = 1e-6;
    sim->options.skin = 2e-4;
    sim->setup();
  }

  // One bond step on zeroed forces (the module alone: no contact force mixes in).
  void bond_step() {
    ParticleStore& p = sim->particles;
    p.clear_forces();
    module->post_force(*sim);
  }

  // Force and torque on the particle with this id.
  std::pair<Vec3, Vec3> load_on(std::uint64_t id) const {
    const std::size_t i = slot_of(*sim, id);
    return {sim->particles.f[i], sim->particles.t[i]};
  }
};

}  // namespace

TEST(BondSlots, LoadsFollowTheParticlesThroughAReorder) {
  Block straight, sorted;
  straight.bond_step();  // makes the bonds and indexes them by slot
  sorted.bond_step();
  ASSERT_EQ(straight.module->bonds().size(), 33u);  // 12 along x, 12 along y, 9 along z
  // stretch both by 0.1 % about the origin, so that every bond is loaded
  for (Block* b : {&straight, &sorted})
    for (Vec3& x : b->sim->particles.x) x = 1.001 * x;
  // reverse the second one's slots (what a cell sort does, here without moving anything)
  std::vector<std::size_t> order(sorted.sim->particles.size());
  std::iota(order.rbegin(), order.rend(), std::size_t{0});
  sorted.sim->particles.permute(order);
  straight.bond_step();
  sorted.bond_step();
  const ParticleStore& p = straight.sim->particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto [f, t] = straight.load_on(p.id[i]);
    const auto [fs, ts] = sorted.load_on(p.id[i]);
    EXPECT_GT(norm(f), 0.0);  // loaded: the comparison is not of zeros
    // bit for bit: the same bonds in the same (id) order add the same loads to each particle
    EXPECT_EQ(0, std::memcmp(&f, &fs, sizeof(Vec3))) << "particle id " << p.id[i];
    EXPECT_EQ(0, std::memcmp(&t, &ts, sizeof(Vec3))) << "particle id " << p.id[i];
  }
}
