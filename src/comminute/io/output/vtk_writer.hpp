#pragma once
// Particle and wall snapshots for ParaView: one .vtp per snapshot and one .pvd collection per
// series, laid out as
//   <dir>/particles.pvd   <dir>/particles/particles_<step>.vtp
//   <dir>/walls.pvd       <dir>/walls/walls_<step>.vtp
// Particle point data: id, radius [m], diameter [m], mass [kg], velocity [m/s],
// angular_velocity [rad/s], force [N], material [-], then the store's named fields (all of them,
// or the selected ones). Wall files hold every wall's triangulated surface with cell data
// wall_index, force [N], torque [N m] (of the wall the cell belongs to), wear_depth [m] (Archard
// wear of mesh triangles; written when a mesh wall is present, 0 on other walls) and field data
// wall_name, wall_force, wall_torque (one tuple per wall) and TimeValue [s].
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "comminute/geometry/wall.hpp"
#include "comminute/io/output/pvd_collection.hpp"
#include "comminute/io/output/vtk_polydata.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::io {

// Builds the particle polydata (points at particle centres, one vertex cell each).
// `fields`: names of the store's per-particle fields to include; nullopt = all of them.
// Throws Error for an unknown field name. Under coarse graining (`coarse_scale` k > 1) the
// diameter of the primary particles a particle stands for, d/k, is added as `primary_diameter`.
VtkPolyData particle_polydata(const ParticleStore& p, double time,
                              const std::optional<std::vector<std::string>>& fields,
                              double coarse_scale = 1.0);
// Builds the wall polydata; `extent` (m) bounds infinite walls (see Wall::surface).
VtkPolyData wall_polydata(const std::vector<std::unique_ptr<Wall>>& walls, double time,
                          double extent);

class VtkWriter {
 public:
  // Fresh series: an existing collection in `dir` is replaced and stale snapshot files of the
  // two series are removed. Call resume() instead to continue a series after a restart.
  VtkWriter(std::filesystem::path dir, std::optional<std::vector<std::string>> fields);
  // Keeps the snapshots with time <= t (the checkpoint's time) in both collections.
  void resume(double t);
  void start_fresh();

  void write_particles(const ParticleStore& p, double time, std::uint64_t step,
                       double coarse_scale = 1.0);
  void write_walls(const std::vector<std::unique_ptr<Wall>>& walls, double time, std::uint64_t step,
                   double extent);

  const PvdCollection& particles_collection() const { return particles_; }
  const PvdCollection& walls_collection() const { return walls_; }

 private:
  std::filesystem::path dir_;
  std::optional<std::vector<std::string>> fields_;
  PvdCollection particles_, walls_;
};

}  // namespace comminute::io
