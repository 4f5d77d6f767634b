#include "comminute/io/output/dataset_writer.hpp"

#include "comminute/core/error.hpp"
#include "comminute/io/output/vtk_polydata.hpp"

namespace comminute::io {

namespace {
std::vector<VtkArray> cell_arrays(const Dataset& d, std::size_t cells) {
  std::vector<VtkArray> out;
  for (const auto& a : d.cell_data) {
    if (a.values.size() != cells * static_cast<std::size_t>(a.components))
      throw Error("dataset " + d.name + ": array " + a.name + " does not match the cell count");
    VtkArray v = vtk_array(a.name, std::span<const double>(a.values));
    v.components = a.components;
    v.tuples = cells;
    out.push_back(std::move(v));
  }
  return out;
}
}  // namespace

void write_dataset(const std::filesystem::path& directory, const Dataset& d, double time) {
  const std::vector<double> t{time};
  const std::filesystem::path stem = directory / d.name;
  if (stem.has_parent_path()) std::filesystem::create_directories(stem.parent_path());
  if (d.structured()) {
    VtkStructuredGrid g;
    g.cells = d.cells;
    g.points = d.points;
    g.cell_data = cell_arrays(d, d.cells[0] * d.cells[1] * d.cells[2]);
    g.field_data.push_back(vtk_array("TimeValue", std::span<const double>(t)));
    write_vts(stem.string() + ".vts", g);
    return;
  }
  VtkPolyData pd;
  pd.points = d.points;
  pd.lines = d.lines;
  pd.cell_data = cell_arrays(d, d.lines.size());
  pd.field_data.push_back(vtk_array("TimeValue", std::span<const double>(t)));
  write_vtp(stem.string() + ".vtp", pd);
}

}  // namespace comminute::io
