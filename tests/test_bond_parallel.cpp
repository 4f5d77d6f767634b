// Bonds on several threads: the bond laws of a step run in parallel threads (4096 bonds or
// more), then their forces are added in bond order. A bonded lattice bed whose spheres start with
// random velocities gives the same motion, bit for bit, on two threads as on one: its 1728
// particles are fewer than the engine's threshold for threaded contact loops, so only the bond
// loop differs. scripts/test runs Parallel* under ThreadSanitizer too.
#include <gtest/gtest.h>
#include <omp.h>

#include <fstream>

#include "case_sections.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr int kSide = 12;  // 1728 spheres, 4752 bonds (the gap tolerance covers the first step)

LoadedCase bonded_lattice(const std::filesystem::path& dir, int threads) {
  omp_set_num_threads(threads);
  // random velocities up to 0.5 m/s: in 100 steps neighbours move up to 0.2 mm apart, so the
  // bonds are pulled and sheared and the weak ones fail
  write_sphere_lattice(dir / "lattice.data", kSide, kLatticeRadius, 2500, 0.5, 3);
  LatticeBedKeys bed;
  bed.side = kSide;
  bed.box_height = 1.0;
  bed.piston_speed = 1.0;
  bed.bonds = ParallelBondKeys{5e-6, 1e10, 4e9, 2e5, 2e5, 5e4};
  std::ofstream(dir / "bed.toml") << lattice_bed_case(bed, "lattice.data");
  LoadedCase c = load_case(dir / "bed.toml");
  c.dem.sim->setup();
  return c;
}

}  // namespace

TEST(Parallel, BondedBedOnTwoThreadsIsBitForBitTheSameAsOnOne) {
  TestDir dir;
  const int steps = 100;
  LoadedCase a = bonded_lattice(dir.path(), 1);
  a.dem.sim->run(steps);
  LoadedCase b = bonded_lattice(dir.path(), 2);
  b.dem.sim->run(steps);
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_GE(a.bonds->bonds().size(), 4096u);  // the bond loop ran threaded to the end
  RecordProperty("bonds", std::to_string(a.bonds->bonds().size()));
  RecordProperty("failed", std::to_string(a.bonds->failures().size()));
  EXPECT_GT(a.bonds->failures().size(), 0u);  // failures are exercised too
  EXPECT_EQ(a.bonds->failures().size(), b.bonds->failures().size());
  EXPECT_EQ(a.dem.sim->particles.x, b.dem.sim->particles.x);
  EXPECT_EQ(a.dem.sim->particles.w, b.dem.sim->particles.w);
  EXPECT_EQ(a.dem.sim->ledger.bond_dissipated, b.dem.sim->ledger.bond_dissipated);
}
