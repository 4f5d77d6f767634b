#pragma once
// Product size distribution over time during a breakage run: every `interval` seconds of
// simulated time, the mass passing each sieve per material (particles at their final size plus
// the fines the breakage module booked as mass) is appended to
// <breakage output directory>/size_distribution.csv (rewritten atomically at each row).
#include <vector>

#include "comminute/analysis/sieve_analysis.hpp"
#include "comminute/breakage/breakage_module.hpp"
#include "comminute/engine/module.hpp"

namespace comminute::analysis {

class SizeDistributionObserver final : public Module {
 public:
  // interval 0: 50 rows per 1000 steps is not known in advance, so every 2000 steps.
  SizeDistributionObserver(const breakage::BreakageModule* breakage, SieveOptions sieves,
                           double interval);
  std::string name() const override { return "size_distribution"; }
  void setup(Simulation& sim) override;
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  const std::vector<double>& sieves() const { return sieves_; }

 private:
  void record(const Simulation& sim);
  void write(const Simulation& sim) const;
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
  double next_ = 0;
};

}  // namespace comminute::analysis
