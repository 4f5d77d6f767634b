#pragma once
// A stirred vessel (mixer) as triangle meshes: a vertical cylindrical vessel and a shaft on its
// axis carrying n flat blades. Frame: the vessel axis is +z through `center` (a point on the
// floor); blade k points along the angle 2 pi k / n from +x towards +y.
//
// Blade k is a rectangular plate: radially from inside the shaft (half the shaft radius) out to
// the tip radius r_tip = shaft_diameter / 2 + blade_length = vessel_diameter / 2 − wall
// clearance; `blade_height` along its chord, `blade_thickness` across it. The chord is tilted from
// the horizontal by the pitch angle (90°: a flat vertical paddle; 45°: a pitched-blade turbine,
// its leading face turned downwards when the shaft turns counter-clockwise about +z). The
// blade's lowest point is `bottom_clearance` above the floor. The shaft is a prism of `segments`
// sides from that height to `shaft_top` (polygons start half a side off +x).
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

struct MixerGeometry {
  double vessel_diameter = 0;   // m, inside
  double vessel_height = 0;     // m, floor to rim
  int blades = 0;               // evenly spaced blades on the shaft
  double blade_length = 0;      // m, from the shaft surface to the tip
  double blade_height = 0;      // m, along the chord
  double blade_thickness = 0;   // m
  double pitch = 0;             // rad, chord from the horizontal (pi/2: vertical paddle)
  double bottom_clearance = 0;  // m, floor to the blades' lowest point
  double shaft_diameter = 0;    // m
  double shaft_top = 0;         // m above the floor
  int segments = 24;            // sides of the shaft prism
  int blades_built = 0;  // blades 0 .. blades_built − 1 are meshed (one period of a sector)
  bool shaft = true;     // mesh the shaft (false: blades only)

  double tip_radius() const { return 0.5 * shaft_diameter + blade_length; }
  double wall_clearance() const { return 0.5 * vessel_diameter - tip_radius(); }
};

// Throws Error naming the offending quantity when the parts do not fit (blades reach the wall or
// the floor, blades overlap one another at the shaft, the shaft is wider than the vessel).
void check_mixer(const MixerGeometry& g);
// The shaft and its blades (closed, outward normals), with the floor centre at the origin.
IndexedMesh mixer_shaft_mesh(const MixerGeometry& g);
// The vessel: a `segments`-sided polygonal shell of the vessel diameter and height and the flat
// floor, open at the top; normals out of the vessel. `segments` ≥ 8.
IndexedMesh mixer_vessel_mesh(double diameter, double height, int segments);

// Tip speed (m/s) of a blade tip at radius r turning at omega (rad/s): v = omega r; rpm = 60
// omega / (2 pi).
inline double tip_speed(double omega, double tip_radius) {
  return omega * tip_radius;
}

}  // namespace comminute
