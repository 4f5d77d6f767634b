#pragma once
// Liberation over time (docs/outputs.md: liberation.csv, liberation_spectrum.csv,
// grade_recovery.csv). At each sample it takes the textured particles (those with fields
// composition.<k>, written by the texture module) either of the whole domain or of the outlet
// stream removed in a time window, and records for every phase its degree of liberation at the
// thresholds 100, 95 and 90 % (liberation.hpp), over all sizes and per size class. The liberation
// spectrum and the ideal grade-recovery curve of the target phase are tables of the latest sample.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/analysis/liberation.hpp"
#include "comminute/breakage/texture/texture_module.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/outlet.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::analysis {

struct LiberationOptions {
  std::size_t target_phase = 1;    // the valuable phase of the spectrum and grade-recovery
  std::vector<double> size_edges;  // m, ascending size-class edges (empty: sqrt(2) series)
  bool from_outlets = false;       // false: the whole domain; true: the outlet stream
  double window = 0;               // s, outlet stream: particles removed in the last window
                                   // (0: since the start of the run)
  double interval = 0;             // s between samples (0: every 2000 steps)
};

class LiberationObserver final : public Module, public SeriesSource {
 public:
  LiberationObserver(const breakage::texture::TextureModule* texture, const OutletModule* outlets,
                     LiberationOptions opt);
  std::string name() const override { return "liberation"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void setup(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  Cadence output_cadence() const override;
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  // The particles the observer looks at now (tests).
  std::vector<ParticleComposition> particles(const Simulation& sim) const;

 private:
  std::vector<double> densities() const;
  const breakage::texture::TextureModule* texture_;
  const OutletModule* outlets_;
  LiberationOptions opt_;
  struct Row {
    double time;
    std::int32_t size_class;  // -1: all sizes
    std::uint32_t phase;
    double mass;  // kg of the phase
    double l100, l95, l90;
  };
  std::vector<Row> rows_;
};

}  // namespace comminute::analysis
