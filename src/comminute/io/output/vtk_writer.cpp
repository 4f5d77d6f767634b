#include "comminute/io/output/vtk_writer.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {
std::string snapshot_name(const char* series, std::uint64_t step) {
  return fmt::format("{0}/{0}_{1:010d}.vtp", series, step);
}
}  // namespace

VtkPolyData particle_polydata(const ParticleStore& p, double time,
                              const std::optional<std::vector<std::string>>& fields,
                              double coarse_scale) {
  VtkPolyData pd;
  pd.points = p.x;
  pd.vertex_per_point = true;
  std::vector<double> diameter(p.size()), mass(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    diameter[i] = 2 * p.radius[i];
    mass[i] = p.physical_mass(i);  // the real mass (docs/models.md, density scaling)
  }
  auto& a = pd.point_data;
  a.push_back(vtk_array("id", std::span<const std::uint64_t>(p.id)));
  a.push_back(vtk_array("radius", std::span<const double>(p.radius)));
  a.push_back(vtk_array("diameter", std::span<const double>(diameter)));
  if (coarse_scale != 1.0) {
    std::vector<double> primary(diameter);
    for (double& d : primary) d /= coarse_scale;  // docs/models.md, "Coarse graining"
    a.push_back(vtk_array("primary_diameter", std::span<const double>(primary)));
  }
  a.push_back(vtk_array("mass", std::span<const double>(mass)));
  a.push_back(vtk_array("velocity", std::span<const Vec3>(p.v)));
  a.push_back(vtk_array("angular_velocity", std::span<const Vec3>(p.w)));
  a.push_back(vtk_array("force", std::span<const Vec3>(p.f)));
  a.push_back(vtk_array("material", std::span<const std::uint16_t>(p.material)));
  const std::vector<std::string>& names = fields ? *fields : p.field_names();
  for (const auto& name : names) {
    if (!p.has_field(name))
      throw Error(fmt::format("output field '{}' is not a particle field (known: {})", name,
                              fmt::join(p.field_names(), ", ")));
    a.push_back(vtk_array(name, std::span<const double>(p.field(p.field_index(name)))));
  }
  const double t[] = {time};
  pd.field_data.push_back(vtk_array("TimeValue", std::span<const double>(t)));
  return pd;
}

VtkPolyData wall_polydata(const std::vector<std::unique_ptr<Wall>>& walls, double time,
                          double extent) {
  VtkPolyData pd;
  std::vector<std::int32_t> wall_index;
  std::vector<Vec3> cell_force, cell_torque, force, torque;
  std::vector<std::string> names;
  std::vector<double> wear;  // per cell, m (written when a wall tracks wear per triangle)
  bool any_wear = false;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const Wall& w = *walls[k];
    const SurfaceMesh m = w.surface(extent);
    any_wear = any_wear || !m.wear_depth.empty();
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      wear.push_back(t < m.wear_depth.size() ? m.wear_depth[t] : 0.0);
    const auto base = static_cast<std::uint32_t>(pd.points.size());
    pd.points.insert(pd.points.end(), m.vertices.begin(), m.vertices.end());
    for (const auto& tri : m.triangles) {
      pd.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
      wall_index.push_back(static_cast<std::int32_t>(k));
      cell_force.push_back(w.force);
      cell_torque.push_back(w.torque);
    }
    names.push_back(w.name);
    force.push_back(w.force);
    torque.push_back(w.torque);
  }
  pd.cell_data.push_back(vtk_array("wall_index", std::span<const std::int32_t>(wall_index)));
  pd.cell_data.push_back(vtk_array("force", std::span<const Vec3>(cell_force)));
  pd.cell_data.push_back(vtk_array("torque", std::span<const Vec3>(cell_torque)));
  if (any_wear) pd.cell_data.push_back(vtk_array("wear_depth", std::span<const double>(wear)));
  const double t[] = {time};
  pd.field_data.push_back(vtk_array("TimeValue", std::span<const double>(t)));
  pd.field_data.push_back(vtk_string_array("wall_name", names));
  pd.field_data.push_back(vtk_array("wall_force", std::span<const Vec3>(force)));
  pd.field_data.push_back(vtk_array("wall_torque", std::span<const Vec3>(torque)));
  return pd;
}

VtkWriter::VtkWriter(std::filesystem::path dir, std::optional<std::vector<std::string>> fields)
    : dir_(std::move(dir)),
      fields_(std::move(fields)),
      particles_(dir_ / "particles.pvd"),
      walls_(dir_ / "walls.pvd") {}

void VtkWriter::start_fresh() {
  particles_.clear();
  walls_.clear();
  for (const char* series : {"particles", "walls"}) {
    const auto sub = dir_ / series;
    if (!std::filesystem::is_directory(sub)) continue;
    // Only our own snapshot files: anything else the user put there stays.
    const std::string prefix = std::string(series) + "_";
    for (const auto& e : std::filesystem::directory_iterator(sub)) {
      const std::string n = e.path().filename().string();
      if (n.starts_with(prefix) && e.path().extension() == ".vtp") std::filesystem::remove(e);
    }
  }
}

void VtkWriter::resume(double t) {
  particles_.resume(t);
  walls_.resume(t);
}

void VtkWriter::write_particles(const ParticleStore& p, double time, std::uint64_t step,
                                double coarse_scale) {
  const std::string name = snapshot_name("particles", step);
  write_vtp(dir_ / name, particle_polydata(p, time, fields_, coarse_scale));
  particles_.add(time, name);
}

void VtkWriter::write_walls(const std::vector<std::unique_ptr<Wall>>& walls, double time,
                            std::uint64_t step, double extent) {
  const std::string name = snapshot_name("walls", step);
  write_vtp(dir_ / name, wall_polydata(walls, time, extent));
  walls_.add(time, name);
}

}  // namespace comminute::io
