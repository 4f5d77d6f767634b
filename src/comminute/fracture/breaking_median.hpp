#pragma once
// E50b of the t10 relation (docs/models.md eq. P1b): the median fracture energy of the particles
// that break at stressing energy E (Tavares & de Carvalho, Minerals Eng. 22 (2009) 650), i.e. the
// median of the fracture-energy distribution P (eq. F1) truncated at E:
//   P(E50b) = P(E) / 2                                                             (eq. P1b)
// Once E reaches the toughest particle's energy (P(E) = 1), E50b is the median of P (E50 for the
// plain lognormal; E50 Emax/(Emax + E50) for the unstarred truncated form). Edge rules: E <= 0
// gives the distribution's E50 parameter (t10 is 0 there anyway); where P(E)/2 is below 1e-15
// (far in the lower tail, beyond the inverse's reach) E50b = E, the limit of the truncated median.
//
// Case key (DEM [materials.<m>.breakage.progeny], population balance [mill.progeny], read with the
// t10 keys): e50b = "breaking" (default, eq. P1b) | "class" (the class median E50(d) of eq. F3).
#include "comminute/core/case_table.hpp"
#include "comminute/fracture/fracture_energy_distribution.hpp"

namespace comminute::fracture {

enum class E50bRule { breaking, class_median };

// Eq. P1b for the distribution `dist` at stressing energy `energy` (J/kg).
double breaking_median(const FractureEnergyDistribution& dist, double energy);

// The E50 the t10 relation divides by under `rule`: eq. P1b, or the E50 parameter of `dist`.
double t10_median_energy(const FractureEnergyDistribution& dist, double energy, E50bRule rule);

// Reads e50b (default "breaking").
E50bRule read_e50b_rule(const CaseTable& t);

}  // namespace comminute::fracture
