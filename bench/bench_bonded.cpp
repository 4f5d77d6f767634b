// Bonded-bed throughput (issue 11, performance): `bench_bonded N bonded|plain [warmup] [steps]`
// builds a simple cubic lattice of about N touching 2 mm spheres in a box, so that every inner
// sphere touches six neighbours; `bonded` joins each touching pair with a parallel bond (six
// bonds per inner sphere, about 3 N bonds), `plain` leaves them unbonded. A piston plane presses
// the bed from above at constant speed (gravity on). It runs `warmup` steps, then times `steps`
// steps and prints one line: N, bonds, threads, wall seconds, user CPU seconds of the timed
// steps, steps per second (wall and CPU), contacts, peak RSS and the bond list's bytes per bond.
// The thread count is OpenMP's (OMP_NUM_THREADS).
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "case_sections.hpp"

namespace {

double user_seconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<double>(ru.ru_utime.tv_sec) + 1e-6 * static_cast<double>(ru.ru_utime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace comminute;
  if (argc < 3) {
    fmt::print(stderr, "usage: {} N bonded|plain [warmup=200] [steps=1000]\n", argv[0]);
    return 2;
  }
  const int side = static_cast<int>(std::lround(std::cbrt(std::atof(argv[1]))));
  const bool bonded = std::string(argv[2]) == "bonded";
  const long warm = argc > 3 ? std::atol(argv[3]) : 200;
  const long steps = argc > 4 ? std::atol(argv[4]) : 1000;
  try {
    const auto dir = std::filesystem::temp_directory_path() /
                     fmt::format("comminute_bench_bonded_{}_{}", side, ::getpid());
    std::filesystem::create_directories(dir);
    testing::write_sphere_lattice(dir / "lattice.data", side, testing::kLatticeRadius, 2500);
    testing::LatticeBedKeys bed;
    bed.side = side;
    bed.box_height = 4 * testing::kLatticeRadius * side;  // twice the lattice
    bed.piston_speed = 0.01;
    if (bonded) bed.bonds = testing::ParallelBondKeys{1e-6, 1e10, 4e9, 1e7, 1e7};
    std::ofstream(dir / "bed.toml") << testing::lattice_bed_case(bed, "lattice.data");
    testing::LoadedCase loaded = testing::load_case(dir / "bed.toml");
    io::DemCase& c = loaded.dem;
    const bonds::BondsModule* b = loaded.bonds;
    Simulation& sim = *c.sim;
    sim.setup();
    sim.run(static_cast<std::uint64_t>(warm));
    const double u0 = user_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    sim.run(static_cast<std::uint64_t>(steps));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double u = user_seconds() - u0;
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    const Observables o = sim.observe();
    std::size_t nb = 0, bond_bytes = 0, scratch_bytes = 0;
    if (b) {
      const bonds::BondList& l = b->bonds();
      nb = l.size();
      // the list's arrays (ids, slots, state records) at their capacities
      bond_bytes = l.id_i.capacity() * sizeof(std::uint64_t) * 2 +
                   l.slot_i.capacity() * sizeof(std::uint32_t) * 2 + l.state.capacity_bytes();
      scratch_bytes = b->scratch_bytes();
    }
    const double steps_d = static_cast<double>(steps);
    fmt::print(
        "N={} bonds={} bonds_per_sphere={:.2f} threads={} steps={} wall_s={:.3f} user_s={:.3f} "
        "steps_per_s_wall={:.1f} steps_per_cpu_s={:.1f} contacts={} wall_contacts={} "
        "failed_bonds={} peak_rss_MB={:.0f} bond_list_bytes_per_bond={:.0f} "
        "bond_scratch_bytes_per_bond={:.0f} kinetic_J={:.6e}\n",
        sim.particles.size(), nb,
        2.0 * static_cast<double>(nb) / static_cast<double>(sim.particles.size()),
        omp_get_max_threads(), steps, s, u, steps_d / s, steps_d / u, o.contacts, o.wall_contacts,
        b ? b->failures().size() : 0, static_cast<double>(ru.ru_maxrss) / 1024.0,
        nb ? static_cast<double>(bond_bytes) / static_cast<double>(nb) : 0.0,
        nb ? static_cast<double>(scratch_bytes) / static_cast<double>(nb) : 0.0,
        o.kinetic_translational + o.kinetic_rotational);
    std::filesystem::remove_all(dir);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  return 0;
}
