// The wall force loop evaluates touching contacts in runs through the contact law's batch
// (engine/wall_force_loop.hpp); each contact's result must reach its own particle. Spheres of
// distinct radii and overlaps, of two materials (pairs mixed within a run), rest on a plane, more
// of them than one run holds: each must receive Hertz's force for its own radius, overlap and pair,
// F = (4/3) E* sqrt(R) δ^1.5 (Hertz, J. reine angew. Math. 92 (1882) 156), with R the sphere's
// radius against a flat wall and 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂. At rest the dashpots and the
// tangential spring give nothing, so the force is Hertz's alone.
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using comminute::testing::DemSetup;
using comminute::testing::make_simulation;

TEST(WallForceRuns, EverySphereOnAPlaneGetsHertzForceOfItsOwnContact) {
  auto sim = make_simulation(DemSetup{});
  const std::uint16_t hard = sim->materials.add({"hard", 2500, 4e7, 0.2});
  PairInput pi;
  pi.restitution = 0.5;
  sim->materials.set_pair(0, hard, pi);
  sim->materials.set_pair(hard, hard, pi);
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  constexpr int nx = 20, ny = 15;  // 300 spheres: several runs of 64, more than one chunk
  const double pitch = 4e-3;       // m: apart, no sphere touches another
  for (int a = 0; a < nx; ++a)
    for (int b = 0; b < ny; ++b) {
      const int k = a * ny + b;
      ParticleInit p;
      p.radius = 1e-3 * (1.0 + 0.3 * (k % 7) / 7.0);
      const double overlap = 1e-5 * (1.0 + (k % 11) / 11.0);
      p.x = {a * pitch, b * pitch, p.radius - overlap};
      p.density = 2500;
      p.material = k % 3 == 0 ? hard : 0;
      sim->particles.add(p);
    }
  sim->dt = 1e-7;
  sim->setup();  // the set-up computes the forces of the initial state
  const ParticleStore& p = sim->particles;
  ASSERT_EQ(p.size(), static_cast<std::size_t>(nx * ny));
  const auto reduced = [](double e, double nu) { return (1 - nu * nu) / e; };
  const double wall = reduced(1e7, 0.3);  // the plane is of material 0
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double e = p.material[i] == hard ? reduced(4e7, 0.2) : reduced(1e7, 0.3);
    const double estar = 1.0 / (e + wall);
    const double r = p.radius[i], delta = r - p.x[i].z;
    const double f = 4.0 / 3.0 * estar * std::sqrt(r) * std::pow(delta, 1.5);
    // the overlap is read back from the position, rounded to 1e-19 m on 1e-5 m: the force
    // (δ^1.5) is known to ~1e-13 relative; 1e-9 leaves room and still tells apart the
    // spheres' forces, which differ by 3 % or more
    EXPECT_NEAR(p.f[i].z, f, 1e-9 * f) << "particle " << i;
    EXPECT_EQ(p.f[i].x, 0.0) << "particle " << i;
    EXPECT_EQ(p.f[i].y, 0.0) << "particle " << i;
  }
}
