#pragma once
// Product size distribution over time during a breakage run: at each sample (every `interval`
// seconds of simulated time, as the output module schedules it), the mass passing each sieve per
// material (particles at their final size plus the fines the breakage module booked as mass).
// Offered as the table size_distribution (size_distribution.csv; docs/outputs.md).
#include <vector>

#include "comminute/analysis/sieve_analysis.hpp"
#include "comminute/breakage/breakage_module.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::analysis {

class SizeDistributionObserver final : public Module, public SeriesSource {
 public:
  // interval 0: every 2000 steps.
  SizeDistributionObserver(const breakage::BreakageModule* breakage, SieveOptions sieves,
                           double interval);
  std::string name() const override { return "size_distribution"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void setup(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  const std::vector<double>& sieves() const { return sieves_; }

  Cadence output_cadence() const override;
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

 private:
  const breakage::BreakageModule* breakage_;
  SieveOptions options_;
  double interval_;
  std::vector<double> sieves_;
  struct Row {
    double time;
    std::uint32_t material;
    std::uint32_t sieve;
    double passing;  // kg
    double total;    // kg of that material
  };
  std::vector<Row> rows_;
};

}  // namespace comminute::analysis
