#pragma once
// Energies summed over the contacts one thread evaluates in a force loop (J).
#include "comminute/contact/contact_law.hpp"

namespace comminute {

// Running energy ledger (J), for the time-series output and conservation checks.
struct EnergyLedger {
  double damping = 0;          // dissipated by normal/tangential dashpots
  double friction = 0;         // dissipated by sliding and rolling friction
  double removed = 0;          // taken out by modules (breakage, particle removal), see their logs
  double wall_work = 0;        // work done on the particles by moving walls
  double bond_dissipated = 0;  // dissipated by bond damage and released when bonds fail
  double bond_elastic = 0;     // strain energy held in the bonds now (set by the bonds module)
};

struct EnergyTally {
  double damping = 0, friction = 0, elastic = 0, wall_work = 0;
  // One contact's dissipation by dashpots and by friction in this step and its stored energy (J).
  void add(double damping_work, double friction_work, double stored) {
    damping += damping_work;
    friction += friction_work;
    elastic += stored;
  }
  void add(const ContactForces& out) {
    add(out.damping_dissipation, out.friction_dissipation, out.stored_energy);
  }
  // Books the dissipation into the ledger and adds the elastic energy held now to `held`.
  void book(EnergyLedger& ledger, double& held) const {
    ledger.damping += damping;
    ledger.friction += friction;
    ledger.wall_work += wall_work;
    held += elastic;
  }
};

}  // namespace comminute
