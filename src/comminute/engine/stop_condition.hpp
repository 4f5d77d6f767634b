#pragma once
// Stop conditions ([[stop]]): end a run before its end time when a wall's force or stress reaches
// a value — a compression test to a target stress, a safety limit on a roll force. After every
// step (observation stage) each condition compares the magnitude of the force the particles
// exert on its wall, |F| (N), or |F| / area (Pa) — or, when the condition has a direction n (unit,
// from the wall into the particles), the compressive force along it, −F·n, the quantity a
// controlled wall's servo holds (wall_control.hpp) — with its value: `above` is reached when the
// quantity is ≥ the value, `below` when ≤; conditions are checked from time `after` on. The first
// condition reached is recorded (time, step, value) and the run loop (run/run_loop.hpp) then
// finishes the outputs and ends the run: `comminute run` exits with status 0, as at the end time,
// and says which condition ended it. Table (docs/outputs.md): stop.csv (one row once reached).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute {

struct StopConditionSpec {
  std::string label;     // "stop[0]", in messages
  std::size_t wall = 0;  // index in Simulation::walls
  Vec3 direction;        // unit, into the particles: the quantity is −F·n; zero: |F|
  double area = 0;       // m², > 0: the quantity is a stress (force / area, Pa), else a force (N)
  double value = 0;      // N or Pa
  bool above = true;     // reached when quantity ≥ value (else ≤ value)
  double after = 0;      // s, checked from this time on
};

struct StopReached {
  std::uint32_t condition = 0;
  std::uint32_t pad = 0;
  std::uint64_t step = 0;
  double time = 0;      // s
  double quantity = 0;  // N or Pa, the value that reached the condition
};

class StopConditionModule final : public Module, public SeriesSource {
 public:
  explicit StopConditionModule(std::vector<StopConditionSpec> conditions);
  std::string name() const override { return "stop"; }
  ModuleStage stage() const override { return ModuleStage::observation; }
  void end_of_step(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation&) override {}
  std::vector<Table> tables(const Simulation& sim) const override;

  const std::vector<StopConditionSpec>& conditions() const { return conditions_; }
  // The condition that ended the run, once one was reached.
  const std::optional<StopReached>& reached() const { return reached_; }
  // The quantity condition k measures now (N or Pa).
  double quantity(const Simulation& sim, std::size_t k) const;
  // A line for the log: which condition, when, at what value.
  std::string describe(const Simulation& sim) const;

 private:
  std::vector<StopConditionSpec> conditions_;
  std::optional<StopReached> reached_;
};

// The stop-condition module among the simulation's modules, or null.
const StopConditionModule* find_stop_conditions(const Simulation& sim);

}  // namespace comminute
