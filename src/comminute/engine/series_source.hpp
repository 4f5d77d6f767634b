#pragma once
// What a module offers to the outputs: tables of rows (csv_table.hpp), never files. The output
// module (io/output) owns the files and the one cadence: it calls sample() at the start of a
// fresh run, every output_cadence() and always at the run's end time, and after each sample
// rewrites every table of tables() as <output directory>/<table name>.csv (atomically).
// A module that is a source returns itself from Module::series_source().
#include <vector>

#include "comminute/core/cadence.hpp"
#include "comminute/core/csv_table.hpp"
#include "comminute/engine/dataset.hpp"

namespace comminute {

class Simulation;

class SeriesSource {
 public:
  virtual ~SeriesSource() = default;
  // How often the module wants a sample (unset: the output module's time-series cadence).
  virtual Cadence output_cadence() const { return {}; }
  // Records the rows that describe the state now (part of the module's checkpointed state).
  virtual void sample(const Simulation& sim) = 0;
  // The module's tables as of now, every row since the start of the run.
  virtual std::vector<Table> tables(const Simulation& sim) const = 0;
  // Spatial datasets (grids, force chains) written with the tables (VTK files), or none.
  virtual std::vector<Dataset> datasets(const Simulation&) const { return {}; }
};

}  // namespace comminute
