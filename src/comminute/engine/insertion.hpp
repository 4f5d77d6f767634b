#pragma once
// Particle insertion as a module: fill a region at the start (a target count or volume fraction)
// or pour into it at a rate over a time window. Positions are drawn by random sequential
// addition: a candidate that overlaps a particle or a wall is redrawn, so inserted particles
// never overlap.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "comminute/engine/module.hpp"
#include "comminute/geometry/region.hpp"
#include "comminute/particles/size_distribution.hpp"

namespace comminute {

struct InsertionSpec {
  std::string label;  // "insert[0]" — used in messages and checkpoint names
  bool pour = false;  // false: fill once at the start
  Region region;
  std::uint16_t material = 0;
  double density = 0;  // kg/m3
  std::shared_ptr<const SizeDistribution> size;
  std::uint64_t count = 0;     // fill: particles to place; pour: total to pour (0 = unlimited)
  double volume_fraction = 0;  // fill: alternative to count (solid volume / region volume)
  double rate = 0;             // pour: particles per second
  double start = 0;            // pour: s
  double end = std::numeric_limits<double>::infinity();  // pour: s
  double interval = 1e-3;                                // pour: s between insertion batches
  Vec3 velocity;                                         // m/s
  double velocity_spread = 0;  // m/s, uniform random in [-spread, spread] per component
  std::uint64_t stream = 0;    // RNG stream (from the insertion's position in the case file)
};

// How many particles (or grains) a pour at `rate` per second from `start` to `end` has due by
// `time` (whole ones, 1e-9 slack for round-off in the time sum), capped at `count` (0: no cap).
std::uint64_t pour_due(double rate, double start, double end, double time, std::uint64_t count);

class InsertionModule final : public Module {
 public:
  InsertionModule(InsertionSpec spec, std::uint64_t seed);
  std::string name() const override { return spec_.label; }
  ModuleStage stage() const override { return ModuleStage::insertion; }
  void setup(Simulation& sim) override;
  void pre_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;

  std::uint64_t inserted() const { return inserted_; }

 private:
  // Places up to n particles; returns how many were placed.
  std::uint64_t place(Simulation& sim, std::uint64_t n, int attempts_per_particle);

  InsertionSpec spec_;
  Rng rng_;
  std::uint64_t inserted_ = 0;
  double next_time_ = 0;
  bool warned_full_ = false;
};

}  // namespace comminute
