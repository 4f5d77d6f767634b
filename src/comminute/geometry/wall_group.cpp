#include "comminute/geometry/wall_group.hpp"

#include <numbers>

#include "comminute/geometry/ball_mill.hpp"

namespace comminute {

std::filesystem::path part_stl_path(const std::filesystem::path& file, const std::string& part) {
  std::filesystem::path out = file;
  out.replace_filename(file.stem().string() + "_" + part + file.extension().string());
  return out;
}

void write_part_stl(const CaseTable& t, const std::string& part, const IndexedMesh& mesh) {
  if (!t.has("stl_file")) return;
  const std::filesystem::path file = part_stl_path(t.file_path("stl_file"), part);
  try {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    write_stl(file, mesh);
  } catch (const std::exception& e) {
    t.fail("stl_file", e.what());
  }
}

MachineKeys read_machine_keys(const CaseTable& t) {
  MachineKeys k;
  k.center = t.vec3("center", Limits::any(), {});
  k.speed = t.number("speed_rpm", Limits::positive()) * 2 * std::numbers::pi / 60;
  k.wear.coefficient = t.number("wear_coefficient", Limits::non_negative(), 0.0);
  if (k.wear.coefficient > 0) k.wear.hardness = t.number("hardness", Limits::positive());
  return k;
}

WallPart make_part(const CaseTable& t, const std::string& part, IndexedMesh m, const Vec3& center,
                   std::unique_ptr<MotionModel> motion, const Vec3& rotation_center,
                   const ArchardWear& wear) {
  for (Vec3& v : m.vertices) v += center;
  write_part_stl(t, part, m);
  auto w = std::make_unique<MeshWall>(MeshSurface(std::move(m.vertices), m.triangles),
                                      std::move(motion), wear);
  w->kinematics.center = center + rotation_center;
  return {part, std::move(w)};
}

}  // namespace comminute
