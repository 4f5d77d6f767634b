#include "comminute/io/case/wall_builders.hpp"

#include <fmt/format.h>

#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/cylinder_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"

namespace comminute::io {

namespace {

Vec3 unit_vector(const CaseTable& t, std::string_view key, const Vec3& fallback) {
  const Vec3 v = t.vec3(key, Limits::any(), fallback);
  if (norm(v) == 0) t.fail(key, "must not be the zero vector");
  return v / norm(v);
}

const bool plane =
    WallBuilderRegistry::add("plane", [](const CaseTable& t) -> std::unique_ptr<Wall> {
      return std::make_unique<PlaneWall>(t.vec3("point"), unit_vector(t, "normal", {0, 0, 1}));
    });

const bool box = WallBuilderRegistry::add("box", [](const CaseTable& t) -> std::unique_ptr<Wall> {
  const Vec3 lo = t.vec3("lo"), hi = t.vec3("hi");
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a])) t.fail("hi", "every component of hi must exceed lo");
  std::array<bool, 6> open{};
  if (t.has("open")) {
    const std::vector<std::string> faces = {"-x", "+x", "-y", "+y", "-z", "+z"};
    for (const auto& f : t.strings("open")) {
      auto it = std::find(faces.begin(), faces.end(), f);
      if (it == faces.end())
        t.fail("open", fmt::format("unknown face \"{}\": use -x, +x, -y, +y, -z, +z", f));
      open[static_cast<std::size_t>(it - faces.begin())] = true;
    }
  }
  return std::make_unique<BoxWall>(lo, hi, open);
});

const bool cylinder =
    WallBuilderRegistry::add("cylinder", [](const CaseTable& t) -> std::unique_ptr<Wall> {
      return std::make_unique<CylinderWall>(
          t.vec3("center"), unit_vector(t, "axis", {0, 0, 1}),
          t.number("radius", Limits::positive()), t.number("length", Limits::positive()),
          t.choice("side", {"inside", "outside"}) == "inside", t.boolean("caps", false));
    });

}  // namespace

std::unique_ptr<Wall> build_wall(const CaseTable& t, std::size_t index, const Simulation& sim) {
  const std::string type = t.choice("type", WallBuilderRegistry::names());
  std::unique_ptr<Wall> w = WallBuilderRegistry::create(type, t);
  w->name = t.string("name", fmt::format("wall{}", index));
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sim.materials.size(); ++k)
    names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  w->material = static_cast<std::uint16_t>(sim.materials.find(t.choice("material", names)));
  w->kinematics.velocity = t.vec3("velocity", Limits::any(), {});
  w->kinematics.angular_velocity = t.vec3("angular_velocity", Limits::any(), {});
  if (t.has("rotation_center")) w->kinematics.center = t.vec3("rotation_center");
  if (type == "box" && norm2(w->kinematics.angular_velocity) > 0)
    t.fail("angular_velocity", "a box wall can translate but not rotate");
  return w;
}

}  // namespace comminute::io
