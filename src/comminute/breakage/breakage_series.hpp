#pragma once
// The outputs of the breakage module, as tables for the output module (SeriesSource):
//   breakage_events.csv   one row per logged stressing event (the module's event log)
//   breakage_fragments.csv one row per fragment of every breakage
//   breakage_ledger.csv   one row per sample: counts, masses, energies, momenta
//   breakage_model.csv    model curves per material: breakage probability and t10 against the
//                         absorbed specific energy, at the mean diameter of the logged events
// Columns and units: docs/outputs.md. The ledger rows are checkpointed (breakage/ledger).
#include <cstdint>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/vec3.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::breakage {

class BreakageModule;

class BreakageSeries final : public SeriesSource {
 public:
  // interval (s) between samples; 0: every 1000 steps.
  BreakageSeries(const BreakageModule& module, double interval)
      : module_(module), interval_(interval) {}

  Cadence output_cadence() const override;
  void sample(const Simulation& sim) override;  // appends a ledger row
  std::vector<Table> tables(const Simulation& sim) const override;

  void save(Archive& a) const;
  void load(const Archive& a);

 private:
  Table events() const;
  Table fragments() const;
  Table ledger() const;
  Table model_curves(const Simulation& sim) const;

  struct LedgerRow {
    double time, removed_total, breakage_removed, created, particle_mass, fines_mass;
    Vec3 momentum, fines_momentum;
    std::uint64_t events, breakages, pending, particles;
  };
  const BreakageModule& module_;
  double interval_;
  std::vector<LedgerRow> ledger_;
};

}  // namespace comminute::breakage
