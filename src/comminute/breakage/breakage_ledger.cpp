#include "comminute/breakage/breakage_ledger.hpp"

#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

void BreakageLedger::remove(Simulation& sim, double joules) {
  removed_ += joules;
  sim.ledger.removed += joules;
}

void BreakageLedger::create(Simulation& sim, double joules) {
  created_ += joules;
  removed_ -= joules;
  sim.ledger.removed -= joules;
}

void BreakageLedger::save(Archive& a) const {
  a.put("breakage/fines_mass", fines_mass_);
  a.put_value("breakage/fines_momentum", fines_momentum_);
  a.put_value("breakage/removed", removed_);
  a.put_value("breakage/created", created_);
}

void BreakageLedger::load(const Archive& a) {
  fines_mass_ = a.get<double>("breakage/fines_mass");
  fines_momentum_ = a.get_value<Vec3>("breakage/fines_momentum");
  removed_ = a.get_value<double>("breakage/removed");
  created_ = a.get_value<double>("breakage/created");
}

}  // namespace comminute::breakage
