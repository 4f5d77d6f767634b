// Keys of [[walls]] type = "mesh": file (STL, ASCII or binary, required), unit_scale (-, 1: file
// units to m), scale (-, 1), rotate ([x, y, z] degrees about the fixed x, then y, then z axis
// through the origin, [0, 0, 0]), translate ([x, y, z] m, [0, 0, 0]), motion (table, optional),
// wear_coefficient (-, 0), hardness (Pa, required with wear).
#include "comminute/geometry/mesh_wall.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "comminute/geometry/rigid_motion.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

MeshWall::MeshWall(MeshSurface surface, std::unique_ptr<MotionModel> motion, ArchardWear wear)
    : mesh_(std::move(surface)), motion_(std::move(motion)), archard_(wear) {
  wear_volume_.assign(mesh_.triangles().size(), 0.0);
  if (motion_) motion_->at(0.0, kinematics.velocity, kinematics.angular_velocity);
}

Vec3 MeshWall::rotate_to_world(const Vec3& b) const {
  return axes_[0] * b.x + axes_[1] * b.y + axes_[2] * b.z;
}

Vec3 MeshWall::to_world(const Vec3& b) const {
  return rotate_to_world(b) + offset_;
}

Vec3 MeshWall::rotate_to_body(const Vec3& d) const {
  return {dot(axes_[0], d), dot(axes_[1], d), dot(axes_[2], d)};
}

Vec3 MeshWall::to_body(const Vec3& x) const {
  return rotate_to_body(x - offset_);
}

int MeshWall::contacts(const Vec3& x, double r, double margin,
                       std::vector<WallContact>& out) const {
  const std::size_t first = out.size();
  mesh_.contacts(to_body(x), r, margin, out);
  return to_world(out, first);
}

int MeshWall::contacts_among(const Vec3& x, double r, double margin,
                             std::span<const std::uint32_t> elements,
                             std::vector<WallContact>& out) const {
  const std::size_t first = out.size();
  mesh_.contacts_among(to_body(x), r, margin, elements, out);
  return to_world(out, first);
}

bool MeshWall::near_elements(const Vec3& x, double r, double margin,
                             std::vector<std::uint32_t>& out) const {
  mesh_.near_triangles(to_body(x), r + margin, out);
  return true;
}

int MeshWall::to_world(std::vector<WallContact>& out, std::size_t first) const {
  for (std::size_t k = first; k < out.size(); ++k) {
    out[k].normal = rotate_to_world(out[k].normal);
    out[k].point = to_world(out[k].point);
  }
  return static_cast<int>(out.size() - first);
}

bool MeshWall::place_exactly(double t_old, double t_new) {
  Vec3 d, rot;
  if (!motion_ || !motion_->pose(t_old, d, rot)) return false;
  // the centre at t = 0, once (a restart recovers it from the saved centre and time)
  if (!start_center_known_) {
    start_center_ = kinematics.center - d;
    start_center_known_ = true;
  }
  motion_->pose(t_new, d, rot);
  const Vec3 c0 = start_center_;
  // world = R (body - c0) + c0 + d, the body frame being the world at t = 0
  axes_ = {rotate(Vec3{1, 0, 0}, rot), rotate(Vec3{0, 1, 0}, rot), rotate(Vec3{0, 0, 1}, rot)};
  offset_ = c0 + d - rotate_to_world(c0);
  kinematics.center = c0 + d;
  return true;
}

void MeshWall::advance(double dt) {
  if (place_exactly(motion_time_, motion_time_ + dt)) {
    motion_time_ += dt;
    motion_->at(motion_time_, kinematics.velocity, kinematics.angular_velocity);
    return;
  }
  // the motion at mid-step integrates a time-dependent rotation to second order
  if (motion_)
    motion_->at(motion_time_ + 0.5 * dt, kinematics.velocity, kinematics.angular_velocity);
  const Vec3 rot = kinematics.angular_velocity * dt;
  Kinematics& k = kinematics;
  if (norm2(rot) > 0) {
    for (Vec3& a : axes_) a = rotate(a, rot);
    // Gram-Schmidt: round-off must not shear the mesh over millions of steps
    axes_[0] = axes_[0] / norm(axes_[0]);
    axes_[1] = axes_[1] - dot(axes_[0], axes_[1]) * axes_[0];
    axes_[1] = axes_[1] / norm(axes_[1]);
    axes_[2] = cross(axes_[0], axes_[1]);
    offset_ = k.center + rotate(offset_ - k.center, rot);
  }
  offset_ += k.velocity * dt;
  k.center += k.velocity * dt;
  motion_time_ += dt;
  if (motion_) motion_->at(motion_time_, kinematics.velocity, kinematics.angular_velocity);
}

double MeshWall::axis_reach(const Vec3& c, const Vec3& a) const {
  // The cache, measured from (c0, a0), bounds the distance from (c, a) for every vertex p:
  // a x (p - c) = a0 x (p - c0) + (a - a0) x (p - c0) + a x (c0 - c), so the distance is at most
  // from_axis + |a - a0| from_center + |c - c0| (a and -a give the same line). The cache is
  // measured anew when that slack exceeds a millionth of the reach: the pose's round-off (which
  // moves a body-frame centre or axis by ulps from step to step) does not make it rescan the mesh.
  Reach& q = reach_;
  const Vec3 along = dot(a, q.axis) < 0 ? -1.0 * a : a;
  double slack = norm(c - q.center) + norm(along - q.axis) * q.from_center;
  if (q.from_center < 0 || !(slack <= 1e-6 * q.from_center)) {
    q = {c, a, mesh_.reach_from(c), mesh_.reach_from_axis(c, a)};
    slack = 0;
  }
  return std::min(q.from_axis + slack, q.from_center + norm(c - q.center));
}

double MeshWall::travel(double dt) const {
  // a vertex p moves at |v + w x (p - centre)| <= |v| + |w| d(p), d(p) its distance from the
  // rotation axis: a drum turning about its own axis travels w R dt, whatever its length
  const Kinematics& k = kinematics;
  const double w = norm(k.angular_velocity);
  const double d =
      w > 0 ? axis_reach(to_body(k.center), rotate_to_body(k.angular_velocity / w)) : 0.0;
  return (norm(k.velocity) + w * d) * dt;
}

void MeshWall::wear(int element, double fn, double s) {
  // Archard, J. Appl. Phys. 24 (1953) 981, eq. (3): worn volume V = k F_n s / H
  if (element >= 0 && fn > 0)
    wear_volume_[static_cast<std::size_t>(element)] +=
        archard_.coefficient * fn * s / archard_.hardness;
}

SurfaceMesh MeshWall::surface(double) const {
  SurfaceMesh m;
  m.vertices.reserve(mesh_.vertices().size());
  for (const Vec3& v : mesh_.vertices()) m.vertices.push_back(to_world(v));
  m.triangles = mesh_.triangles();
  m.wear_depth.resize(wear_volume_.size());
  for (std::size_t t = 0; t < wear_volume_.size(); ++t)
    m.wear_depth[t] = wear_volume_[t] / mesh_.areas()[t];
  return m;
}

void MeshWall::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "geometry", std::vector<Vec3>{offset_, Vec3{}, kinematics.center});
  a.put(prefix + "orientation", std::vector<Vec3>{axes_[0], axes_[1], axes_[2]});
  a.put(prefix + "motion_time", std::vector<double>{motion_time_});
  a.put(prefix + "wear_volume", wear_volume_);
  // a closed-form pose's centre at t = 0 (a restart must not recover it with round-off)
  if (start_center_known_) a.put(prefix + "start_center", std::vector<Vec3>{start_center_});
}

void MeshWall::load(const Archive& a, const std::string& prefix) {
  const auto g = a.get<Vec3>(prefix + "geometry");
  const auto axes = a.get<Vec3>(prefix + "orientation");
  const auto t = a.get<double>(prefix + "motion_time");
  auto wear = a.get<double>(prefix + "wear_volume");
  bool ok = g.size() == 3 && axes.size() == 3 && t.size() == 1 && std::isfinite(t[0]) &&
            wear.size() == wear_volume_.size();
  for (const Vec3& v : axes) ok = ok && is_finite(v);
  for (double w : wear) ok = ok && std::isfinite(w);
  if (!ok)
    throw Error(
        fmt::format("checkpoint entries '{}orientation', '{}motion_time' and "
                    "'{}wear_volume' do not hold this mesh's pose and {} triangles",
                    prefix, prefix, prefix, wear_volume_.size()));
  offset_ = g[0];
  kinematics.center = g[2];
  for (int k = 0; k < 3; ++k)
    axes_[static_cast<std::size_t>(k)] = axes[static_cast<std::size_t>(k)];
  motion_time_ = t[0];
  start_center_known_ = a.has(prefix + "start_center");
  if (start_center_known_) {
    const auto c0 = a.get<Vec3>(prefix + "start_center");
    if (c0.size() != 1 || !is_finite(c0[0]))
      throw Error(fmt::format("checkpoint entry '{}start_center' does not hold one point", prefix));
    start_center_ = c0[0];
  }
  wear_volume_ = std::move(wear);
  reach_ = {};
}

std::size_t MeshWall::bytes() const {
  return mesh_.bytes() + wear_volume_.capacity() * sizeof(double);
}

namespace {

// Scale, rotate about x, y, z (degrees, fixed axes), translate.
std::vector<Vec3> placed(const CaseTable& t, std::vector<Vec3> v) {
  const double s =
      t.number("unit_scale", Limits::positive(), 1.0) * t.number("scale", Limits::positive(), 1.0);
  const Vec3 deg = t.vec3("rotate", Limits::any(), {});
  const Vec3 shift = t.vec3("translate", Limits::any(), {});
  const double rad = std::numbers::pi / 180.0;
  for (Vec3& p : v) {
    p = p * s;
    p = rotate(p, Vec3{deg.x * rad, 0, 0});
    p = rotate(p, Vec3{0, deg.y * rad, 0});
    p = rotate(p, Vec3{0, 0, deg.z * rad});
    p += shift;
  }
  return v;
}

const bool registered = WallRegistry::add("mesh", [](const CaseTable& t) {
  IndexedMesh m;
  try {
    m = read_stl(t.input_file("file"));
  } catch (const StlError& e) {
    t.fail("file", e.what());
  }
  std::unique_ptr<MotionModel> motion;
  if (auto mt = t.optional_table("motion")) {
    for (const char* k : {"velocity", "angular_velocity"})
      if (t.has(k)) t.fail(k, "give the motion either here or in [walls.motion], not both");
    motion = make_motion(*mt);
  }
  std::vector<Vec3> vertices = placed(t, std::move(m.vertices));
  try {  // the placed mesh once more: scaling must not overflow or collapse a triangle
    validate_mesh({vertices, m.triangles});
  } catch (const StlError& e) {
    t.fail("file", fmt::format("after unit_scale, scale, rotate and translate: {}", e.what()));
  }
  ArchardWear wear;
  wear.coefficient = t.number("wear_coefficient", Limits::non_negative(), 0.0);
  if (wear.coefficient > 0) wear.hardness = t.number("hardness", Limits::positive());
  return std::make_unique<MeshWall>(MeshSurface(std::move(vertices), m.triangles),
                                    std::move(motion), wear);
});

}  // namespace
}  // namespace comminute
