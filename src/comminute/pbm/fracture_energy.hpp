#pragma once
// Distribution of particle fracture energies (mass-specific, J/kg) of one size class: the upper-
// truncated lognormal of the UFRJ model (Tavares & King; MODELS.md "Fracture energy
// distribution"):  E* = E·E_max/(E_max − E),  F(E) = ½[1 + erf((ln E* − ln E50)/(√2 σ))],
// with the size effect E50(d) = E∞ [1 + (d0/d)^φ] and E_max = ratio_max · E50(d).
namespace comminute::pbm {

struct FractureEnergyModel {
  double e50_inf = 100;    // E∞, J/kg
  double d0 = 1e-3;        // m
  double phi = 1.0;        // φ
  double sigma = 0.8;      // σ of ln E*
  double max_ratio = 1e3;  // E_max/E50 (→ ∞: plain lognormal)

  double e50(double d) const;
  // F(E) for particles of size d: the fraction with fracture energy below E.
  double cdf(double energy, double d) const;
};

}  // namespace comminute::pbm
