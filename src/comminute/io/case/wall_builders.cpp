#include "comminute/io/case/wall_builders.hpp"

#include <fmt/format.h>

namespace comminute::io {

std::unique_ptr<Wall> build_wall(const CaseTable& t, std::size_t index, const Simulation& sim) {
  std::unique_ptr<Wall> w = WallRegistry::create(t.choice("type", WallRegistry::names()), t);
  w->name = t.string("name", fmt::format("wall{}", index));
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sim.materials.size(); ++k)
    names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  w->material = static_cast<std::uint16_t>(sim.materials.find(t.choice("material", names)));
  // (a wall with a [walls.motion] table set its kinematics itself)
  if (t.has("velocity")) w->kinematics.velocity = t.vec3("velocity", Limits::any());
  if (t.has("angular_velocity"))
    w->kinematics.angular_velocity = t.vec3("angular_velocity", Limits::any());
  if (t.has("rotation_center")) w->kinematics.center = t.vec3("rotation_center");
  if (!w->can_rotate() && norm2(w->kinematics.angular_velocity) > 0)
    t.fail("angular_velocity", fmt::format("a {} wall can translate but not rotate", w->type()));
  return w;
}

}  // namespace comminute::io
