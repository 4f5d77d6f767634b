// Fuzzes the STL reader ([[walls]] type = "mesh"): any bytes must give a validated mesh or an
// StlError; a mesh that passes is built into a MeshSurface and queried around its vertices (the
// contact resolution must not crash on any valid mesh).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/geometry/mesh_surface.hpp"
#include "comminute/geometry/stl_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace comminute;
  IndexedMesh m;
  try {
    m = weld(parse_stl(std::string(reinterpret_cast<const char*>(data), size)));
    validate_mesh(m);
  } catch (const StlError&) {
    return 0;
  }
  const MeshSurface surface(m.vertices, m.triangles);
  std::vector<WallContact> out;
  for (const Vec3& v : m.vertices) {
    const double r = 0.1 * (1 + std::abs(v.x));
    for (const double margin : {0.0, 0.05 * r}) {
      out.clear();
      surface.contacts(v + Vec3{0.3 * r, -0.2 * r, 0.5 * r}, r, margin, out);
      for (const auto& c : out) (void)surface.adjacent(c.feature, out.front().feature);
    }
  }
  return 0;
}
