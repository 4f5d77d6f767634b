// Prepares the dense-bed benchmark state: runs a case (the peers' loose lattice) until the bed has
// settled, then writes it as a LAMMPS-style data file (positions, velocities, angular velocities)
// that comminute, LIGGGHTS, LAMMPS and Yade all read.
//   bench_make_dense_state CASE.toml OUT.data [max_steps=40000] [ke_per_particle=1e-9 J]
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "comminute/core/atomic_file.hpp"
#include "comminute/io/case/dem_case.hpp"

int main(int argc, char** argv) {
  using namespace comminute;
  if (argc < 3) {
    fmt::print(stderr, "usage: {} CASE.toml OUT.data [max_steps] [ke_per_particle]\n", argv[0]);
    return 2;
  }
  const long max_steps = argc > 3 ? std::atol(argv[3]) : 40000;
  const double ke_limit = argc > 4 ? std::atof(argv[4]) : 1e-9;
  try {
    io::DemCase c = io::load_plain_dem_case(argv[1]);
    Simulation& sim = *c.sim;
    sim.setup();
    long steps = 0;
    double ke = 0;
    do {
      sim.run(1000);
      steps += 1000;
      const Observables o = sim.observe();
      ke = (o.kinetic_translational + o.kinetic_rotational) / static_cast<double>(o.particles);
      fmt::print(stderr,
                 "step {} t = {:.4f} s  kinetic energy per particle {:.3g} J  contacts {}\n", steps,
                 sim.time, ke, o.contacts);
    } while (ke > ke_limit && steps < max_steps);
    const auto& p = sim.particles;
    double zmax = 0;
    for (const auto& x : p.x) zmax = std::max(zmax, x.z);
    AtomicFile out(argv[2]);
    auto& s = out.stream();
    s.precision(17);
    s << fmt::format("# dense bed: {} settled for {:.4f} s by comminute from {}\n\n", p.size(),
                     sim.time, argv[1]);
    s << p.size() << " atoms\n1 atom types\n\n";
    s << "0.0 0.1 xlo xhi\n0.0 0.1 ylo yhi\n0.0 " << std::max(0.06, 1.2 * zmax)
      << " zlo zhi\n\nAtoms\n\n";
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = 2 * p.radius[i];
      const double rho = p.mass[i] / (3.14159265358979323846 / 6 * d * d * d);
      s << i + 1 << " 1 " << d << ' ' << rho << ' ' << p.x[i].x << ' ' << p.x[i].y << ' '
        << p.x[i].z << '\n';
    }
    s << "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
      s << i + 1 << ' ' << p.v[i].x << ' ' << p.v[i].y << ' ' << p.v[i].z << ' ' << p.w[i].x << ' '
        << p.w[i].y << ' ' << p.w[i].z << '\n';
    out.commit();
    fmt::print(stderr, "wrote {} ({} particles, {} contacts)\n", argv[2], p.size(),
               sim.observe().contacts);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
  return 0;
}
