#pragma once
// Triangle meshes for the mesh-wall tests: a tiled square, a closed box, and STL writers.
#include <cstring>
#include <fstream>
#include <map>
#include <string>

#include "comminute/geometry/mesh_wall.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute::testing {

// The square [x0, x0 + n h] x [y0, y0 + n h] at height z, n x n cells of two triangles each,
// normals +z.
inline IndexedMesh tiled_square(int n, double h, double x0 = 0, double y0 = 0, double z = 0) {
  IndexedMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.push_back({x0 + i * h, y0 + j * h, z});
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// Every edge used by exactly two triangles, once in each direction: closed and consistently
// oriented (a 2-manifold surface).
inline bool closed(const IndexedMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[static_cast<std::size_t>(k)], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges)
    if (n != 1 || edges.count({e.second, e.first}) != 1) return false;
  return true;
}

inline std::unique_ptr<MeshWall> mesh_wall(const IndexedMesh& m,
                                           std::unique_ptr<MotionModel> motion = nullptr,
                                           ArchardWear wear = {}) {
  return std::make_unique<MeshWall>(MeshSurface(m.vertices, m.triangles), std::move(motion), wear);
}

inline void write_ascii_stl(const std::string& path, const IndexedMesh& m) {
  std::ofstream f(path);
  f.precision(17);
  f << "solid test\n";
  for (const auto& t : m.triangles) {
    f << "  facet normal 0 0 0\n    outer loop\n";
    for (auto v : t)
      f << "      vertex " << m.vertices[v].x << " " << m.vertices[v].y << " " << m.vertices[v].z
        << "\n";
    f << "    endloop\n  endfacet\n";
  }
  f << "endsolid test\n";
}

inline std::string binary_stl(const IndexedMesh& m) {
  std::string b(80, ' ');
  const auto n = static_cast<std::uint32_t>(m.triangles.size());
  b.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.triangles) {
    float rec[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) rec[3 + 3 * k + a] = static_cast<float>(m.vertices[t[k]][a]);
    b.append(reinterpret_cast<const char*>(rec), 48);
    b.append(2, '\0');
  }
  return b;
}

}  // namespace comminute::testing
