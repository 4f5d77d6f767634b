#pragma once
// A wall placed by a point and a unit direction (a plane: point and normal; a cylinder: centre
// and axis) moves rigidly with its Kinematics, and is checkpointed as those two vectors plus the
// rotation centre.
#include <string>

#include "comminute/core/archive.hpp"
#include "comminute/geometry/rigid_motion.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

// Rotates point and direction by ω dt about the rotation centre, then translates all by v dt.
inline void move_rigidly(Vec3& point, Vec3& direction, Kinematics& k, double dt) {
  const Vec3 rot = k.angular_velocity * dt;
  point = k.center + rotate(point - k.center, rot) + k.velocity * dt;
  direction = rotate(direction, rot);
  k.center += k.velocity * dt;
}

inline void save_rigid_frame(Archive& a, const std::string& prefix, const Vec3& point,
                             const Vec3& direction, const Kinematics& k) {
  a.put(prefix + "geometry", std::vector<Vec3>{point, direction, k.center});
}

inline void load_rigid_frame(const Archive& a, const std::string& prefix, Vec3& point,
                             Vec3& direction, Kinematics& k) {
  const auto g = a.get<Vec3>(prefix + "geometry");
  point = g.at(0);
  direction = g.at(1);
  k.center = g.at(2);
}

}  // namespace comminute
