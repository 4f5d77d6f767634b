#pragma once
// The rotating drum of the power tests (issue 14 rig test 4, issue 13 test 1): 300 beads
// (r = 3.5 mm) in a capped drum (R = 50 mm, L = 40 mm, axis y) turning at 5 rad/s, a third of
// the critical speed sqrt(g/R) = 14 rad/s: a rolling/cascading bed; step 5e-5 s (a thirtieth
// of the linear law's contact time at k_n = 2000 N/m).
#include <cmath>
#include <memory>

#include "comminute/geometry/cylinder_wall.hpp"
#include "dem_fixture.hpp"

namespace comminute::testing {

// The contact law and its keys from `s`; friction 0.5, restitution 0.5, gravity set here.
inline std::unique_ptr<Simulation> make_drum(DemSetup s) {
  s.friction = 0.5;
  s.restitution = 0.5;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double R = 0.05, L = 0.04, r = 0.0035, omega = 5.0;
  sim->walls.push_back(std::make_unique<CylinderWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}, R, L,
                                                      /*inside=*/true, /*caps=*/true));
  sim->walls[0]->kinematics.angular_velocity = {0, omega, 0};
  sim->walls[0]->kinematics.center = {0, 0, 0};
  // a loose lattice (spacing 2.3 r) filling the drum from the bottom up
  const double h = 2.3 * r;
  int n = 0;
  for (double z = -R + 1.2 * r; z < R && n < 300; z += h)
    for (double x = -R + 1.2 * r; x < R && n < 300; x += h)
      for (double y = -L / 2 + 1.2 * r; y < L / 2 - 1.2 * r && n < 300; y += h)
        if (std::hypot(x, z) < R - 1.2 * r) {
          add_sphere(*sim, {x, y, z}, r);
          ++n;
        }
  sim->dt = 5e-5;
  return sim;
}

}  // namespace comminute::testing
