#pragma once
// A small stirred vessel for the mixer tests: a vertical cylinder (analytic shell and floor), a
// rotating shaft (analytic cylinder turning about its own axis) and a three-bladed `mixer` wall
// on it, either whole (an open domain, or a one-third sector whose walls are all 3-fold
// symmetric) or as one blade whose periodic images make the other two (a one-third sector).
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "comminute/core/case_table.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/geometry/cylinder_wall.hpp"
#include "comminute/geometry/periodic_images_wall.hpp"
#include "comminute/geometry/periodic_map.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

namespace comminute::testing {

struct MixerRig {
  double vessel_radius = 0.03;  // m
  double height = 0.06;         // m
  double shaft_radius = 0.006;  // m
  double omega = 30;            // rad/s about +z
  double particle_radius = 0.0015;
  // the blades (mixer_table): chord 8 mm, 4 mm thick, 20° from the horizontal (a particle on the
  // upper face sticks there with friction 0.5), lowest point 3 mm above the floor
  double blade_height = 0.008, blade_thickness = 0.004, pitch = 20 * std::numbers::pi / 180;
  double bottom_clearance = 0.003;
  // A point on blade 0's upper face, at distance rho from the axis, and the face's normal.
  Vec3 upper_face_normal() const { return {0, -std::sin(pitch), std::cos(pitch)}; }
  Vec3 on_upper_face(double rho) const {
    const double zc = bottom_clearance +
                      0.5 * (blade_height * std::sin(pitch) + blade_thickness * std::cos(pitch));
    return Vec3{rho, 0, zc} + 0.5 * blade_thickness * upper_face_normal();
  }
};

enum class Blades { whole, one_imaged };

inline std::string mixer_table(const MixerRig& rig, int built) {
  return "vessel_diameter = " + std::to_string(2 * rig.vessel_radius) +
         "\nvessel_height = " + std::to_string(rig.height) +
         "\nblades = 3\nblades_built = " + std::to_string(built) +
         "\nshaft_diameter = " + std::to_string(2 * rig.shaft_radius) +
         "\nwall_clearance = 0.003\nblade_height = 0.008\nblade_thickness = 0.004\n"
         "pitch = 20\nbottom_clearance = 0.003\nshaft = false\nrpm = " +
         std::to_string(rig.omega * 60 / (2 * std::numbers::pi)) + "\n";
}

// The simulation with its walls: shell, floor, shaft, blades (last). `sector`: periodic one-third
// sector about z.
inline std::unique_ptr<Simulation> mixer_sim(const MixerRig& rig, bool sector, Blades blades,
                                             const DemSetup& s) {
  auto sim = make_simulation(s);
  const double H = rig.height;
  sim->walls.push_back(std::make_unique<CylinderWall>(Vec3{0, 0, H / 2}, Vec3{0, 0, 1},
                                                      rig.vessel_radius, H, true, false));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  auto shaft = std::make_unique<CylinderWall>(Vec3{0, 0, H / 2}, Vec3{0, 0, 1}, rig.shaft_radius, H,
                                              false, false);
  shaft->kinematics.angular_velocity = {0, 0, rig.omega};
  sim->walls.push_back(std::move(shaft));
  const CaseFile t = CaseFile::parse(mixer_table(rig, blades == Blades::whole ? 3 : 1));
  std::unique_ptr<Wall> w = WallRegistry::create("mixer", t.root());
  const PeriodicMap map = PeriodicMap::sector(2, {0, 0, 0}, 3);
  if (blades == Blades::one_imaged) w = std::make_unique<PeriodicImagesWall>(std::move(w), map);
  w->name = "blades";
  sim->walls.push_back(std::move(w));
  if (sector) sim->set_periodic(map);
  return sim;
}

// Lattice sites (spacing a, jittered by up to 0.1 a) in the vessel's annulus between the shaft
// and the shell, above z0, at angles in [theta0, theta1), lowest layers first, that keep clear of
// the blades (at their start position); at most `count`.
inline std::vector<Vec3> mixer_sites(const MixerRig& rig, const Wall& blades, double z0,
                                     double theta0, double theta1, std::size_t count, Rng& rng) {
  const double r = rig.particle_radius, a = 2.3 * r;
  std::vector<Vec3> out;
  std::vector<WallContact> found;
  for (double z = z0; z < rig.height - r && out.size() < count; z += a)
    for (double rho = rig.shaft_radius + 1.2 * r; rho < rig.vessel_radius - 1.2 * r; rho += a) {
      const double step = a / rho;
      for (double th = theta0 + 0.5 * step; th < theta1 - 0.5 * step && out.size() < count;
           th += step) {
        const Vec3 x{rho * std::cos(th) + 0.1 * a * (rng.uniform() - 0.5),
                     rho * std::sin(th) + 0.1 * a * (rng.uniform() - 0.5),
                     z + 0.1 * a * (rng.uniform() - 0.5)};
        found.clear();
        if (blades.contacts(x, 1.1 * r, 0.0, found) > 0) continue;
        out.push_back(x);
      }
    }
  return out;
}

}  // namespace comminute::testing
