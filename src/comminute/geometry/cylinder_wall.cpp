// Keys of [[walls]] type = "cylinder": center (m, required), axis (-, default [0, 0, 1]), radius
// and length (m, required), side ("inside" or "outside", required), caps (bool, default false).
#include "comminute/geometry/cylinder_wall.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/units.hpp"
#include "comminute/geometry/rigid_frame.hpp"
#include "comminute/geometry/wall_keys.hpp"

namespace comminute {

CylinderWall::CylinderWall(const Vec3& center, const Vec3& axis, double radius, double length,
                           bool inside, bool caps)
    : center_(center),
      axis_(axis / norm(axis)),
      radius_(radius),
      length_(length),
      inside_(inside),
      caps_(caps) {
  kinematics.center = center;
}

int CylinderWall::contacts(const Vec3& x, double r, double margin,
                           std::vector<WallContact>& out) const {
  const Vec3 d = x - center_;
  const double s = dot(d, axis_);  // axial coordinate
  const Vec3 radial = d - s * axis_;
  const double rho = norm(radial);
  const Vec3 er = rho > 0 ? radial / rho : perpendicular(axis_);
  const double half = 0.5 * length_;
  int n = 0;
  if (inside_) {
    const double gap = radius_ - rho;  // centre to lateral surface
    if (std::abs(s) <= half && gap < r + margin) {
      out.push_back({-er, center_ + s * axis_ + radius_ * er, r - gap, 0});
      ++n;
    }
    if (caps_ && rho <= radius_) {
      for (int side = 0; side < 2; ++side) {
        const double g = side == 0 ? s + half : half - s;
        if (g >= r + margin) continue;
        const Vec3 normal = side == 0 ? axis_ : -axis_;
        out.push_back({normal, x - g * normal, r - g, 1 + side});
        ++n;
      }
    }
    return n;
  }
  // outside: nearest point of the solid cylinder
  const double sc = std::clamp(s, -half, half);
  const double rc = std::min(rho, radius_);
  const Vec3 q = center_ + sc * axis_ + rc * er;
  const Vec3 dx = x - q;
  double dist = norm(dx);
  Vec3 normal;
  if (dist > 0 && (std::abs(s) > half || rho > radius_)) {
    normal = dx / dist;
  } else {  // centre inside the solid: push out through the nearest surface
    const double to_side = radius_ - rho, to_end = half - std::abs(s);
    if (to_side < to_end) {
      normal = er;
      dist = -to_side;
    } else {
      normal = s >= 0 ? axis_ : -axis_;
      dist = -to_end;
    }
  }
  if (dist >= r + margin) return 0;
  out.push_back({normal, x - dist * normal, r - dist, 0});
  return 1;
}

void CylinderWall::advance(double dt) {
  move_rigidly(center_, axis_, kinematics, dt);
}

bool CylinderWall::surface_moves() const {
  if (norm2(kinematics.velocity) > 0) return true;
  // rotation about its own axis (through a point on the axis) leaves the surface in place
  const Vec3& w = kinematics.angular_velocity;
  if (norm2(w) == 0) return false;
  const Vec3 off = kinematics.center - center_;
  return norm2(cross(w, axis_)) > 1e-24 * norm2(w) || norm2(cross(off, axis_)) > 1e-24;
}

SurfaceMesh CylinderWall::surface(double) const {
  SurfaceMesh m;
  const int segments = 72;
  const Vec3 u = perpendicular(axis_), v = cross(axis_, u);
  for (int k = 0; k < segments; ++k) {
    const double phi = 2 * units::pi * k / segments;
    const Vec3 e = std::cos(phi) * u + std::sin(phi) * v;
    m.vertices.push_back(center_ - 0.5 * length_ * axis_ + radius_ * e);
    m.vertices.push_back(center_ + 0.5 * length_ * axis_ + radius_ * e);
  }
  for (std::uint32_t k = 0; k < segments; ++k) {
    const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % segments);
    m.triangles.push_back({a, b, a + 1});
    m.triangles.push_back({b, b + 1, a + 1});
  }
  if (caps_ || !inside_) {
    const auto c0 = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(center_ - 0.5 * length_ * axis_);
    m.vertices.push_back(center_ + 0.5 * length_ * axis_);
    for (std::uint32_t k = 0; k < segments; ++k) {
      const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % segments);
      m.triangles.push_back({c0, b, a});
      m.triangles.push_back({c0 + 1, a + 1, b + 1});
    }
  }
  return m;
}

void CylinderWall::save(Archive& a, const std::string& prefix) const {
  save_rigid_frame(a, prefix, center_, axis_, kinematics);
}

void CylinderWall::load(const Archive& a, const std::string& prefix) {
  load_rigid_frame(a, prefix, center_, axis_, kinematics);
}

namespace {

const bool registered = WallRegistry::add("cylinder", [](const CaseTable& t) {
  return std::make_unique<CylinderWall>(
      t.vec3("center"), read_unit_vector(t, "axis", {0, 0, 1}),
      t.number("radius", Limits::positive()), t.number("length", Limits::positive()),
      t.choice("side", {"inside", "outside"}) == "inside", t.boolean("caps", false));
});

}  // namespace
}  // namespace comminute
