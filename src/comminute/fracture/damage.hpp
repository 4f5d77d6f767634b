#pragma once
// Tavares-King continuum damage of a particle stressed below its fracture energy (docs/models.md
// eq. D1-D2), r = e E_k / E in [0, 1):
//   one_minus_d (default; Tavares, KONA Powder Part. J. 34 (2017) 106, eq. 20):
//     D = [2 gamma (1 - D) / (2 gamma - 5 D + 5) r]^(2 gamma / 5)                       (eq. D1)
//   no_factor (Tavares & King, Powder Technol. 123 (2002) 138, as printed without (1 - D)):
//     D = [2 gamma / (2 gamma - 5 D + 5) r]^(2 gamma / 5)                               (eq. D1')
//   E <- E (1 - D)                                                                     (eq. D2)
//
// Roots (one set of edge rules, for the DEM criterion and the UFRJ mill alike):
//   * one_minus_d: the right side falls strictly with D from > 0 at D = 0 to 0 at D = 1, so
//     there is exactly one root in (0, 1); it is found by bisection on [0, 1] to 1e-15.
//   * no_factor: D is the smallest root, found by fixed-point iteration from D = 0 (monotone
//     increasing), stopped when a step is below 1e-15 (1 + D); convergence slows as r -> 1
//     (10^6 iterations cover r = 0.999).
//   * gamma > 0 and 0 <= r < 1, else comminute::Error (r >= 1 means the particle breaks: the
//     caller tests breakage before damage); r = 0 gives D = 0.
//
// Case keys (DEM [materials.<m>.breakage], population balance [mill]):
//   damage_gamma (-, default 5, > 0); the old DEM key `gamma` is an error naming it;
//   damage_form ("one_minus_d" default | "no_factor").
#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

enum class DamageForm { one_minus_d, no_factor };

double tavares_king_damage(double gamma, double r, DamageForm form);

// gamma and form of the damage law, as read from a case.
struct DamageLaw {
  double gamma = 5.0;
  DamageForm form = DamageForm::one_minus_d;
  double operator()(double r) const { return tavares_king_damage(gamma, r, form); }
};

// Reads damage_gamma (default 5) and damage_form (default "one_minus_d") from `t`.
DamageLaw read_damage_law(const CaseTable& t);

}  // namespace comminute::fracture
