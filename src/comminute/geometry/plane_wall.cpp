#include "comminute/geometry/plane_wall.hpp"

#include "comminute/geometry/rigid_motion.hpp"

namespace comminute {

PlaneWall::PlaneWall(const Vec3& point, const Vec3& normal)
    : point_(point), normal_(normal / norm(normal)) {}

int PlaneWall::contacts(const Vec3& x, double r, double margin,
                        std::vector<WallContact>& out) const {
  const double d = dot(x - point_, normal_);
  if (d >= r + margin) return 0;
  out.push_back({normal_, x - d * normal_, r - d, 0});
  return 1;
}

void PlaneWall::advance(double dt) {
  const Vec3 rot = kinematics.angular_velocity * dt;
  point_ = kinematics.center + rotate(point_ - kinematics.center, rot) + kinematics.velocity * dt;
  normal_ = rotate(normal_, rot);
  kinematics.center += kinematics.velocity * dt;
}

bool PlaneWall::surface_moves() const {
  return norm2(kinematics.velocity) > 0 || norm2(cross(kinematics.angular_velocity, normal_)) > 0;
}

SurfaceMesh PlaneWall::surface(double extent) const {
  const Vec3 u = perpendicular(normal_), v = cross(normal_, u);
  SurfaceMesh m;
  for (int k = 0; k < 4; ++k) {
    const double su = (k == 0 || k == 3) ? -1 : 1, sv = k < 2 ? -1 : 1;
    m.vertices.push_back(point_ + extent * (su * u + sv * v));
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

void PlaneWall::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "geometry", std::vector<Vec3>{point_, normal_, kinematics.center});
}

void PlaneWall::load(const Archive& a, const std::string& prefix) {
  auto g = a.get<Vec3>(prefix + "geometry");
  point_ = g.at(0);
  normal_ = g.at(1);
  kinematics.center = g.at(2);
}

}  // namespace comminute
