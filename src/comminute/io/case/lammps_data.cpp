#include "comminute/io/case/lammps_data.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <unordered_map>

#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {
bool finite_all(std::initializer_list<double> v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
}  // namespace

std::vector<ParticleInit> read_lammps_data(const std::filesystem::path& file,
                                           const std::string& key) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), key, 0, "no such data file");
  if (std::filesystem::is_directory(file))
    throw InputError(file.string(), key, 0, "is a directory, not a data file");
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), key, 0, "cannot open the data file");
  std::vector<ParticleInit> out;
  std::unordered_map<long, std::size_t> by_id;
  std::string line, section;
  long lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream s(line);
    std::string first;
    if (!(s >> first)) continue;
    if (first == "Atoms" || first == "Velocities") {
      section = first;
      continue;
    }
    if (section.empty()) continue;  // header lines
    if (!std::isdigit(static_cast<unsigned char>(first[0]))) {
      section.clear();  // another section we do not read
      continue;
    }
    long id = 0;
    const auto r = std::from_chars(first.data(), first.data() + first.size(), id);
    if (r.ec != std::errc() || r.ptr != first.data() + first.size() || id < 1)
      throw InputError(file.string(), key, lineno,
                       fmt::format("atom id '{}' is not a positive integer in range", first));
    if (section == "Atoms") {
      int type;
      double d, rho;
      ParticleInit p;
      if (!(s >> type >> d >> rho >> p.x.x >> p.x.y >> p.x.z) || !(d > 0) || !(rho > 0) ||
          !finite_all({d, rho, p.x.x, p.x.y, p.x.z}))
        throw InputError(file.string(), key, lineno,
                         "expected 'id type diameter density x y z' with diameter, density > 0, "
                         "all finite");
      p.radius = 0.5 * d;
      p.density = rho;
      if (!by_id.emplace(id, out.size()).second)
        throw InputError(file.string(), key, lineno, fmt::format("atom id {} appears twice", id));
      out.push_back(p);
    } else {
      auto it = by_id.find(id);
      if (it == by_id.end())
        throw InputError(file.string(), key, lineno,
                         fmt::format("velocity for unknown atom {}", id));
      ParticleInit& p = out[it->second];
      if (!(s >> p.v.x >> p.v.y >> p.v.z >> p.w.x >> p.w.y >> p.w.z) ||
          !finite_all({p.v.x, p.v.y, p.v.z, p.w.x, p.w.y, p.w.z}))
        throw InputError(file.string(), key, lineno, "expected 'id vx vy vz wx wy wz', all finite");
    }
  }
  if (out.empty()) throw InputError(file.string(), key, 0, "no Atoms section with particles found");
  return out;
}

}  // namespace comminute::io
