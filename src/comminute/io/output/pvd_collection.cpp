#include "comminute/io/output/pvd_collection.hpp"

#include <fmt/format.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

void PvdCollection::resume(double t_end) {
  entries_.clear();
  std::ifstream in(path_);
  if (!in) return;  // no collection yet: the series starts afresh
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  if (s.find("type=\"Collection\"") == std::string::npos)
    throw Error(fmt::format("'{}' is not a ParaView collection; cannot resume it", path_.string()));
  // Our own writer's format: one DataSet element per line (see write()).
  static const std::regex dataset(R"re(<DataSet timestep="([^"]*)"[^>]* file="([^"]*)"\s*/>)re");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset); it != std::sregex_iterator();
       ++it) {
    const double t = std::stod((*it)[1].str());
    if (t <= t_end) entries_.push_back({t, (*it)[2].str()});
  }
  write();
}

void PvdCollection::clear() {
  entries_.clear();
  std::filesystem::remove(path_);
}

void PvdCollection::add(double time, const std::string& file) {
  entries_.push_back({time, file});
  write();
}

void PvdCollection::write() const {
  AtomicFile f(path_);
  auto& os = f.stream();
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<Collection>\n";
  // Times with 17 significant digits: the exact double, so a restart compares them exactly.
  for (const auto& e : entries_)
    os << fmt::format(R"(<DataSet timestep="{:.17g}" group="" part="0" file="{}"/>)", e.time,
                      e.file)
       << '\n';
  os << "</Collection>\n</VTKFile>\n";
  f.commit();
}

}  // namespace comminute::io
