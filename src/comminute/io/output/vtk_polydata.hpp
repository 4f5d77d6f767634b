#pragma once
// A VTK XML PolyData (.vtp) file with all arrays in one raw appended block (header_type UInt64),
// the layout VTK's vtkXMLPolyDataReader and ParaView read natively. The caller describes arrays
// (name, type, components, bytes); write() emits the XML header and the binary block through
// AtomicFile, so a killed run never leaves a truncated .vtp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute::io {

struct VtkArray {
  std::string name;
  std::string type;  // VTK type name: Float64, Int64, UInt64, UInt32, UInt16, Int32, String
  int components = 1;
  std::vector<std::uint8_t> bytes;  // raw values, host byte order (String: NUL-terminated)
  std::size_t tuples = 0;           // number of tuples (String: number of strings)
};

// Builders that copy a typed array into a VtkArray.
VtkArray vtk_array(std::string name, std::span<const double> v);
VtkArray vtk_array(std::string name, std::span<const Vec3> v);
VtkArray vtk_array(std::string name, std::span<const std::uint64_t> v);
VtkArray vtk_array(std::string name, std::span<const std::uint16_t> v);
VtkArray vtk_array(std::string name, std::span<const std::int32_t> v);
VtkArray vtk_string_array(std::string name, const std::vector<std::string>& v);

struct VtkPolyData {
  std::vector<Vec3> points;                             // m
  bool vertex_per_point = false;                        // one vertex cell per point (particles)
  std::vector<std::array<std::uint32_t, 2>> lines;      // line cells (force chains)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // polygon cells (wall surfaces)
  std::vector<VtkArray> point_data, cell_data, field_data;
};

// Writes `pd` to `path` atomically (.part then rename). Throws Error on I/O failure.
void write_vtp(const std::filesystem::path& path, const VtkPolyData& pd);

// A structured grid (.vts, ParaView): `cells` cells per direction, the points of the
// (cells+1) lattice with the first index fastest, cell data in the same order.
struct VtkStructuredGrid {
  std::array<std::size_t, 3> cells{};
  std::vector<Vec3> points;  // m
  std::vector<VtkArray> cell_data, field_data;
};
void write_vts(const std::filesystem::path& path, const VtkStructuredGrid& g);

}  // namespace comminute::io
