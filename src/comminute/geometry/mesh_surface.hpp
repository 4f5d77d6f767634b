#pragma once
// A static triangle surface in its body frame with what contact needs: unit normals, unique edges
// with their one or two triangles, planar patches (triangles joined across edges whose normals
// agree, so a flat face tiled by many triangles is one patch), the triangle bins, and the
// sphere query that resolves face, edge and vertex regions into one contact per touched feature.
//
// Regions (Ericson, Real-Time Collision Detection, 2005, Sec. 5.1.5): the closest point of a
// triangle to a sphere centre lies in its face, on one of its edges or at one of its corners.
// Kept contacts (Kremmer & Favier, Int. J. Numer. Meth. Eng. 2001; Su et al., Powder Technol.
// 2011): every face contact, one per patch; an edge contact only when neither triangle of that
// edge has a face contact; a vertex contact only when no triangle around it has a face contact and
// no edge at it an edge contact; each edge and vertex once. A sphere on a tiled flat surface thus
// feels one contact, and crossing a convex edge goes face -> edge -> face with the same distance
// and normal at each switch (no force jump).
//
// Feature ids (history keys): face contacts use their patch id p (0 <= p < patches), edge
// contacts patches + edge, vertex contacts patches + edges + vertex.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "comminute/geometry/triangle_bins.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

class MeshSurface {
 public:
  MeshSurface() = default;
  MeshSurface(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles);

  // Contacts of sphere (x, r) closer than r + margin, in the body frame, sorted by feature.
  // WallContact::element is the triangle that produced each. With margin = 0 (the force loop)
  // only the kept contacts; with margin > 0 (candidates for the neighbour lists) every feature
  // within reach that could become a kept contact as the sphere moves: the face of every
  // triangle within reach and every edge and corner within reach, but those inside a planar
  // patch, which never are (their overlaps are those of the distances to each feature).
  void contacts(const Vec3& x, double r, double margin, std::vector<WallContact>& out) const;
  // The same among the triangles `near` (ascending) only: exact when they hold every triangle
  // closer to x than r + margin.
  void contacts_among(const Vec3& x, double r, double margin, std::span<const std::uint32_t> near,
                      std::vector<WallContact>& out) const;
  // Appends, ascending, the triangles closer to x than `reach` (with a relative slack of 1e-9).
  void near_triangles(const Vec3& x, double reach, std::vector<std::uint32_t>& out) const;
  // True when a contact can pass from feature a to feature b as a sphere moves over the surface
  // (the same feature, or features that touch: a patch and its edges, corners and neighbouring
  // patches; an edge and its corners and the edges sharing one).
  bool adjacent(int a, int b) const;

  const std::vector<Vec3>& vertices() const { return v_; }
  const std::vector<std::array<std::uint32_t, 3>>& triangles() const { return tri_; }
  const std::vector<double>& areas() const { return area_; }
  std::size_t patches() const { return n_patch_; }
  // Largest distance of a vertex from point c (m).
  double reach_from(const Vec3& c) const;
  // Largest distance of a vertex from the line through c along the unit vector a (m).
  double reach_from_axis(const Vec3& c, const Vec3& a) const;
  std::size_t bytes() const;

 private:
  enum Region : std::uint8_t { face, edge, corner };
  struct Closest {
    Vec3 point;
    Region region = face;
    int local = 0;  // which edge (0: v0-v1, 1: v1-v2, 2: v2-v0) or corner
  };
  Closest closest(std::uint32_t t, const Vec3& x) const;
  // The triangles in the bins around the box of half-width reach about x, ascending, once each.
  void gather(const Vec3& x, double reach, std::vector<std::uint32_t>& near) const;
  // True when triangle t's plane is at least reach from x: it cannot be within reach.
  bool beyond(std::uint32_t t, const Vec3& x, double reach) const;
  bool patch_has_vertex(std::uint32_t patch, std::uint32_t v) const;

  std::vector<Vec3> v_;
  std::vector<std::array<std::uint32_t, 3>> tri_;
  std::vector<Vec3> normal_;
  std::vector<double> area_;
  std::vector<std::array<std::uint32_t, 3>> tri_edge_;         // edge id of local edge k
  std::vector<std::array<std::uint32_t, 2>> edge_vertex_;      // endpoints
  std::vector<std::array<std::int64_t, 2>> edge_triangle_;     // -1: open edge
  std::vector<std::uint32_t> patch_;                           // per triangle
  std::vector<std::uint32_t> vertex_start_, vertex_triangle_;  // triangles around each vertex
  std::vector<std::uint64_t> patch_pairs_;                     // neighbouring patches (a << 32 | b)
  std::vector<std::uint8_t> edge_flat_, vertex_flat_;  // inside a planar patch: never a contact
  std::size_t n_patch_ = 0;
  TriangleBins bins_;
};

}  // namespace comminute
