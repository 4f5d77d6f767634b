#include "comminute/io/case/lammps_data.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <unordered_map>

#include "comminute/core/error.hpp"

namespace comminute::io {

std::vector<ParticleInit> read_lammps_data(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "", 0, "cannot open the data file");
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
    const long id = std::stol(first);
    if (section == "Atoms") {
      int type;
      double d, rho;
      ParticleInit p;
      if (!(s >> type >> d >> rho >> p.x.x >> p.x.y >> p.x.z) || !(d > 0) || !(rho > 0))
        throw InputError(file.string(), "", lineno,
                         "expected 'id type diameter density x y z' with diameter, density > 0");
      p.radius = 0.5 * d;
      p.density = rho;
      by_id[id] = out.size();
      out.push_back(p);
    } else {
      auto it = by_id.find(id);
      if (it == by_id.end())
        throw InputError(file.string(), "", lineno,
                         fmt::format("velocity for unknown atom {}", id));
      ParticleInit& p = out[it->second];
      if (!(s >> p.v.x >> p.v.y >> p.v.z >> p.w.x >> p.w.y >> p.w.z))
        throw InputError(file.string(), "", lineno, "expected 'id vx vy vz wx wy wz'");
    }
  }
  if (out.empty()) throw InputError(file.string(), "", 0, "no Atoms section with particles found");
  return out;
}

}  // namespace comminute::io
