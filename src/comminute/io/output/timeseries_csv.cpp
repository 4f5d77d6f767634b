#include "comminute/io/output/timeseries_csv.hpp"

#include <fmt/format.h>

#include <set>

#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {
const std::vector<std::string>& checked(const std::vector<std::string>& wall_names) {
  std::set<std::string> seen;
  for (const auto& n : wall_names) {
    if (n.empty() || n.find_first_of(",\"\r\n") != std::string::npos)
      throw Error(
          fmt::format("wall name '{}' cannot name a CSV column (empty, or holds a comma, "
                      "quote or line break)",
                      n));
    if (!seen.insert(n).second)
      throw Error(fmt::format("two walls are named '{}'; names must differ", n));
  }
  return wall_names;
}
}  // namespace

TimeSeriesWriter::TimeSeriesWriter(std::filesystem::path path, std::vector<std::string> wall_names)
    : wall_names_(std::move(wall_names)), series_(std::move(path), columns(checked(wall_names_))) {}

std::vector<Column> TimeSeriesWriter::columns(const std::vector<std::string>& wall_names) {
  std::vector<Column> c = {{"time", "s"},
                           {"step", "-"},
                           {"time_step", "s"},
                           {"particles", "-"},
                           {"contacts", "-"},
                           {"wall_contacts", "-"},
                           {"kinetic_translational", "J"},
                           {"kinetic_rotational", "J"},
                           {"potential_gravity", "J"},
                           {"elastic", "J"},
                           {"dissipated_damping", "J"},
                           {"dissipated_friction", "J"},
                           {"energy_removed", "J"},
                           {"wall_work", "J"},
                           {"elastic_bonds", "J"},
                           {"dissipated_bonds", "J"},
                           {"energy_balance", "J"}};
  for (const auto& w : wall_names) {
    for (const char* a : {"_Fx", "_Fy", "_Fz"}) c.push_back({w + a, "N"});
    for (const char* a : {"_Tx", "_Ty", "_Tz"}) c.push_back({w + a, "N m"});
    c.push_back({w + "_P", "W"});
  }
  return c;
}

void TimeSeriesWriter::append(const Observables& o,
                              const std::vector<std::unique_ptr<Wall>>& walls) {
  if (walls.size() != wall_names_.size())
    throw Error(fmt::format("time series of '{}' has {} walls, got {}", path().string(),
                            wall_names_.size(), walls.size()));
  const EnergyLedger& l = o.ledger;
  const double balance = o.kinetic_translational + o.kinetic_rotational + o.potential_gravity +
                         o.elastic + l.bond_elastic + l.damping + l.friction + l.removed +
                         l.bond_dissipated - l.wall_work;
  std::vector<Cell> row = {o.time,
                           o.step,
                           o.dt,
                           o.particles,
                           o.contacts,
                           o.wall_contacts,
                           o.kinetic_translational,
                           o.kinetic_rotational,
                           o.potential_gravity,
                           o.elastic,
                           l.damping,
                           l.friction,
                           l.removed,
                           l.wall_work,
                           l.bond_elastic,
                           l.bond_dissipated,
                           balance};
  for (const auto& w : walls) {
    for (double v : {w->force.x, w->force.y, w->force.z, w->torque.x, w->torque.y, w->torque.z})
      row.emplace_back(v);
    // the power the wall delivers to the particles: -(F . v + T . omega), F and T being what the
    // particles exert on it (T about the rotation centre, whose velocity is v)
    const Kinematics& k = w->kinematics;
    row.emplace_back(-(dot(w->force, k.velocity) + dot(w->torque, k.angular_velocity)));
  }
  series_.append(row);
}

}  // namespace comminute::io
