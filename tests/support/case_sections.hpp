#pragma once
// Case-file text (TOML) and data files that the tests and the benchmarks build their cases from:
// the [simulation], [contact], material and [interaction] tables of a one-material DEM case,
// plane walls, a data-file insertion, a pour of grain templates, a parallel-bond table, a simple
// cubic lattice of touching spheres and the bonded bed pressed by a piston on it. Numbers are
// written so that they read back to the same double.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "comminute/bonds/bonds_module.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::testing {

// A number as TOML text that reads back to the same double (always a float literal).
std::string toml_number(double x);

// [simulation]: keys left at 0 are left out (the engine decides: time step, skin).
struct RunKeys {
  std::uint64_t seed = 1;
  double end_time = 1.0;  // s
  double time_step = 0;   // s
  double skin = 0;        // m
};

// One material, Hertz–Mindlin, and the [interaction] of its pairs.
struct SolidKeys {
  std::string name = "rock";
  double density = 2500;         // kg/m³
  double youngs_modulus = 1e10;  // Pa
  double poisson_ratio = 0.3;    // –
  double restitution = 0.3;      // –
  double friction = 0.0;         // –
};

// [simulation], [contact], [materials.<name>] and [interaction].
std::string dem_sections(const RunKeys& run, const SolidKeys& solid);

// A [[walls]] plane through (0, 0, z) with the normal (0, 0, normal_z); `motion` is one more line
// (its velocity or control, TOML) or empty for a fixed plane.
std::string plane_wall(std::string_view name, double z, double normal_z, std::string_view material,
                       std::string_view motion = {});

// A piston's constant velocity along z: the `motion` line of plane_wall.
std::string velocity_z(double v);

// [[insert]] of the spheres of a LAMMPS data file (relative to the case file).
std::string data_file_insert(std::string_view material, std::string_view file);

// [bonds] with the parallel bond law; the strengths' standard deviations are left out when 0.
struct ParallelBondKeys {
  double gap_tolerance = 1e-6;     // m
  double normal_stiffness = 1e10;  // Pa/m
  double shear_stiffness = 4e9;    // Pa/m
  double tensile_strength = 1e7;   // Pa
  double shear_strength = 1e7;     // Pa
  double strength_sd = 0;          // Pa, of both strengths
  bool within_grain = false;       // bond only sub-spheres of one grain (clusters)
};
std::string parallel_bond_section(const ParallelBondKeys& b);

// [[insert]] of ellipsoidal grain templates (type = "clusters") in a box region; `mode` "pour"
// places `rate` grains per second every `interval` (rate 0: left out); `extra` holds the table's
// other keys as TOML lines (the target: count or mass; start, end, layers, velocity, ...).
struct GrainPourKeys {
  std::string material = "rice";
  std::string mode = "pour";
  double length = 3.0e-3, width = 2.0e-3, thickness = 1.6e-3;  // m, the ellipsoid's axes
  int spheres_per_grain = 6;
  int templates = 2;
  double rate = 4000.0;                                               // grains/s
  double interval = 1e-3;                                             // s
  std::array<double, 3> lo{-0.01, -0.01, 0.0}, hi{0.01, 0.01, 0.01};  // m, the region
  std::string extra;
};
std::string grain_pour_insert(const GrainPourKeys& k);

// One [[calibration.parameter]]: a free case key and its bounds (in the key's unit).
std::string calibration_parameter(std::string_view key, double min, double max);

// A LAMMPS data file of side³ touching spheres of radius r on a simple cubic lattice (centres at
// r (2i + 1), 2r apart) of the given density; with max_speed > 0, random velocities uniform in
// ±max_speed per axis (Rng(seed)).
void write_sphere_lattice(const std::filesystem::path& file, int side, double radius,
                          double density, double max_speed = 0, std::uint64_t seed = 0);

// The lattice bed: the lattice (2 mm spheres, E = 50 MPa, e = 0.5, μ = 0.5, gravity on, dt = 2 µs)
// in a box bin open at the top, `box_height` high, pressed by a piston plane that starts on the
// lattice's top and moves down at `piston_speed`; with `bonds`, every touching pair bonded.
struct LatticeBedKeys {
  int side = 10;
  double box_height = 1.0;     // m
  double piston_speed = 0.01;  // m/s, downwards
  std::optional<ParallelBondKeys> bonds;
};
inline constexpr double kLatticeRadius = 1e-3;  // m
std::string lattice_bed_case(const LatticeBedKeys& bed, std::string_view data_file);

// A case read as `comminute run` reads it up to the set-up: the DEM case, its bonds (null without
// [bonds]) and the time step; unknown keys refused. Not set up.
struct LoadedCase {
  io::DemCase dem;
  const bonds::BondsModule* bonds = nullptr;
};
LoadedCase load_case(const std::filesystem::path& file);

}  // namespace comminute::testing
