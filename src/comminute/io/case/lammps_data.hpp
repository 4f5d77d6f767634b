#pragma once
// Reads spheres from a LAMMPS-style granular data file ("Atoms" lines `id type diameter density
// x y z`, optional "Velocities" lines `id vx vy vz wx wy wz`), the format LIGGGHTS and LAMMPS read
// (atom_style sphere), used by the benchmarks to give every code the same initial state.
#include <filesystem>
#include <string>
#include <vector>

#include "comminute/particles/particle_store.hpp"

namespace comminute::io {

// `key`: the case key that named the file (for messages).
std::vector<ParticleInit> read_lammps_data(const std::filesystem::path& file,
                                           const std::string& key = "");

}  // namespace comminute::io
