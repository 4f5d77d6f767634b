#pragma once
// A pair of rolls (a high-pressure grinding roll, HPGR) as triangle meshes: two rolls of diameter
// D and width W with their axes along y, their centres on the x axis at x = -/+ (D/2 + gap/2)
// (the line of centres is x, the pinch at the origin, the narrowest gap between the rolls
// `gap`), a feed chute of two inclined plates above the pinch and two side (cheek) plates closing
// the ends. Everything is placed relative to the origin; the wall reader shifts it by `center`.
//
// Roll: a prism of `segments` vertices on the circle of radius D/2 in the (x, z) plane (one vertex
// of each roll on the line of centres, so the gap between the two is `gap` exactly), cut into
// rings along y, closed by flat end discs: a closed, consistently oriented surface with outward
// normals.
// Chute: plates whose lower edges lie at x = -/+ opening/2, `chute_clearance` above the roll
// surface below them, leaning outwards by `chute_angle` from the vertical up to `chute_height`
// above the lower edges. Side plates: rectangles at y = -/+ (W/2 + side_plate_clearance) from the
// bottom of the rolls to the top of the chute. Without side plates (a slice periodic along y) the
// rolls and the chute extend `overhang` (rounded up to whole tiles of their tiling along y, which
// repeats with period W) beyond -/+ W/2 instead, so that a periodic face at -/+ W/2 sees the same
// surface on both sides.
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

struct RollPairGeometry {
  double diameter = 0;              // m, of each roll
  double width = 0;                 // m, roll length along y
  double gap = 0;                   // m, at the pinch
  int segments = 360;               // roll polygon vertices on the full circle
  int axial_divisions = 0;          // rings of the roll mantle across the width (0: automatic)
  bool chute = true;                // false: no chute
  double chute_opening = 0;         // m, between the lower edges of the plates
  double chute_height = 0;          // m, vertical extent of the plates
  double chute_angle = 0;           // rad, lean of each plate from the vertical (outwards)
  double chute_clearance = 0;       // m, lower edge above the roll surface
  bool side_plates = true;          // false: rolls and chute extend `overhang` past the width
  double side_plate_clearance = 0;  // m, from the roll end to the side plate
  double overhang = 0;              // m, without side plates
};

// Throws GeometryError (wall_group.hpp) naming the key of the offending dimension.
void check_roll_pair(const RollPairGeometry& g);
// Distance of each roll's axis from the pinch along the line of centres: D/2 + gap/2 (m).
double roll_offset(const RollPairGeometry& g);
// Rings of the roll mantle along y: axial_divisions across the width, or when 0 enough that a ring
// is at most four facet chords long (long thin facets would fill the cells of the mesh's triangle
// grid); without side plates continued over the overhang, rounded up to whole rings (so a slice
// periodic across the width sees the same rings from both faces).
int roll_rings(const RollPairGeometry& g);
// Roll k (0: at -x, 1: at +x), closed, outward normals.
IndexedMesh roll_mesh(const RollPairGeometry& g, int k);
// The chute's two plates (open surfaces, normals towards the chute's inside); empty without chute.
IndexedMesh chute_mesh(const RollPairGeometry& g);
// Height (m) of the chute plates' lower edges above the line of centres.
double chute_bottom(const RollPairGeometry& g);
// The two side plates (normals towards the rolls); empty without side plates.
IndexedMesh side_plates_mesh(const RollPairGeometry& g);

}  // namespace comminute
