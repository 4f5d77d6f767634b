#pragma once
// A jaw crusher (Blake type) as triangle meshes: a fixed jaw and a swinging jaw with their width
// along y, gravity along -z, the discharge opening at z = 0 and the feed opening at z = height.
// Everything is placed relative to the origin; the wall reader shifts it by `center`.
//
// Fixed jaw: the rectangle x = 0, 0 <= z <= height, facing +x. Swinging jaw, drawn at its
// closed side: the plane rectangle from its bottom edge (x = closed_side_setting, z = 0) to its
// top edge (x = gape, z = height), facing the fixed jaw. It pivots about the line through its top
// edge along y (the pivot, which stays put: the feed opening is `gape` at all times); an eccentric
// drives its bottom edge, which swings between the closed side (x = css) and the open side
// (x = css + throw), once per turn of the eccentric. Both jaws are tiled by `divisions` strips
// along the height (so the wear per triangle shows a profile down the jaw) and by tiles about as
// wide as a strip is high across the width (repeating with period `width`). Side (cheek) plates:
// the rectangles y = -/+ width/2, 0 <= x <= gape, 0 <= z <= height, facing the chamber; without
// them (a slice periodic along y) the jaws extend `overhang` (rounded up to whole tiles) beyond
// -/+ width/2.
//
// Motion (a documented simplification of the eccentric and toggle linkage): the swing angle
// about the pivot varies harmonically with the eccentric's phase,
//   alpha(t) = alpha_open (1 - cos(Omega t)) / 2,
// (an infinitely long toggle), with alpha_open the angle that puts the bottom edge at x = css +
// throw exactly; the closed-side setting and the throw are thus reached exactly at the dead
// centres (t = 0 and t = pi / Omega), and in between the bottom edge stays within 0.14 % of the
// throw of the harmonic stroke for the laboratory jaw (docs/models.md, "Roll press and jaw
// crusher", J1-J2).
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

struct JawCrusherGeometry {
  double height = 0;               // m, of the jaws
  double width = 0;                // m, along y
  double gape = 0;                 // m, feed opening at the top
  double closed_side_setting = 0;  // m, css: narrowest discharge opening at the bottom
  double jaw_throw = 0;            // m, stroke of the bottom edge along x
  int divisions = 16;              // strips of each jaw along the height
  bool side_plates = true;         // false: jaws extend `overhang` past the width
  double overhang = 0;             // m, without side plates
};

// Throws GeometryError (wall_group.hpp) naming the key of the offending dimension.
void check_jaw_crusher(const JawCrusherGeometry& g);
IndexedMesh fixed_jaw_mesh(const JawCrusherGeometry& g);
// At the closed side (t = 0).
IndexedMesh swing_jaw_mesh(const JawCrusherGeometry& g);
IndexedMesh cheek_plates_mesh(const JawCrusherGeometry& g);
// The pivot of the swinging jaw: its top edge on y = 0, (gape, 0, height).
Vec3 jaw_pivot(const JawCrusherGeometry& g);
// alpha_open (rad, about +y; negative: the jaw opens by turning about -y).
double jaw_opening_angle(const JawCrusherGeometry& g);

}  // namespace comminute
