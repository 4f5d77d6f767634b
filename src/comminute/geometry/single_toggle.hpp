#pragma once
// The single-toggle (overhead eccentric) jaw crusher drive as a planar four-bar linkage, the
// model of Oduori, Mutuli & Munyasi (J. Eng. Design Technol. 13 (2015) 213): the frame, the
// eccentric as the crank (O to A, length e, turning at Omega), the swinging jaw as the coupler
// (A to B, length l3: it hangs on the eccentric at A and rests on the toggle at B), the toggle
// plate as the rocker (T to B, length l4, T its seat on the frame). Every point of the jaw moves
// in the x-z plane (the jaw's width along y); angles are counter-clockwise with x to the right
// and z up, i.e. about -y.
//
// Construction from the crusher's keys (docs/models.md, J3-J5): at the closed side the jaw is
// drawn as in geometry/jaw_crusher.hpp: A at its top edge (gape, H) and B at its bottom edge
// (css, 0). The toggle seat is T = B + l4 (cos g, -sin g) (g the toggle angle: the toggle
// slopes down from the jaw to its seat for g > 0). B at the closed side is at its smallest x,
// a limit position of the rocker, where crank and coupler are in line; the eccentricity e is
// solved so that the other limit position puts B at x = css + throw.
#include "comminute/core/vec3.hpp"

namespace comminute {

struct SingleToggleLinkage {
  Vec3 shaft;                     // O, m: the eccentric shaft's centre (y = 0)
  Vec3 toggle_seat;               // T, m
  double eccentricity = 0;        // e, m
  double jaw_length = 0;          // l3 = |AB|, m
  double toggle_length = 0;       // l4 = |TB|, m
  double start_angle = 0;         // crank angle at t = 0 (the closed side), rad
  double assembly = 1;            // sign of (B - A) x (T - A) along -y: the branch of the linkage
  Vec3 hang_start, toggle_start;  // A and B at t = 0, m

  // Crank angle theta: the pin A, the jaw's toggle end B and the jaw's angle (of B - A).
  Vec3 pin(double theta) const;
  Vec3 toggle_end(double theta) const;
  double jaw_angle(double theta) const;
  // The jaw's angular velocity (rad/s, counter-clockwise) at crank angle theta, speed omega.
  double jaw_angular_speed(double theta, double omega) const;
};

// Throws GeometryError naming the key at fault (a toggle too short, an angle for which the
// bottom edge's stroke is not the throw, a throw no eccentric of this linkage reaches).
SingleToggleLinkage single_toggle_linkage(double height, double gape, double closed_side_setting,
                                          double jaw_throw, double toggle_length,
                                          double toggle_angle);

}  // namespace comminute
