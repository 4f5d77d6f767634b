// Keys of [[walls]] type = "plane": point (m, required), normal (-, default [0, 0, 1]).
#include "comminute/geometry/plane_wall.hpp"

#include "comminute/geometry/rigid_frame.hpp"
#include "comminute/geometry/wall_keys.hpp"

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
  move_rigidly(point_, normal_, kinematics, dt);
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
  save_rigid_frame(a, prefix, point_, normal_, kinematics);
}

void PlaneWall::load(const Archive& a, const std::string& prefix) {
  load_rigid_frame(a, prefix, point_, normal_, kinematics);
}

namespace {

const bool registered = WallRegistry::add("plane", [](const CaseTable& t) {
  return std::make_unique<PlaneWall>(t.vec3("point"), read_unit_vector(t, "normal", {0, 0, 1}));
});

}  // namespace
}  // namespace comminute
