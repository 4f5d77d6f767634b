#pragma once
// A tumbling (ball) mill as a closed triangle mesh: a shell of diameter D and length L about the
// y axis through the origin (y from -L/2 to L/2), n lifter bars along its length and flat end
// liners closing both ends; and the two sizing rules every mill rig starts from, the critical
// speed and the ball charge of a filling fraction.
//
// Cross-section: the shell is a polygon with its vertices on the circle of radius D/2 (`segments`
// of them evenly spaced, those that fall under a lifter's base left out). Lifter k sits at angle
// 2 pi k / n (measured from +x towards +z): a trapezoid whose base is the chord of width
// `lifter_width` on the shell, whose top face is the chord at distance D/2 - `lifter_height`
// from the axis, and whose two side faces lean towards the lifter's centre line by
// `lifter_face_angle` from the normal of the top face (0: a rectangular bar).
#include <filesystem>

#include "comminute/geometry/stl_file.hpp"

namespace comminute {

struct BallMillGeometry {
  double diameter = 0;           // m, inside the shell liner
  double length = 0;             // m, between the end liners
  int lifters = 0;               // evenly spaced lifter bars
  double lifter_height = 0;      // m, from the shell to the top face at the centre line
  double lifter_width = 0;       // m, base chord
  double lifter_face_angle = 0;  // rad
  bool end_liners = true;        // false: an open tube
  int segments = 72;             // shell polygon vertices on the full circle
};

// Throws Error naming the offending quantity when the lifters do not fit (overlap one another,
// reach the axis, or have a top face of width <= 0).
void check_ball_mill(const BallMillGeometry& g);
// The mill's inner surface, outward normals (closed when end_liners).
IndexedMesh ball_mill_mesh(const BallMillGeometry& g);
// The area (m2) of the cross-section the mesh encloses: the shell polygon less the lifters.
double ball_mill_section_area(const BallMillGeometry& g);
// Volume enclosed by a closed, consistently oriented mesh (m3), by the divergence theorem.
double enclosed_volume(const IndexedMesh& m);
// Writes a binary STL.
void write_stl(const std::filesystem::path& file, const IndexedMesh& m);

// Critical speed (rad/s): the speed at which a ball of diameter d on the liner of a mill of
// diameter D is held by centrifugal force against gravity, omega_c = sqrt(2 g / (D - d)).
double critical_speed(double mill_diameter, double ball_diameter, double g = 9.81);
// Balls of diameter d that fill a fraction J of a mill volume V as a bed of porosity `voids`
// (0.4 for a ball charge): N = (1 - voids) J V / (pi d^3 / 6), rounded to the nearest integer.
long balls_for_filling(double filling, double mill_volume, double ball_diameter,
                       double voids = 0.4);

}  // namespace comminute
