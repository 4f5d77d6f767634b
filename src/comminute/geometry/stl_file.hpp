#pragma once
// STL triangle files, ASCII or binary (told apart by the binary size rule: 84 + 50 n bytes for the
// n triangles its header counts), welded into an indexed mesh (vertices with bit-identical
// coordinates merged) and validated. Every refusal is an StlError naming the triangle index
// (counting from 0, in file order) and, for ASCII files, the line.
//
// Refused (errors): a file that is neither STL form or ends early (truncated), a vertex coordinate
// that is NaN or infinite, a zero-area triangle (area <= 1e-12 of its longest edge squared, which
// includes two equal vertices), a non-manifold edge (shared by more than two triangles), and two
// triangles that run along a shared edge in the same direction (inconsistent orientation).
// Accepted: open surfaces (edges used by one triangle).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "comminute/core/error.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

struct IndexedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

class StlError : public Error {
 public:
  // triangle: index in file order (-1: the file as a whole); line: ASCII line (0: none).
  StlError(long triangle, long line, const std::string& message);
  long triangle() const { return triangle_; }
  long line() const { return line_; }

 private:
  long triangle_, line_;
};

// Parses STL bytes (ASCII or binary) into one Vec3 per triangle corner (3 per triangle).
std::vector<Vec3> parse_stl(const std::string& bytes);
// Merges corners with identical coordinates into shared vertices.
IndexedMesh weld(const std::vector<Vec3>& corners);
// Throws StlError for a zero-area triangle, a non-manifold edge or inconsistent orientation.
void validate_mesh(const IndexedMesh& mesh);
// Reads, welds and validates a file; errors carry the file name in their message.
IndexedMesh read_stl(const std::filesystem::path& file);

}  // namespace comminute
