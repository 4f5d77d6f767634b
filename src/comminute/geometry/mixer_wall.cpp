// The `mixer` wall (a bladed shaft turning about the vertical axis of a vessel) and the
// `mixer_vessel` wall (the vessel's shell and floor), meshes generated from their dimensions
// (geometry/mixer.hpp) instead of read from STL files; keys in docs/case-file.md (Mixer walls).
#include <fmt/format.h>

#include <numbers>

#include "comminute/geometry/generated_mesh.hpp"
#include "comminute/geometry/mesh_wall.hpp"
#include "comminute/geometry/mixer.hpp"
#include "comminute/geometry/ramped_rotation.hpp"

namespace comminute {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

MixerGeometry read_geometry(const CaseTable& t) {
  MixerGeometry g;
  g.vessel_diameter = t.number("vessel_diameter", Limits::positive());
  g.vessel_height = t.number("vessel_height", Limits::positive());
  g.blades = static_cast<int>(t.integer("blades", 1, 64));
  g.blades_built = static_cast<int>(t.integer("blades_built", 1, 64, g.blades));
  g.shaft_diameter = t.number("shaft_diameter", Limits::positive());
  if (t.has("blade_length") == t.has("wall_clearance"))
    t.fail("blade_length", "give either blade_length or wall_clearance (m), not both");
  g.blade_length = t.has("blade_length") ? t.number("blade_length", Limits::positive())
                                         : 0.5 * (g.vessel_diameter - g.shaft_diameter) -
                                               t.number("wall_clearance", Limits::positive());
  g.blade_height = t.number("blade_height", Limits::positive());
  g.blade_thickness = t.number("blade_thickness", Limits::positive());
  g.pitch = t.number("pitch", Limits{0.0, 90.0, true, false}, 90.0) * kDegree;
  g.bottom_clearance = t.number("bottom_clearance", Limits::positive());
  g.shaft_top = t.number("shaft_top", Limits::positive(), g.vessel_height);
  g.segments = static_cast<int>(t.integer("segments", 6, 100000, 24));
  g.shaft = t.boolean("shaft", true);
  try {
    check_mixer(g);
  } catch (const Error& e) {
    t.fail("blades", e.what());
  }
  return g;
}

// rpm, tip_speed (m/s at the blade tip) or a [walls.motion] table; none: the shaft stands still.
std::unique_ptr<MotionModel> read_speed(const CaseTable& t, const MixerGeometry& g) {
  const int given = int(t.has("rpm")) + int(t.has("tip_speed")) + int(t.has("motion"));
  if (given > 1) t.fail("rpm", "give the speed once: rpm, tip_speed or [walls.motion]");
  if (auto mt = t.optional_table("motion")) return make_motion(*mt);
  if (given == 0) return nullptr;
  // omega = 2 pi N / 60 (N in rpm) = v_tip / r_tip (docs/models.md eq. X1)
  const double omega = t.has("rpm") ? t.number("rpm", Limits::any()) * 2 * std::numbers::pi / 60
                                    : t.number("tip_speed", Limits::any()) / g.tip_radius();
  return std::make_unique<RampedRotation>(Vec3{0, 0, omega},
                                          t.number("ramp_time", Limits::non_negative(), 0.0));
}

std::unique_ptr<MeshWall> placed(IndexedMesh m, const Vec3& center,
                                 std::unique_ptr<MotionModel> motion) {
  for (Vec3& v : m.vertices) v += center;
  auto w = std::make_unique<MeshWall>(MeshSurface(std::move(m.vertices), m.triangles),
                                      std::move(motion), ArchardWear{});
  w->kinematics.center = center;
  return w;
}

const bool registered_shaft = WallRegistry::add("mixer", [](const CaseTable& t) {
  const MixerGeometry g = read_geometry(t);
  const Vec3 center = t.vec3("center", Limits::any(), {});
  IndexedMesh m = mixer_shaft_mesh(g);
  auto speed = read_speed(t, g);
  auto w = placed(m, center, std::move(speed));
  for (Vec3& v : m.vertices) v += center;
  write_stl_if_asked(t, m);
  return w;
});

const bool registered_vessel = WallRegistry::add("mixer_vessel", [](const CaseTable& t) {
  const double d = t.number("vessel_diameter", Limits::positive());
  const double h = t.number("vessel_height", Limits::positive());
  const auto n = static_cast<int>(t.integer("segments", 8, 100000, 72));
  const Vec3 center = t.vec3("center", Limits::any(), {});
  IndexedMesh m = mixer_vessel_mesh(d, h, n);
  auto w = placed(m, center, nullptr);
  for (Vec3& v : m.vertices) v += center;
  write_stl_if_asked(t, m);
  return w;
});

}  // namespace
}  // namespace comminute
