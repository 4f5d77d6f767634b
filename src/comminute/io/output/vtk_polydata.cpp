#include "comminute/io/output/vtk_polydata.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {

template <class T>
VtkArray typed_array(std::string name, const char* type, int components, std::span<const T> v) {
  VtkArray a{std::move(name), type, components, {}, v.size()};
  a.bytes.resize(v.size_bytes());
  if (!v.empty()) std::memcpy(a.bytes.data(), v.data(), v.size_bytes());
  return a;
}

// Appended-data layout: each array is a UInt64 byte count followed by its bytes; `offset` is
// where that count starts, counted from the first byte after the '_' marker.
struct Appended {
  std::vector<const std::vector<std::uint8_t>*> blocks;
  std::uint64_t size = 0;
  std::uint64_t add(const std::vector<std::uint8_t>& b) {
    const std::uint64_t at = size;
    blocks.push_back(&b);
    size += sizeof(std::uint64_t) + b.size();
    return at;
  }
};

// String arrays go inline as ASCII character codes, each string ended by 0 (VTK's convention).
void write_string_array(std::ostream& os, const VtkArray& a) {
  os << fmt::format(R"(<DataArray type="String" Name="{}" NumberOfTuples="{}" format="ascii">)",
                    a.name, a.tuples);
  for (std::uint8_t c : a.bytes) os << ' ' << static_cast<unsigned>(c);
  os << "</DataArray>\n";
}

void write_arrays(std::ostream& os, const std::vector<VtkArray>& arrays, Appended& app,
                  bool with_tuples) {
  for (const auto& a : arrays) {
    if (a.type == "String") {
      write_string_array(os, a);
      continue;
    }
    os << fmt::format(R"(<DataArray type="{}" Name="{}" NumberOfComponents="{}" )", a.type, a.name,
                      a.components);
    if (with_tuples) os << fmt::format(R"(NumberOfTuples="{}" )", a.tuples);
    os << fmt::format(R"(format="appended" offset="{}"/>)", app.add(a.bytes)) << '\n';
  }
}

// The raw appended block (each array: its UInt64 byte count, then its bytes) and the file's end.
void write_appended(std::ostream& os, const Appended& app) {
  os << "<AppendedData encoding=\"raw\">\n_";
  for (const auto* b : app.blocks) {
    const std::uint64_t count = b->size();
    os.write(reinterpret_cast<const char*>(&count), sizeof count);
    if (!b->empty())
      os.write(reinterpret_cast<const char*>(b->data()), static_cast<std::streamsize>(b->size()));
  }
  os << "\n</AppendedData>\n</VTKFile>\n";
}

}  // namespace

VtkArray vtk_array(std::string name, std::span<const double> v) {
  return typed_array(std::move(name), "Float64", 1, v);
}
VtkArray vtk_array(std::string name, std::span<const Vec3> v) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return typed_array(std::move(name), "Float64", 3, v);
}
VtkArray vtk_array(std::string name, std::span<const std::uint64_t> v) {
  return typed_array(std::move(name), "UInt64", 1, v);
}
VtkArray vtk_array(std::string name, std::span<const std::uint16_t> v) {
  return typed_array(std::move(name), "UInt16", 1, v);
}
VtkArray vtk_array(std::string name, std::span<const std::int32_t> v) {
  return typed_array(std::move(name), "Int32", 1, v);
}
VtkArray vtk_string_array(std::string name, const std::vector<std::string>& v) {
  VtkArray a{std::move(name), "String", 1, {}, v.size()};
  for (const auto& s : v) {
    a.bytes.insert(a.bytes.end(), s.begin(), s.end());
    a.bytes.push_back(0);
  }
  return a;
}

void write_vtp(const std::filesystem::path& path, const VtkPolyData& pd) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  const std::size_t n = pd.points.size();
  const std::size_t verts = pd.vertex_per_point ? n : 0;
  const std::size_t polys = pd.triangles.size();
  const std::size_t lines = pd.lines.size();

  // Connectivity and offsets of the vertex and triangle cells (Int64, as VTK 9 writes them).
  std::vector<std::int64_t> vconn(verts), voff(verts), pconn(3 * polys), poff(polys),
      lconn(2 * lines), loff(lines);
  for (std::size_t c = 0; c < lines; ++c) {
    for (int k = 0; k < 2; ++k) lconn[2 * c + k] = pd.lines[c][k];
    loff[c] = static_cast<std::int64_t>(2 * (c + 1));
  }
  for (std::size_t i = 0; i < verts; ++i) {
    vconn[i] = static_cast<std::int64_t>(i);
    voff[i] = static_cast<std::int64_t>(i + 1);
  }
  for (std::size_t c = 0; c < polys; ++c) {
    for (int k = 0; k < 3; ++k) pconn[3 * c + k] = pd.triangles[c][k];
    poff[c] = static_cast<std::int64_t>(3 * (c + 1));
  }
  auto as_bytes = [](const std::vector<std::int64_t>& v) {
    std::vector<std::uint8_t> b(v.size() * sizeof(std::int64_t));
    if (!v.empty()) std::memcpy(b.data(), v.data(), b.size());
    return b;
  };
  const std::vector<VtkArray> points{vtk_array("Points", std::span<const Vec3>(pd.points))};
  const std::vector<std::uint8_t> vconn_b = as_bytes(vconn), voff_b = as_bytes(voff),
                                  pconn_b = as_bytes(pconn), poff_b = as_bytes(poff),
                                  lconn_b = as_bytes(lconn), loff_b = as_bytes(loff);

  AtomicFile file(path, std::ios::binary);
  std::ostream& os = file.stream();
  Appended app;
  os << "<?xml version=\"1.0\"?>\n"
     << fmt::format(R"(<VTKFile type="PolyData" version="1.0" byte_order="{}" )", order)
     << "header_type=\"UInt64\">\n<PolyData>\n";
  if (!pd.field_data.empty()) {
    os << "<FieldData>\n";
    write_arrays(os, pd.field_data, app, true);
    os << "</FieldData>\n";
  }
  os << fmt::format(
            R"(<Piece NumberOfPoints="{}" NumberOfVerts="{}" NumberOfLines="{}" NumberOfStrips="0" )"
            R"(NumberOfPolys="{}">)",
            n, verts, lines, polys)
     << '\n';
  os << "<PointData>\n";
  write_arrays(os, pd.point_data, app, false);
  os << "</PointData>\n<CellData>\n";
  write_arrays(os, pd.cell_data, app, false);
  os << "</CellData>\n<Points>\n";
  write_arrays(os, points, app, false);
  os << "</Points>\n";
  auto cells = [&](const char* tag, const std::vector<std::uint8_t>& conn,
                   const std::vector<std::uint8_t>& off) {
    os << '<' << tag << ">\n"
       << fmt::format(
              R"(<DataArray type="Int64" Name="connectivity" format="appended" offset="{}"/>)",
              app.add(conn))
       << '\n'
       << fmt::format(R"(<DataArray type="Int64" Name="offsets" format="appended" offset="{}"/>)",
                      app.add(off))
       << "\n</" << tag << ">\n";
  };
  cells("Verts", vconn_b, voff_b);
  cells("Lines", lconn_b, loff_b);
  cells("Polys", pconn_b, poff_b);
  os << "</Piece>\n</PolyData>\n";
  write_appended(os, app);
  file.commit();
}

void write_vts(const std::filesystem::path& path, const VtkStructuredGrid& g) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  const auto [nx, ny, nz] = g.cells;
  if (g.points.size() != (nx + 1) * (ny + 1) * (nz + 1))
    throw Error("structured grid: the point count does not match the cells");
  const std::vector<VtkArray> points{vtk_array("Points", std::span<const Vec3>(g.points))};
  AtomicFile file(path, std::ios::binary);
  std::ostream& os = file.stream();
  Appended app;
  const std::string extent = fmt::format("0 {} 0 {} 0 {}", nx, ny, nz);
  os << "<?xml version=\"1.0\"?>\n"
     << fmt::format(R"(<VTKFile type="StructuredGrid" version="1.0" byte_order="{}" )", order)
     << "header_type=\"UInt64\">\n"
     << fmt::format(R"(<StructuredGrid WholeExtent="{}">)", extent) << '\n';
  if (!g.field_data.empty()) {
    os << "<FieldData>\n";
    write_arrays(os, g.field_data, app, true);
    os << "</FieldData>\n";
  }
  os << fmt::format(R"(<Piece Extent="{}">)", extent) << "\n<CellData>\n";
  write_arrays(os, g.cell_data, app, false);
  os << "</CellData>\n<Points>\n";
  write_arrays(os, points, app, false);
  os << "</Points>\n</Piece>\n</StructuredGrid>\n";
  write_appended(os, app);
  file.commit();
}

}  // namespace comminute::io
