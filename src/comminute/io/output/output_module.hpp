#pragma once
// Writes a run's outputs as the simulation advances, as configured by [output]:
//   <directory>/particles.pvd + particles/*.vtp   particle snapshots (ParaView)
//   <directory>/walls.pvd + walls/*.vtp           wall surfaces with forces
//   <directory>/timeseries.csv                    energies, contacts, wall forces vs time
//   <directory>/<table>.csv                       the tables of every module that is a
//                                                 SeriesSource (e.g. breakage_ledger.csv)
//   <directory>/checkpoint.h5                     the latest checkpoint (restart from it)
// One cadence scheme (OutputSchedule) for every series: the start of a fresh run, every interval
// of the series, and always a last output at the run's end time (finish()).
// Add it to Simulation::modules; call start() once before stepping (after setup() or load()) and
// finish() at the end or on a stop. After Simulation::load() (a restart) the series continue:
// entries after the checkpoint's time are dropped, earlier ones are kept.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/io/output/output_schedule.hpp"
#include "comminute/io/output/timeseries_csv.hpp"
#include "comminute/io/output/vtk_writer.hpp"

namespace comminute::io {

class OutputModule : public Module {
 public:
  // end_time (s): the run's end, for the default cadences (100 snapshots, 1000 rows per run).
  OutputModule(OutputOptions options, double end_time);

  std::string name() const override { return "output"; }
  ModuleStage stage() const override { return ModuleStage::output; }
  void end_of_step(Simulation& sim) override;  // writes what is due at this step
  void save(Archive& a) const override;
  void load(const Archive& a) override;

  // Opens the series (fresh, or continued after load()) and finds the modules that offer tables;
  // a fresh run also writes the initial state (snapshot, row and a sample of every table at the
  // start time); a continued run rewrites the tables as of the checkpoint.
  void start(Simulation& sim);
  // Writes the last snapshot, row and sample of every table (those not written at this step
  // already: the final row at the run's end time) and a checkpoint.
  void finish(Simulation& sim);
  // Writes <directory>/checkpoint.h5 now (atomically; the previous one stays until replaced).
  void write_checkpoint(Simulation& sim);

  const OutputOptions& options() const { return options_; }
  std::filesystem::path checkpoint_path() const { return options_.directory / "checkpoint.h5"; }
  std::filesystem::path timeseries_path() const { return options_.directory / "timeseries.csv"; }

 private:
  // A module's tables: sampled and rewritten on their own schedule.
  struct Source {
    std::string name;  // the module's name (checkpoint entry output/series/<name>)
    SeriesSource* source;
    OutputSchedule schedule;
  };

  void check_fields(const ParticleStore& p) const;
  void write_snapshot(Simulation& sim);
  void write_row(Simulation& sim);
  void sample(Source& s, const Simulation& sim);  // a row now, tables rewritten
  void write_tables(const Source& s, const Simulation& sim) const;
  double wall_extent(const Simulation& sim) const;

  OutputOptions options_;
  OutputSchedule particles_, timeseries_, checkpoint_;
  Cadence timeseries_cadence_;   // also the default of the sources
  std::vector<Source> sources_;  // found at start()
  std::map<std::string, std::vector<std::uint64_t>> loaded_sources_;  // by load(), for start()
  double extent_ = 0;                  // m, fixed at the first wall snapshot
  std::optional<double> resume_time_;  // set by load()
  bool started_ = false;
  std::unique_ptr<VtkWriter> vtk_;
  std::unique_ptr<TimeSeriesWriter> csv_;
};

}  // namespace comminute::io
