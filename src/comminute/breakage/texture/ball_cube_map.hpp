#pragma once
// Equal-volume bijection between a cube and a ball (Rosca, Morawiec & De Graef, Modelling Simul.
// Mater. Sci. Eng. 22 (2014) 075013, "cubochoric" map; docs/models.md eq. T1). The cube
// [-a/2, a/2]^3 with a = pi^(2/3) maps onto the ball of radius R = (3 pi / 4)^(1/3), both of
// volume pi^2; the map is positively homogeneous of degree 1, so the unit-edge cube maps onto the
// ball of radius (3 / (4 pi))^(1/3) by scaling. Every cube cell therefore covers the same volume
// of the ball: the phase fractions of a voxel texture are plain voxel counts.
#include "comminute/core/vec3.hpp"

namespace comminute::breakage::texture {

// Edge of the reference cube, pi^(2/3), and radius of the ball of equal volume, (3 pi / 4)^(1/3).
double cube_edge();
double ball_radius();

// Cube [-a/2, a/2]^3 (a = cube_edge()) -> ball of radius ball_radius().
Vec3 cube_to_ball(const Vec3& c);
// Inverse of cube_to_ball.
Vec3 ball_to_cube(const Vec3& b);

// The unit-edge cube [-1/2, 1/2]^3 -> ball of radius (3 / (4 pi))^(1/3) (unit volume), and back.
Vec3 unit_cube_to_ball(const Vec3& c);
Vec3 unit_ball_to_cube(const Vec3& b);
double unit_ball_radius();

}  // namespace comminute::breakage::texture
