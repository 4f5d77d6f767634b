// Bonds on several threads: the bond laws of a step run in parallel threads (4096 bonds or
// more), then their forces are added in bond order. A bonded lattice bed whose spheres start with
// random velocities gives the same motion, bit for bit, on two threads as on one: its 1728
// particles are fewer than the engine's threshold for threaded contact loops, so only the bond
// loop differs. scripts/test runs Parallel* under ThreadSanitizer too.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <fstream>

#include "comminute/core/rng.hpp"
#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

constexpr int kSide = 12;  // 1728 spheres, 4752 bonds (the gap tolerance covers the first step)

struct Bed {
  io::DemCase dem;
  const bonds::BondsModule* bonds = nullptr;
};

Bed bonded_lattice(const std::filesystem::path& dir, int threads) {
  omp_set_num_threads(threads);
  constexpr double r = 1e-3, l = 2 * r * kSide;
  {
    std::ofstream d(dir / "lattice.data");
    d << "# simple cubic lattice, touching spheres\n\n"
      << kSide * kSide * kSide << " atoms\n1 atom types\n\nAtoms # sphere\n\n";
    int id = 1;
    for (int k = 0; k < kSide; ++k)
      for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i)
          d << id++ << " 1 0.002 2500 " << r * (2 * i + 1) << ' ' << r * (2 * j + 1) << ' '
            << r * (2 * k + 1) << '\n';
    // random velocities up to 0.5 m/s: in 100 steps neighbours move up to 0.2 mm apart, so the
    // bonds are pulled and sheared and the weak ones fail
    d << "\nVelocities\n\n";
    Rng rng(3);
    for (int n = 1; n < id; ++n)
      d << n << ' ' << rng.uniform(-0.5, 0.5) << ' ' << rng.uniform(-0.5, 0.5) << ' '
        << rng.uniform(-0.5, 0.5) << " 0 0 0\n";
  }
  std::ofstream(dir / "bed.toml") << fmt::format(R"(
[simulation]
seed = 1
end_time = 1.0
time_step = 2e-6
skin = 2e-4
gravity = [0.0, 0.0, -9.81]
[contact]
model = "hertz_mindlin"
[materials.rock]
density = 2500.0
youngs_modulus = 5.0e7
poisson_ratio = 0.3
[interaction]
restitution = 0.5
friction = 0.5
[[walls]]
name = "bin"
type = "box"
lo = [0.0, 0.0, 0.0]
hi = [{l}, {l}, 1.0]
open = ["+z"]
material = "rock"
[[walls]]
name = "piston"
type = "plane"
point = [0.0, 0.0, {l}]
normal = [0.0, 0.0, -1.0]
material = "rock"
velocity = [0.0, 0.0, -1.0]
[[insert]]
type = "data_file"
material = "rock"
file = "lattice.data"
[bonds]
law = "parallel_bond"
gap_tolerance = 5e-6
normal_stiffness = 1e10
shear_stiffness = 4e9
tensile_strength = 2e5
shear_strength = 2e5
tensile_strength_sd = 5e4
shear_strength_sd = 5e4
)",
                                                 fmt::arg("l", l));
  const CaseFile file = CaseFile::load(dir / "bed.toml");
  Bed bed{io::build_dem_case(file.root()), nullptr};
  bed.bonds = io::add_bonds(file.root(), bed.dem);
  io::decide_time_step(bed.dem);
  file.reject_unknown();
  bed.dem.sim->setup();
  return bed;
}

}  // namespace

TEST(Parallel, BondedBedOnTwoThreadsIsBitForBitTheSameAsOnOne) {
  comminute::testing::TestDir dir;
  const int steps = 100;
  Bed a = bonded_lattice(dir.path(), 1);
  a.dem.sim->run(steps);
  Bed b = bonded_lattice(dir.path(), 2);
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
