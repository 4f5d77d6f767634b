#include "comminute/io/case/wall_builders.hpp"

#include <fmt/format.h>

#include "comminute/geometry/prescribed_motion_wall.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute::io {

namespace {

std::uint16_t wall_material(const CaseTable& t, const Simulation& sim) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sim.materials.size(); ++k)
    names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  return static_cast<std::uint16_t>(sim.materials.find(t.choice("material", names)));
}

std::vector<std::unique_ptr<Wall>> build_group(const CaseTable& t, const std::string& type,
                                               std::size_t index, const Simulation& sim) {
  for (const char* key : {"velocity", "angular_velocity", "rotation_center", "control", "motion"})
    if (t.has(key))
      t.fail(key, fmt::format("the parts of a generated '{}' move by themselves", type));
  std::unique_ptr<WallGroup> g = WallGroupRegistry::create(type, t);
  const std::string name = t.string("name", fmt::format("wall{}", index));
  const std::uint16_t material = wall_material(t, sim);
  std::vector<std::unique_ptr<Wall>> out;
  for (WallPart& part : g->parts) {
    part.wall->name = name + "_" + part.name;
    part.wall->material = material;
    out.push_back(std::move(part.wall));
  }
  return out;
}

}  // namespace

std::vector<std::unique_ptr<Wall>> build_walls(const CaseTable& t, std::size_t index,
                                               const Simulation& sim) {
  std::vector<std::string> types = WallRegistry::names();
  for (const std::string& n : WallGroupRegistry::names()) types.push_back(n);
  const std::string type = t.choice("type", types);
  if (WallGroupRegistry::contains(type)) return build_group(t, type, index, sim);
  std::unique_ptr<Wall> w = WallRegistry::create(type, t);
  w->name = t.string("name", fmt::format("wall{}", index));
  w->material = wall_material(t, sim);
  // (a wall with a [walls.motion] table set its kinematics itself)
  if (t.has("velocity")) w->kinematics.velocity = t.vec3("velocity", Limits::any());
  if (t.has("angular_velocity"))
    w->kinematics.angular_velocity = t.vec3("angular_velocity", Limits::any());
  if (t.has("rotation_center")) w->kinematics.center = t.vec3("rotation_center");
  if (!w->can_rotate() && norm2(w->kinematics.angular_velocity) > 0)
    t.fail("angular_velocity", fmt::format("a {} wall can translate but not rotate", w->type()));
  // an analytic wall moved by a motion model (a mesh wall's factory read its table itself)
  const auto mt = dynamic_cast<MeshWall*>(w.get()) ? std::nullopt : t.optional_table("motion");
  if (mt) {
    for (const char* k : {"velocity", "angular_velocity"})
      if (t.has(k)) t.fail(k, "give the motion either here or in [walls.motion], not both");
    std::unique_ptr<MotionModel> motion = make_motion(*mt);
    if (!w->can_rotate()) {  // the keys of a model that would turn the wall
      const std::string model = mt->string("type");
      const std::string what = fmt::format("a {} wall can translate but not rotate", w->type());
      if (model == "rotation") mt->fail("type", what);
      if (model == "eccentric" && mt->number("swing_amplitude", Limits::any(), 0.0) != 0)
        mt->fail("swing_amplitude", what);
      if (mt->has("angular_velocity")) mt->fail("angular_velocity", what);
    }
    w = std::make_unique<PrescribedMotionWall>(std::move(w), std::move(motion));
  }
  std::vector<std::unique_ptr<Wall>> out;
  out.push_back(std::move(w));
  return out;
}

}  // namespace comminute::io
