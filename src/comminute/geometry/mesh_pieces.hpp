#pragma once
// Pieces the machine generators build their meshes from.
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

// Appends the flat parallelogram with corner o and edges u and v, tiled by nu x nv cells of two
// triangles each (shared vertices, so the tiles join into one planar surface), every triangle's
// normal on the side of `facing` (a direction).
void add_grid(IndexedMesh& m, const Vec3& o, const Vec3& u, const Vec3& v, int nu, int nv,
              const Vec3& facing);
// Tiles along one axis of a part `width` wide: tiles of length width / m (m = ceil(width /
// target), at least 1) across the width and, with `overhang` > 0, continued past both sides over
// the overhang rounded up to whole tiles, so that a slice periodic along that axis with period
// `width` sees the same tiling from both of its faces.
struct AxialTiling {
  double half = 0;  // half the tiled length
  int count = 0;    // tiles over it
};
AxialTiling axial_tiling(double width, double overhang, double target);

// Appends all of `part` to m (vertices renumbered).
void append(IndexedMesh& m, const IndexedMesh& part);
// Unit normal of triangle t of m (right-hand rule on its corner order).
Vec3 triangle_normal(const IndexedMesh& m, std::size_t t);

}  // namespace comminute
