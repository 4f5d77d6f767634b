#pragma once
// Pouring bonded grains during the run ([[insert]] type = "clusters", mode = "pour"): every
// `interval` from `start` to `end`, the grains due by then at `rate` (grains per second) are
// placed in the region by random sequential addition of whole grains (bonds/grain_placement.hpp:
// a uniform centre, a uniformly random orientation, no sub-sphere outside the region, on an
// earlier particle or on a wall); each grain's sub-spheres get the grain's velocity, and the
// bonds module bonds the template's pairs at once (the same law and gap rule as a fill). The pour
// stops when `count` grains or `mass` kg are in (whichever the case gives). Grain k takes
// template k mod (number of templates). Per-particle fields: `grain` (continuing the ids of
// earlier grains), `layer` (1 + the time window of the pour the grain came in; `layers` equal
// windows of [start, end]) and `batch` (the insertion round, 1, 2, …, counting rounds that
// placed at least one grain). Table `poured_grains` (docs/outputs.md): one row per grain.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "comminute/bonds/cluster_packing.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/geometry/region.hpp"

namespace comminute::bonds {

class BondsModule;

struct GrainPourSpec {
  std::string label;  // "insert[0]": messages and checkpoint names
  Region region;
  std::vector<GrainTemplate> templates;  // bonds filled in (pairs within the gap tolerance)
  std::uint16_t material = 0;
  double density = 0;  // kg/m³, of the material (the grain's, not the sub-spheres')
  double rate = 0;     // grains per second
  double start = 0;    // s
  double end = std::numeric_limits<double>::infinity();  // s
  double interval = 1e-3;                                // s between insertion rounds
  std::uint64_t count = 0;                               // grains to pour (0: no count target)
  double mass = 0;                                       // kg to pour (0: no mass target)
  int layers = 1;                                        // equal time windows of [start, end]
  int attempts = 50;                                     // placement attempts per grain and round
  Vec3 velocity;                                         // m/s
  double velocity_spread = 0;  // m/s, uniform in [-spread, spread] per component, per grain
  std::uint64_t stream = 0;    // RNG stream (the insertion's position in the case file)
};

// One poured grain (plain data: checkpointed as is).
struct PouredGrain {
  double time = 0;  // s
  std::uint64_t grain = 0, batch = 0, layer = 0, templ = 0;
  Vec3 centre;                     // m, where it was placed
  std::array<double, 4> rotation;  // unit quaternion (w, x, y, z), body -> world
};

class GrainPourModule final : public Module, public SeriesSource {
 public:
  GrainPourModule(GrainPourSpec spec, std::uint64_t seed);
  std::string name() const override { return spec_.label; }
  ModuleStage stage() const override { return ModuleStage::insertion; }
  void setup(Simulation& sim) override;
  void restored(Simulation& sim) override;
  void pre_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation&) override {}  // rows are recorded as the grains come in
  std::vector<Table> tables(const Simulation& sim) const override;

  // kg, each sub-sphere's and the grain's mass of template k (the sum of its sub-spheres', in
  // their order)
  double sphere_mass(std::size_t k) const { return sphere_mass_[k]; }
  double grain_mass(std::size_t k) const { return grain_mass_[k]; }
  const GrainTemplate& grain_template(std::size_t k) const { return spec_.templates[k]; }
  std::uint64_t poured() const { return grains_.size(); }
  double poured_mass() const { return poured_mass_; }  // kg
  const std::vector<PouredGrain>& grains() const { return grains_; }
  bool done() const;

 private:
  void find_bonds(Simulation& sim);
  // Places up to n grains; returns how many were placed.
  std::uint64_t place(Simulation& sim, std::uint64_t n);

  GrainPourSpec spec_;
  Rng rng_;
  std::vector<double> sphere_density_, sphere_mass_, grain_mass_;  // per template
  BondsModule* bonds_ = nullptr;
  std::size_t grain_field_ = 0, layer_field_ = 0, batch_field_ = 0;
  std::uint64_t first_grain_ = 0;  // grain id of the first poured grain
  std::uint64_t batches_ = 0;      // rounds that placed a grain
  double next_time_ = 0;           // s
  double poured_mass_ = 0;         // kg
  bool warned_full_ = false;
  std::vector<PouredGrain> grains_;
};

}  // namespace comminute::bonds
