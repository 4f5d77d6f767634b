// Keys of [[walls]] type = "box": lo, hi (m, required, every component of hi above lo), open
// (faces left open among "-x", "+x", "-y", "+y", "-z", "+z", default none).
#include "comminute/geometry/box_wall.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace comminute {

BoxWall::BoxWall(const Vec3& lo, const Vec3& hi, std::array<bool, 6> open)
    : lo_(lo), hi_(hi), open_(open) {}

int BoxWall::contacts(const Vec3& x, double r, double margin, std::vector<WallContact>& out) const {
  int n = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int face = 2 * axis + side;
      if (open_[face]) continue;
      const double d = side == 0 ? x[axis] - lo_[axis] : hi_[axis] - x[axis];
      if (d >= r + margin) continue;
      Vec3 normal;
      normal[axis] = side == 0 ? 1.0 : -1.0;
      Vec3 point = x;
      point[axis] = side == 0 ? lo_[axis] : hi_[axis];
      out.push_back({normal, point, r - d, face});
      ++n;
    }
  }
  return n;
}

void BoxWall::advance(double dt) {
  lo_ += kinematics.velocity * dt;
  hi_ += kinematics.velocity * dt;
  kinematics.center += kinematics.velocity * dt;
}

SurfaceMesh BoxWall::surface(double) const {
  SurfaceMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back(
        {(k & 1) ? hi_.x : lo_.x, (k & 2) ? hi_.y : lo_.y, (k & 4) ? hi_.z : lo_.z});
  // two triangles per closed face, corners listed counter-clockwise seen from inside
  const std::array<std::array<std::uint32_t, 4>, 6> quads = {
      {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}}};
  for (int f = 0; f < 6; ++f) {
    if (open_[f]) continue;
    const auto& q = quads[f];
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

void BoxWall::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "geometry", std::vector<Vec3>{lo_, hi_, kinematics.center});
}

void BoxWall::load(const Archive& a, const std::string& prefix) {
  auto g = a.get<Vec3>(prefix + "geometry");
  lo_ = g.at(0);
  hi_ = g.at(1);
  kinematics.center = g.at(2);
}

namespace {

std::array<bool, 6> read_open_faces(const CaseTable& t) {
  std::array<bool, 6> open{};
  if (!t.has("open")) return open;
  const std::vector<std::string> faces = {"-x", "+x", "-y", "+y", "-z", "+z"};
  for (const auto& f : t.strings("open")) {
    auto it = std::find(faces.begin(), faces.end(), f);
    if (it == faces.end())
      t.fail("open", fmt::format("unknown face \"{}\": use -x, +x, -y, +y, -z, +z", f));
    open[static_cast<std::size_t>(it - faces.begin())] = true;
  }
  return open;
}

const bool registered = WallRegistry::add("box", [](const CaseTable& t) {
  const Vec3 lo = t.vec3("lo"), hi = t.vec3("hi");
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a])) t.fail("hi", "every component of hi must exceed lo");
  return std::make_unique<BoxWall>(lo, hi, read_open_faces(t));
});

}  // namespace
}  // namespace comminute
