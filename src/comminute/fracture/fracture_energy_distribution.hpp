#pragma once
// Upper-truncated lognormal distribution of the mass-specific fracture energies of the particles
// of one size (Tavares & King, Int. J. Miner. Process. 54 (1998) 1; docs/models.md eq. F1-F2).
//
//   E* = E Emax / (Emax - E),   P(E) = 1/2 erfc(-(ln E* - ln E50) / (sqrt2 sigma))   (eq. F1)
//   sampling: ln E* = ln E50 + sqrt2 sigma erf^-1(2u - 1), E = E* Emax / (Emax + E*)   (eq. F2)
//
// Edge rules (one set, for the DEM criteria and the population balance alike):
//   * E50 > 0, sigma > 0 and Emax/E50 > 1 or the constructor throws comminute::Error;
//     Emax/E50 = infinity gives the plain (untruncated) lognormal;
//   * P(E) = 0 for E <= 0 and 1 for E >= Emax;
//   * this is the "unstarred" form: its median is E50 Emax/(Emax + E50), not E50 (median()).
namespace comminute::fracture {

class FractureEnergyDistribution {
 public:
  // e50: J/kg; sigma: standard deviation of ln E*; emax_ratio = Emax/E50.
  FractureEnergyDistribution(double e50, double sigma, double emax_ratio);
  double cdf(double e) const;                      // probability that the fracture energy is <= e
  double quantile(double u) const;                 // inverse of cdf, u in (0, 1)
  double median() const { return quantile(0.5); }  // = E50 Emax/(Emax + E50)
  double e50() const { return e50_; }
  double emax() const { return emax_; }  // J/kg (infinity when untruncated)

 private:
  double e50_, sigma_, emax_;
};

}  // namespace comminute::fracture
