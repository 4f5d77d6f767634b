#include "comminute/io/output/timeseries_csv.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <set>
#include <sstream>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

TimeSeriesWriter::TimeSeriesWriter(std::filesystem::path path, std::vector<std::string> wall_names)
    : path_(std::move(path)), wall_names_(std::move(wall_names)) {
  std::set<std::string> seen;
  for (const auto& n : wall_names_) {
    if (n.empty() || n.find_first_of(",\"\r\n") != std::string::npos)
      throw Error(
          fmt::format("wall name '{}' cannot name a CSV column (empty, or holds a comma, "
                      "quote or line break)",
                      n));
    if (!seen.insert(n).second)
      throw Error(fmt::format("two walls are named '{}'; names must differ", n));
  }
}

std::vector<std::string> TimeSeriesWriter::columns(const std::vector<std::string>& wall_names) {
  std::vector<std::string> c = {"time [s]",
                                "step [-]",
                                "particles [-]",
                                "contacts [-]",
                                "wall_contacts [-]",
                                "kinetic_translational [J]",
                                "kinetic_rotational [J]",
                                "potential_gravity [J]",
                                "elastic [J]",
                                "dissipated_damping [J]",
                                "dissipated_friction [J]",
                                "energy_removed [J]",
                                "wall_work [J]",
                                "energy_balance [J]"};
  for (const auto& w : wall_names) {
    for (const char* a : {"Fx [N]", "Fy [N]", "Fz [N]"}) c.push_back(w + "_" + a);
    for (const char* a : {"Tx [N m]", "Ty [N m]", "Tz [N m]"}) c.push_back(w + "_" + a);
  }
  return c;
}

std::string TimeSeriesWriter::header() const {
  return fmt::format("{}", fmt::join(columns(wall_names_), ","));
}

void TimeSeriesWriter::start_fresh() {
  AtomicFile f(path_);
  f.stream() << header() << '\n';
  f.commit();
  open_for_append();
}

void TimeSeriesWriter::resume(double t) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) {
    start_fresh();
    return;
  }
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  const std::string s = text.str();
  std::size_t eol = s.find('\n');
  if (eol == std::string::npos || s.substr(0, eol) != header())
    throw Error(
        fmt::format("cannot continue '{}': its header is not this case's header\n"
                    "  found:    {}\n  expected: {}",
                    path_.string(), s.substr(0, eol), header()));
  AtomicFile f(path_, std::ios::binary);
  f.stream() << header() << '\n';
  // Complete lines only (ending in '\n'); the first field is the time.
  for (std::size_t begin = eol + 1; (eol = s.find('\n', begin)) != std::string::npos;
       begin = eol + 1) {
    const std::string_view line(s.data() + begin, eol - begin);
    double time = 0;
    const auto r = std::from_chars(line.data(), line.data() + line.size(), time);
    if (r.ec != std::errc() || (r.ptr != line.data() + line.size() && *r.ptr != ','))
      throw Error(fmt::format("cannot continue '{}': a row does not start with a time: '{}'",
                              path_.string(), line));
    if (time > t) break;  // rows are in time order: the rest was written after the checkpoint
    f.stream() << line << '\n';
  }
  f.commit();
  open_for_append();
}

void TimeSeriesWriter::open_for_append() {
  out_.close();
  out_.open(path_, std::ios::app | std::ios::binary);
  if (!out_) throw Error(fmt::format("cannot open '{}' for appending", path_.string()));
}

void TimeSeriesWriter::append(const Observables& o,
                              const std::vector<std::unique_ptr<Wall>>& walls) {
  if (!out_.is_open()) throw Error("TimeSeriesWriter::append before start_fresh() or resume()");
  if (walls.size() != wall_names_.size())
    throw Error(fmt::format("time series of '{}' has {} walls, got {}", path_.string(),
                            wall_names_.size(), walls.size()));
  const EnergyLedger& l = o.ledger;
  const double balance = o.kinetic_translational + o.kinetic_rotational + o.potential_gravity +
                         o.elastic + l.damping + l.friction + l.removed - l.wall_work;
  fmt::memory_buffer row;
  fmt::format_to(std::back_inserter(row), "{},{},{},{},{},{},{},{},{},{},{},{},{},{}", o.time,
                 o.step, o.particles, o.contacts, o.wall_contacts, o.kinetic_translational,
                 o.kinetic_rotational, o.potential_gravity, o.elastic, l.damping, l.friction,
                 l.removed, l.wall_work, balance);
  for (const auto& w : walls)
    fmt::format_to(std::back_inserter(row), ",{},{},{},{},{},{}", w->force.x, w->force.y,
                   w->force.z, w->torque.x, w->torque.y, w->torque.z);
  row.push_back('\n');
  out_.write(row.data(), static_cast<std::streamsize>(row.size()));
  out_.flush();
  if (!out_) throw Error(fmt::format("write to '{}' failed", path_.string()));
}

}  // namespace comminute::io
