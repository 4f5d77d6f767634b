#pragma once
// Tavares fracture-energy model: the upper-truncated lognormal distribution of specific fracture
// energies, its size effect and the stiffness partition of contact work between two bodies.
// Equations: MODELS.md "Fracture energy distribution" (Tavares & King 1998; seed 002 eq. 10-13).

namespace comminute::breakage {

// P(E) = 1/2 [1 + erf((ln E* - ln E50) / (sqrt2 sigma))], E* = E Emax / (Emax - E)  (seed 002
// eq. 10-11). This is the seed's ("unstarred") form: its median is E50 Emax/(Emax + E50), not E50.
class FractureEnergyDistribution {
 public:
  // e50: J/kg; sigma: standard deviation of ln E*; emax_ratio = Emax/E50 (> 1; infinity gives the
  // plain lognormal).
  FractureEnergyDistribution(double e50, double sigma, double emax_ratio);
  double cdf(double e) const;                      // probability that the fracture energy is <= e
  double quantile(double u) const;                 // inverse of cdf, u in (0, 1)
  double median() const { return quantile(0.5); }  // = E50 Emax/(Emax + E50)
  double e50() const { return e50_; }
  double emax() const { return emax_; }  // J/kg (infinity when untruncated)

 private:
  double e50_, sigma_, emax_;
};

// Size effect of the median (seed 002 eq. 12): E50(d) = E_inf * partition * [1 + (d0/d)^phi], with
// partition = 1/(1 + k_p/k_s) when E_inf was measured as applied energy against a device of
// stiffness k_s (so that E50 is an absorbed energy), 1 when E_inf is already absorbed energy.
struct SizeEffect {
  double e_inf = 0;      // J/kg
  double d0 = 0;         // m
  double phi = 1;        // -
  double partition = 1;  // -
  double e50(double d) const;
};

// Plane-strain modulus k = E/(1 - nu^2) of a body (Pa), seed 002 eq. 13.
double plane_strain_modulus(double youngs_modulus, double poisson_ratio);
// Share of a contact's work absorbed by body p touching body o: e = 1/(1 + k_p/k_o) (eq. 13).
double energy_share(double k_p, double k_o);

}  // namespace comminute::breakage
