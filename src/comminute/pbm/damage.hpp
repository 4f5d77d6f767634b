#pragma once
// Damage of an unbroken particle stressed below its fracture energy (Tavares & King, Powder
// Technol. 123 (2002) 138; seed 002 eq. 14–15): with r = e/E < 1,
//   D = [2γ/(2γ − 5D + 5) · r]^(2γ/5),
// solved by fixed-point iteration from D = 0 (monotone, converges to the smallest root); the
// particle's fracture energy becomes E(1 − D).
namespace comminute::pbm {

double damage(double gamma, double energy_ratio);

}  // namespace comminute::pbm
