#include "comminute/geometry/generated_mesh.hpp"

#include <filesystem>

#include "comminute/geometry/ball_mill.hpp"

namespace comminute {

void write_stl_if_asked(const CaseTable& t, const IndexedMesh& m) {
  if (!t.has("stl_file")) return;
  const std::filesystem::path file = t.file_path("stl_file");
  try {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    write_stl(file, m);
  } catch (const std::exception& e) {
    t.fail("stl_file", e.what());
  }
}

}  // namespace comminute
