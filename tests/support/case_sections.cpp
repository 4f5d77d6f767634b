#include "case_sections.hpp"

#include <fmt/format.h>

#include <fstream>

#include "comminute/core/rng.hpp"
#include "comminute/io/case/bonds_case.hpp"

namespace comminute::testing {

std::string toml_number(double x) {
  std::string s = fmt::format("{}", x);  // shortest text that reads back to x
  if (s.find_first_of(".eni") == std::string::npos) s += ".0";
  return s;
}

std::string dem_sections(const RunKeys& run, const SolidKeys& solid) {
  std::string s =
      fmt::format("[simulation]\nseed = {}\nend_time = {}\n", run.seed, toml_number(run.end_time));
  if (run.time_step > 0) s += fmt::format("time_step = {}\n", toml_number(run.time_step));
  if (run.skin > 0) s += fmt::format("skin = {}\n", toml_number(run.skin));
  s += fmt::format(
      "[contact]\nmodel = \"hertz_mindlin\"\n[materials.{}]\ndensity = {}\nyoungs_modulus = {}\n"
      "poisson_ratio = {}\n[interaction]\nrestitution = {}\nfriction = {}\n",
      solid.name, toml_number(solid.density), toml_number(solid.youngs_modulus),
      toml_number(solid.poisson_ratio), toml_number(solid.restitution),
      toml_number(solid.friction));
  return s;
}

std::string plane_wall(std::string_view name, double z, double normal_z, std::string_view material,
                       std::string_view motion) {
  std::string s = fmt::format(
      "[[walls]]\nname = \"{}\"\ntype = \"plane\"\npoint = [0.0, 0.0, {}]\nnormal = [0.0, 0.0, "
      "{}]\nmaterial = \"{}\"\n",
      name, toml_number(z), toml_number(normal_z), material);
  if (!motion.empty()) s += fmt::format("{}\n", motion);
  return s;
}

std::string velocity_z(double v) {
  return fmt::format("velocity = [0.0, 0.0, {}]", toml_number(v));
}

std::string data_file_insert(std::string_view material, std::string_view file) {
  return fmt::format("[[insert]]\ntype = \"data_file\"\nmaterial = \"{}\"\nfile = \"{}\"\n",
                     material, file);
}

std::string parallel_bond_section(const ParallelBondKeys& b) {
  std::string s = fmt::format(
      "[bonds]\nlaw = \"parallel_bond\"\ngap_tolerance = {}\nnormal_stiffness = {}\n"
      "shear_stiffness = {}\ntensile_strength = {}\nshear_strength = {}\n",
      toml_number(b.gap_tolerance), toml_number(b.normal_stiffness), toml_number(b.shear_stiffness),
      toml_number(b.tensile_strength), toml_number(b.shear_strength));
  if (b.strength_sd > 0)
    s += fmt::format("tensile_strength_sd = {0}\nshear_strength_sd = {0}\n",
                     toml_number(b.strength_sd));
  if (b.within_grain) s += "within_grain = true\n";
  return s;
}

std::string grain_pour_insert(const GrainPourKeys& k) {
  std::string s = fmt::format(
      "[[insert]]\ntype = \"clusters\"\nmode = \"{}\"\nmaterial = \"{}\"\nshape = \"ellipsoid\"\n"
      "length = {}\nwidth = {}\nthickness = {}\nspheres_per_grain = {}\ntemplates = {}\n"
      "interval = {}\n",
      k.mode, k.material, toml_number(k.length), toml_number(k.width), toml_number(k.thickness),
      k.spheres_per_grain, k.templates, toml_number(k.interval));
  if (k.rate > 0) s += fmt::format("rate = {}\n", toml_number(k.rate));
  auto point = [](const std::array<double, 3>& x) {
    return fmt::format("[{}, {}, {}]", toml_number(x[0]), toml_number(x[1]), toml_number(x[2]));
  };
  s += fmt::format("region = {{ shape = \"box\", lo = {}, hi = {} }}\n", point(k.lo), point(k.hi));
  if (!k.extra.empty()) s += k.extra + "\n";
  return s;
}

std::string calibration_parameter(std::string_view key, double min, double max) {
  return fmt::format("[[calibration.parameter]]\nkey = \"{}\"\nmin = {}\nmax = {}\n", key,
                     toml_number(min), toml_number(max));
}

void write_sphere_lattice(const std::filesystem::path& file, int side, double radius,
                          double density, double max_speed, std::uint64_t seed) {
  std::ofstream d(file);
  d << "# simple cubic lattice of touching spheres\n\n"
    << side * side * side << " atoms\n1 atom types\n\nAtoms # sphere\n\n";
  long id = 1;
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i)
        d << id++ << " 1 " << 2 * radius << ' ' << density << ' ' << radius * (2 * i + 1) << ' '
          << radius * (2 * j + 1) << ' ' << radius * (2 * k + 1) << '\n';
  if (!(max_speed > 0)) return;
  d << "\nVelocities\n\n";
  Rng rng(seed);
  for (long n = 1; n < id; ++n)
    d << n << ' ' << rng.uniform(-max_speed, max_speed) << ' ' << rng.uniform(-max_speed, max_speed)
      << ' ' << rng.uniform(-max_speed, max_speed) << " 0 0 0\n";
}

std::string lattice_bed_case(const LatticeBedKeys& bed, std::string_view data_file) {
  const double l = 2 * kLatticeRadius * bed.side;  // m, the lattice's edge
  std::string s = dem_sections({1, 1.0, 2e-6, 2e-4}, {"rock", 2500.0, 5.0e7, 0.3, 0.5, 0.5}) +
                  fmt::format(
                      "[[walls]]\nname = \"bin\"\ntype = \"box\"\nlo = [0.0, 0.0, 0.0]\n"
                      "hi = [{0}, {0}, {1}]\nopen = [\"+z\"]\nmaterial = \"rock\"\n",
                      toml_number(l), toml_number(bed.box_height)) +
                  plane_wall("piston", l, -1.0, "rock", velocity_z(-bed.piston_speed)) +
                  data_file_insert("rock", data_file);
  if (bed.bonds) s += parallel_bond_section(*bed.bonds);
  return s;
}

LoadedCase load_case(const std::filesystem::path& file) {
  const CaseFile f = CaseFile::load(file);
  LoadedCase c{io::build_dem_case(f.root()), nullptr};
  c.bonds = io::add_bonds(f.root(), c.dem);
  io::decide_time_step(c.dem);
  f.reject_unknown();
  return c;
}

}  // namespace comminute::testing
