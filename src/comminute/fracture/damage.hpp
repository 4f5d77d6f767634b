#pragma once
// Tavares-King continuum damage of a particle stressed below its fracture energy (Tavares & King,
// Powder Technol. 123 (2002) 138; docs/models.md eq. D1-D2):
//   D = [2 gamma / (2 gamma - 5 D + 5) r]^(2 gamma / 5),  r = e E_k / E in [0, 1)      (eq. D1)
//   E <- E (1 - D)                                                                     (eq. D2)
// Tavares's review (KONA Powder Part. J. 34 (2017) 106, eq. 20) prints a variant with a (1 - D)
// factor in the numerator; this code keeps the form above (see docs/models.md eq. D1).
//
// Edge rules (one set, for the DEM criterion and the UFRJ mill alike):
//   * gamma > 0 and 0 <= r < 1, else comminute::Error (r >= 1 means the particle breaks: the
//     caller tests breakage before damage);
//   * r = 0 gives D = 0;
//   * D is the smallest root, found by fixed-point iteration from D = 0 (monotone increasing),
//     stopped when a step is below 1e-15 (1 + D); convergence slows as r -> 1 (10^6 iterations
//     cover r = 0.999).
//
// Case key: damage_gamma (-, default 5, > 0); the old DEM key `gamma` is an error naming it.
#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

double tavares_king_damage(double gamma, double r);

// Reads damage_gamma from `t` (default 5).
double read_damage_gamma(const CaseTable& t);

}  // namespace comminute::fracture
