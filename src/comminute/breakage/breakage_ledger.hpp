#pragma once
// The energy and mass ledger of breakage: energy taken out (parents' contact energy, kinetic
// energy difference of parent and fragments, fines' potential energy), elastic energy created by
// the starting overlaps and the growth of fragments, and the fines booked as mass with their
// momentum. Every joule booked here is booked in sim.ledger.removed as well. Checkpointed as
// breakage/removed, breakage/created, breakage/fines_mass and breakage/fines_momentum.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {
class Simulation;
}

namespace comminute::breakage {

class BreakageLedger {
 public:
  void set_materials(std::size_t n) { fines_mass_.resize(n, 0.0); }
  // Energy taken out of the system (J).
  void remove(Simulation& sim, double joules);
  // Elastic energy created by placement or growth (J): booked as negative removed energy.
  void create(Simulation& sim, double joules);
  // Fines of `material` booked as mass, moving with velocity v.
  void add_fines(std::uint16_t material, double mass, const Vec3& v) {
    fines_mass_[material] += mass;
    fines_momentum_ += mass * v;
  }

  double removed() const { return removed_; }
  double created() const { return created_; }
  const std::vector<double>& fines_mass() const { return fines_mass_; }
  Vec3 fines_momentum() const { return fines_momentum_; }

  void save(Archive& a) const;
  void load(const Archive& a);

 private:
  std::vector<double> fines_mass_;  // kg, per material
  Vec3 fines_momentum_;             // kg m/s
  double removed_ = 0;              // J
  double created_ = 0;              // J
};

}  // namespace comminute::breakage
