#pragma once
// Tavares-King continuum damage (Tavares & King 2002; seed 002 eq. 14-15, MODELS.md "Damage").

namespace comminute::breakage {

// Damage D caused by a non-breaking event with ratio r = e E_k / E in [0, 1) for damage
// exponent gamma > 0: the smallest root of D = [2 gamma/(2 gamma - 5 D + 5) r]^(2 gamma/5), found
// by fixed-point iteration from D = 0 (monotone increasing, so it converges to that root).
double tavares_king_damage(double gamma, double r);

}  // namespace comminute::breakage
