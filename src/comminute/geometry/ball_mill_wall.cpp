// The `ball_mill` wall: a mesh wall generated from the mill's dimensions (geometry/ball_mill.hpp)
// instead of read from an STL file; keys in docs/case-file.md (Ball mill walls).
#include <fmt/format.h>

#include <numbers>

#include "comminute/geometry/ball_mill.hpp"
#include "comminute/geometry/generated_mesh.hpp"
#include "comminute/geometry/mesh_wall.hpp"
#include "comminute/geometry/ramped_rotation.hpp"

namespace comminute {

namespace {

BallMillGeometry read_geometry(const CaseTable& t) {
  BallMillGeometry g;
  g.diameter = t.number("diameter", Limits::positive());
  g.length = t.number("length", Limits::positive());
  g.lifters = static_cast<int>(t.integer("lifters", 0, 1000, 0));
  if (g.lifters > 0) {
    g.lifter_height = t.number("lifter_height", Limits::positive());
    g.lifter_width = t.number("lifter_width", Limits::positive());
    g.lifter_face_angle =
        t.number("lifter_face_angle", Limits{0.0, 80.0}, 0.0) * std::numbers::pi / 180;
  }
  g.end_liners = t.boolean("end_liners", true);
  g.segments = static_cast<int>(t.integer("segments", 8, 100000, 72));
  try {
    check_ball_mill(g);
  } catch (const Error& e) {
    t.fail(g.lifters > 0 ? "lifters" : "diameter", e.what());
  }
  return g;
}

std::unique_ptr<MotionModel> read_drive(const CaseTable& t, const BallMillGeometry& g) {
  const bool fraction = t.has("critical_speed_fraction");
  auto mt = t.optional_table("motion");
  if (fraction && mt)
    t.fail("critical_speed_fraction", "give the speed either here or in [walls.motion]");
  if (mt) return make_motion(*mt);
  if (!fraction) return nullptr;
  const double f = t.number("critical_speed_fraction", Limits{0.0, 2.0, true, false});
  const double d = t.number("ball_diameter", Limits::non_negative(), 0.0);
  if (d >= g.diameter) t.fail("ball_diameter", "must be below the mill diameter");
  // turning about the mill axis (+y) at a fraction of the critical speed
  return std::make_unique<RampedRotation>(Vec3{0, f * critical_speed(g.diameter, d), 0},
                                          t.number("ramp_time", Limits::non_negative(), 0.0));
}

const bool registered = WallRegistry::add("ball_mill", [](const CaseTable& t) {
  const BallMillGeometry g = read_geometry(t);
  IndexedMesh m = ball_mill_mesh(g);
  const Vec3 center = t.vec3("center", Limits::any(), {});
  for (Vec3& v : m.vertices) v += center;
  write_stl_if_asked(t, m);
  ArchardWear wear;
  wear.coefficient = t.number("wear_coefficient", Limits::non_negative(), 0.0);
  if (wear.coefficient > 0) wear.hardness = t.number("hardness", Limits::positive());
  auto w = std::make_unique<MeshWall>(MeshSurface(std::move(m.vertices), m.triangles),
                                      read_drive(t, g), wear);
  w->kinematics.center = center;
  return w;
});

}  // namespace
}  // namespace comminute
