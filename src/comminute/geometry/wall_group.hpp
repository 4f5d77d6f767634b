#pragma once
// A machine generated from one [[walls]] table as several walls (its parts), each moving by itself
// and reporting its own force, torque and power: the two rolls, the chute and the side plates of
// a roll press, the jaws of a crusher. Each generator is a plug-in of WallGroupRegistry reading
// its own keys; the case builder names part p of a table named n "n_p" and gives every part the
// table's material (io/case/wall_builders.cpp).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/geometry/mesh_wall.hpp"
#include "comminute/geometry/stl_file.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

struct WallPart {
  std::string name;  // the part's name, appended to the table's name
  std::unique_ptr<Wall> wall;
};

struct WallGroup {
  std::vector<WallPart> parts;
};

// A generator's refusal of its dimensions: the key to blame (for InputError) and why.
class GeometryError : public Error {
 public:
  GeometryError(std::string key, const std::string& message)
      : Error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

using WallGroupRegistry = Registry<WallGroup, const CaseTable&>;

// The path of part `part`'s STL next to `file`: "dir/name.stl" -> "dir/name_<part>.stl".
std::filesystem::path part_stl_path(const std::filesystem::path& file, const std::string& part);

// When table t has `stl_file`, writes `mesh` there as part `part` (part_stl_path; folders
// created); a failure is an InputError naming `stl_file`.
void write_part_stl(const CaseTable& t, const std::string& part, const IndexedMesh& mesh);

// The keys every generated machine reads: center ([x, y, z], m, default origin), speed_rpm
// (1/min, > 0, required; returned in rad/s) and the Archard keys of all its parts
// (wear_coefficient, hardness).
struct MachineKeys {
  Vec3 center;       // m
  double speed = 0;  // rad/s
  ArchardWear wear;
};
MachineKeys read_machine_keys(const CaseTable& t);

// Geometry g after its generator's check, a GeometryError turned into an InputError naming the
// key in table t.
template <class Geometry>
Geometry checked(const CaseTable& t, const Geometry& g, void (*check)(const Geometry&)) {
  try {
    check(g);
  } catch (const GeometryError& e) {
    t.fail(e.key(), e.what());
  }
  return g;
}

// Part `part` of a generated machine: mesh m (built about the origin) shifted by `center`, its
// STL written (write_part_stl), moving by `motion` (may be null) about `rotation_center` (given
// relative to the origin like the mesh, shifted by `center` too).
WallPart make_part(const CaseTable& t, const std::string& part, IndexedMesh m, const Vec3& center,
                   std::unique_ptr<MotionModel> motion, const Vec3& rotation_center,
                   const ArchardWear& wear);

}  // namespace comminute
