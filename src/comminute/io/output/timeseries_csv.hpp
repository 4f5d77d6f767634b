#pragma once
// The time-series CSV of a run (a SeriesWriter: one header line naming every column with its
// unit, then one row per output time, appended and flushed row by row so that a killed run keeps
// every complete row):
//
//   time [s],step [-],particles [-],contacts [-],wall_contacts [-],kinetic_translational [J],
//   kinetic_rotational [J],potential_gravity [J],elastic [J],dissipated_damping [J],
//   dissipated_friction [J],energy_removed [J],wall_work [J],energy_balance [J],
//   then for each wall <name>_Fx [N],<name>_Fy [N],<name>_Fz [N],<name>_Tx [N m],... _Tz [N m]
//
// energy_balance = kinetic + potential + elastic + dissipated + removed - wall_work: constant in
// time when every energy flow is accounted for (a check, not a physical quantity).
// Numbers are written in the shortest form that reads back to the same double.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "comminute/core/series_writer.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

class TimeSeriesWriter {
 public:
  // Throws Error if a wall name is empty, repeated or holds a comma, quote or line break.
  TimeSeriesWriter(std::filesystem::path path, std::vector<std::string> wall_names);

  static std::vector<Column> columns(const std::vector<std::string>& wall_names);

  // Fresh run: replaces any existing file by the header alone.
  void start_fresh() { series_.start_fresh(); }
  // Restart from a checkpoint at time t: keeps the header and the complete rows with
  // time <= t, drops the rest (rows written after the checkpoint, a half-written last line).
  // Throws Error if the existing header is not this case's header. No file: starts fresh.
  void resume(double t) { series_.resume(t); }
  // Appends one row (walls in the order given to the constructor) and flushes it.
  void append(const Observables& o, const std::vector<std::unique_ptr<Wall>>& walls);

  const std::filesystem::path& path() const { return series_.path(); }
  const std::string& header() const { return series_.header(); }

 private:
  std::vector<std::string> wall_names_;
  SeriesWriter series_;
};

}  // namespace comminute::io
