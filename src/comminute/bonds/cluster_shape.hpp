#pragma once
// The solid a bonded grain fills with sub-spheres, in its body frame (centre at the origin):
// a sphere, an ellipsoid with its length along x, width along y and thickness along z, or a
// closed triangle mesh. Each answers the signed distance of a point to its surface (negative
// inside), its volume and a bounding half-extent; the packing uses nothing else.
#include <memory>

#include "comminute/core/vec3.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute::bonds {

class ClusterShape {
 public:
  virtual ~ClusterShape() = default;
  // m, < 0 inside: minus the distance to the surface; > 0 outside: the distance.
  virtual double signed_distance(const Vec3& x) const = 0;
  virtual double volume() const = 0;         // m³
  virtual Vec3 half_extent() const = 0;      // m, the shape lies in [−h, h] per axis
  double equivalent_diameter() const;        // m, of the sphere of the same volume
  Vec3 outward_normal(const Vec3& x) const;  // unit, the gradient of signed_distance (numerical)
};

std::unique_ptr<ClusterShape> make_sphere_shape(double diameter);
std::unique_ptr<ClusterShape> make_ellipsoid_shape(double length, double width, double thickness);
// A closed mesh (every edge shared by two triangles; Error otherwise), moved so that its volume
// centroid is the origin.
std::unique_ptr<ClusterShape> make_mesh_shape(const IndexedMesh& mesh);

// Distance from x to the surface of the ellipsoid with semi-axes e (all > 0), signed as above
// (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid", Geometric
// Tools 2013, eq. for F(t) = Σ (e_i y_i / (t + e_i²))² − 1, root by bisection).
double ellipsoid_signed_distance(const Vec3& e, const Vec3& x);

}  // namespace comminute::bonds
