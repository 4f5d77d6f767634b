// DEM throughput on a case file: `bench_dem_throughput CASE [warmup] [steps]` builds the case,
// runs `warmup` steps, then times `steps` steps (the same window the peer decks time) and prints
// one line: N, threads, seconds, particle-steps per second, contacts, peak RSS. Before it: one line
// per mesh wall (triangles, bytes of its data structures, bytes per triangle) and one line with the
// extent of the particle centres at the end (a check that nothing left the container).
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "comminute/geometry/mesh_wall.hpp"
#include "support/case_bench.hpp"

namespace {
// Resident set size now (MB).
double rss_mb() {
  return static_cast<double>(comminute::bench::status_kb("VmRSS")) / 1024.0;
}

// Memory of each mesh wall: MeshWall::bytes() sums the capacities of its arrays (vertices,
// triangles, normals, areas, edges, patches, vertex-triangle lists, the cell grid, wear).
void print_mesh_memory(const comminute::Simulation& sim) {
  for (const auto& wall : sim.walls) {
    const auto* mesh = dynamic_cast<const comminute::MeshWall*>(wall.get());
    if (mesh == nullptr) continue;
    const std::size_t n = mesh->mesh().triangles().size();
    fmt::print(
        "mesh_wall triangles={} bytes={} bytes_per_triangle={:.0f}\n", n, mesh->bytes(),
        static_cast<double>(mesh->bytes()) / static_cast<double>(std::max<std::size_t>(n, 1)));
  }
}

// Extent of the particle centres, and their largest distance from the y axis (the drum's axis).
void print_extent(const comminute::ParticleStore& p, const comminute::Observables& o) {
  comminute::Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double r_xz = 0;
  for (std::size_t i = 0; i < p.owned(); ++i) {
    lo = {std::min(lo.x, p.x[i].x), std::min(lo.y, p.x[i].y), std::min(lo.z, p.x[i].z)};
    hi = {std::max(hi.x, p.x[i].x), std::max(hi.y, p.x[i].y), std::max(hi.z, p.x[i].z)};
    r_xz = std::max(r_xz, std::hypot(p.x[i].x, p.x[i].z));
  }
  fmt::print(
      "centres lo=[{:.5f},{:.5f},{:.5f}] hi=[{:.5f},{:.5f},{:.5f}] max_dist_from_y_axis={:.5f} "
      "kinetic_translational_J={:.4g} kinetic_rotational_J={:.4g}\n",
      lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, r_xz, o.kinetic_translational, o.kinetic_rotational);
}
}  // namespace

int main(int argc, char** argv) {
  using namespace comminute;
  return bench::run_case_bench(
      argc, argv, "[warmup=1000] [steps=2000]", {1000, 2000},
      [](Simulation& sim, const std::vector<long>& counts) {
        const long warm = counts[0], steps = counts[1];
        const double rss_setup = rss_mb();
        print_mesh_memory(sim);
        sim.run(static_cast<std::uint64_t>(warm));
        const auto t0 = std::chrono::steady_clock::now();
        sim.run(static_cast<std::uint64_t>(steps));
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rusage ru{};
        getrusage(RUSAGE_SELF, &ru);
        const Observables o = sim.observe();
        print_extent(sim.particles, o);
        const double n = static_cast<double>(sim.particles.size());
        fmt::print(
            "N={} threads={} steps={} seconds={:.3f} particle_steps_per_s={:.4g} contacts={} "
            "wall_contacts={} pairs={} rebuilds={} rss_setup_MB={:.0f} rss_end_MB={:.0f} "
            "peak_rss_MB={:.0f} "
            "bytes_per_particle={:.0f}\n",
            sim.particles.size(), omp_get_max_threads(), steps, s,
            n * static_cast<double>(steps) / s, o.contacts, o.wall_contacts, sim.pairs().size(),
            sim.neighbor_rebuilds(), rss_setup, rss_mb(),
            static_cast<double>(ru.ru_maxrss) / 1024.0,
            static_cast<double>(ru.ru_maxrss) * 1024.0 / n);
      });
}
