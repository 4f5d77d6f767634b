// A fragment that grows under a sustained load (the nip of a roll press, a compressed bed): a
// growing sphere between two rigid planes closer than its final diameter. Capped growth
// (growth_overlap_ratio as a cap on the overlap, the default) stops where the planes touch it
// and leaves it at the gap's size for good, carrying its full mass but almost no force; pushing
// growth (`growth = "pushing"`) lets it grow against the planes to its full size, where it
// presses them with the Hertz force of its full-size overlap. This is why the HPGR example's
// product held fragments coarser than the gap (examples/hpgr/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "comminute/breakage/breakage_module.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double kFinal = 5e-3;      // m, the fragment's final radius
constexpr double kHalfGap = 4.5e-3;  // m, half the distance between the planes (< kFinal)
constexpr double kStart = 3e-3;      // m, its radius when placed
constexpr double kYoungs = 5e7, kPoisson = 0.3, kDensity = 2500;

struct Squeeze {
  double radius = 0;      // m, after the run
  bool growing = true;    // still flagged growing
  double wall_force = 0;  // N, the force of the sphere on the plane at +x, along +x
};

// The growing sphere between the planes, set up (not run): placed at x = `offset`, time step
// dt / `refine`, growth per step (growth_step and growth_overlap_ratio) divided by `refine` too,
// so that it grows at the same rate in time.
std::unique_ptr<Simulation> squeeze_setup(bool pushing, double offset = 0.0, int refine = 1) {
  DemSetup s;
  s.youngs = kYoungs;
  s.poisson = kPoisson;
  s.density = kDensity;
  auto sim = make_simulation(s);
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{-kHalfGap, 0, 0}, Vec3{1, 0, 0}));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{kHalfGap, 0, 0}, Vec3{-1, 0, 0}));
  breakage::BreakageOptions opt;
  opt.growth_pushes = pushing;
  opt.growth_step /= refine;
  opt.growth_overlap_ratio /= refine;
  // material 0 has no breakage: the sphere only grows
  std::vector<std::optional<breakage::MaterialBreakage>> mats(1);
  auto mod = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
  mod->register_fields(sim->particles);
  ParticleInit init;
  init.x = {offset, 0, 0};
  init.radius = kStart;
  init.density = kDensity;
  init.flags = pflag::growing;
  const double mass = kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kFinal, 3);
  sim->particles.add_with_mass(init, mass);
  auto& p = sim->particles;
  p.field(p.field_index("breakage.target_radius"))[0] = kFinal;
  sim->modules.push_back(std::move(mod));
  sim->dt = 1e-6 / refine;  // s, ~1/30 of the Rayleigh time of the 5 mm sphere
  sim->setup();
  return sim;
}

Squeeze squeeze(bool pushing) {
  auto sim = squeeze_setup(pushing);
  // capped: full size would need 1/growth_step = 200 steps; pushing: the overlap deepens by at
  // most growth_overlap_ratio · r = 5 µm per step, 0.5 mm in ~100 steps; 2000 steps is plenty
  sim->run(2000);
  const auto& p = sim->particles;
  return {p.radius[0], (p.flags[0] & pflag::growing) != 0, sim->walls[1]->force.x};
}

struct Balance {
  double drift = 0;    // J, change of KE + elastic + damping + friction + removed − wall work
  double work = 0;     // J, the elastic energy growth created (booked)
  double damping = 0;  // J, dissipated by the dashpots
  bool growing = true;
};

// The energy balance of a sphere growing off-centre between the planes with pushing growth: it
// touches the nearer plane first, is pushed off, rattles between the planes and settles at the
// middle at full size. Over 3 ms (the growth takes ~0.3 ms); the planes are fixed (no wall work).
Balance squeeze_balance(int refine) {
  auto sim = squeeze_setup(true, 1e-3, refine);
  auto sum = [&] {
    const Observables o = sim->observe();
    return o.kinetic_translational + o.kinetic_rotational + o.elastic + o.ledger.damping +
           o.ledger.friction + o.ledger.removed - o.ledger.wall_work;
  };
  const double b0 = sum();
  sim->run(3000 * static_cast<std::uint64_t>(refine));
  const auto& mod = dynamic_cast<const breakage::BreakageModule&>(*sim->modules[0]);
  return {sum() - b0, mod.created_energy(), sim->ledger.damping,
          (sim->particles.flags[0] & pflag::growing) != 0};
}

}  // namespace

TEST(GrowthUnderLoad, CappedGrowthStallsAtTheGap) {
  const Squeeze c = squeeze(false);
  EXPECT_TRUE(c.growing);
  // it stops where the overlap with each plane reaches 0.001 of its radius: r (1 - 0.001) =
  // kHalfGap, to round-off (1e-12 m)
  EXPECT_NEAR(c.radius, kHalfGap / (1 - 0.001), 1e-12);
}

TEST(GrowthUnderLoad, PushingGrowthReachesFullSizeAndCarriesTheLoad) {
  const Squeeze c = squeeze(true);
  EXPECT_FALSE(c.growing);
  EXPECT_EQ(c.radius, kFinal);  // growth ends exactly at the target
  // Hertz, sphere on a rigid-equivalent plane of the same material: F = 4/3 E* √R δ^{3/2},
  // 1/E* = 2 (1 − ν²)/E (Johnson, Contact Mechanics, 1985, eq. 4.22), δ = R − h. The sphere is
  // at rest between symmetric planes, so no damping force: 1e-9 relative is round-off in δ^{3/2}.
  const double e_star = kYoungs / (2 * (1 - kPoisson * kPoisson));
  const double f = 4.0 / 3.0 * e_star * std::sqrt(kFinal) * std::pow(kFinal - kHalfGap, 1.5);
  EXPECT_NEAR(c.wall_force, f, 1e-9 * f);
}

// The energy ledger closes with pushing growth: the elastic energy that growth puts into the
// deepening overlaps (computed with the contact law at fixed positions, step by step) is booked
// as created energy (`created_elastic_energy [J]` of breakage_ledger.csv, negative in
// ledger.removed), and with it KE + elastic + damping + friction + removed − wall work stays
// constant. What is left is the time integration's error (the damping ledger is first order in
// dt, and growth acts between the force computation and the second half kick, a stale force for
// half a step): refining dt four times (growth per step too, so the motion is the same) must cut
// the drift at least in half (first order: to 1/4), where a booking leak would not shrink; and
// the refined drift must be below 1e-3 of the energy growth created (the bound of
// BreakageEngine.EnergyLedgerClosesThroughBreakage). Measured: 6.8e-4 of it, 1/4 of the coarse.
TEST(GrowthUnderLoad, PushingGrowthEnergyLedgerCloses) {
  const Balance coarse = squeeze_balance(1);
  const Balance fine = squeeze_balance(4);
  RecordProperty("created_J", std::to_string(fine.work));
  RecordProperty("damping_J", std::to_string(fine.damping));
  RecordProperty("drift_coarse_J", std::to_string(coarse.drift));
  RecordProperty("drift_fine_J", std::to_string(fine.drift));
  ASSERT_FALSE(fine.growing);  // growth reached full size within the run
  ASSERT_GT(fine.work, 0.0);
  // the sphere did rattle: its dashpots took a good part of what growth put in (not only the
  // elastic energy of the final overlaps)
  EXPECT_GT(fine.damping, 0.05 * fine.work);
  EXPECT_LE(std::abs(fine.drift), 0.5 * std::abs(coarse.drift));
  EXPECT_LE(std::abs(fine.drift), 1e-3 * fine.work);
}

// Capped growth against another sphere: a growing sphere (3 mm, final 5 mm, 25 µm per step) and a
// 6 mm sphere 10.51 mm away, both held fixed. Growth stops where the overlap reaches 0.001 of the
// smaller radius, r + R - d = 0.001 r, to round-off. The last step before the stall starts 10 µm
// from touching, closer than one step's growth: a pair passed over because it is not touching yet
// (growth's shortcut for pairs too far apart to matter) would let the spheres overlap by 15 µm
// instead of 4.5 µm.
TEST(GrowthUnderLoad, CappedGrowthStopsAtANeighbourWithinOneStep) {
  DemSetup s;
  s.youngs = kYoungs;
  s.poisson = kPoisson;
  s.density = kDensity;
  auto sim = make_simulation(s);
  std::vector<std::optional<breakage::MaterialBreakage>> mats(1);  // no breakage: growth only
  auto mod =
      std::make_unique<breakage::BreakageModule>(std::move(mats), breakage::BreakageOptions{});
  mod->register_fields(sim->particles);
  constexpr double kOther = 6e-3, kDistance = 10.51e-3;  // m
  ParticleInit grower;
  grower.radius = kStart;
  grower.density = kDensity;
  grower.flags = pflag::growing | pflag::fixed;
  sim->particles.add_with_mass(grower,
                               kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kFinal, 3));
  ParticleInit other;
  other.x = {kDistance, 0, 0};
  other.radius = kOther;
  other.density = kDensity;
  other.flags = pflag::fixed;
  sim->particles.add(other);
  auto& p = sim->particles;
  p.field(p.field_index("breakage.target_radius"))[0] = kFinal;
  sim->modules.push_back(std::move(mod));
  sim->dt = 1e-6;
  sim->setup();
  sim->run(200);  // 60 steps to reach the other sphere at 25 µm per step
  EXPECT_TRUE(p.flags[0] & pflag::growing);
  EXPECT_NEAR(p.radius[0], (kDistance - kOther) / (1 - 0.001), 1e-12);
}
