#pragma once
// The fracture energies of particles of every size: the size effect of the median (SizeEffect)
// and the upper-truncated lognormal around it (FractureEnergyDistribution). Used by the DEM
// criterion "tavares", the population-balance rate "datta_rajamani_variant" and the UFRJ mill.
//
// Case keys (one set for DEM and population balance; docs/models.md "Case keys"):
//   e_inf        J/kg  required  E_inf of E50(d)
//   d0           m     0         size-effect length (0: no size effect)
//   phi          -     1         size-effect exponent, >= 0
//   sigma        -     required  standard deviation of ln E*, > 0
//   emax_ratio   -     inf       Emax/E50 > 1 (inf: plain lognormal)
// Renamed keys are input errors naming the new key: e50_inf -> e_inf, max_ratio -> emax_ratio.
#include <limits>

#include "comminute/core/case_table.hpp"
#include "comminute/fracture/fracture_energy_distribution.hpp"
#include "comminute/fracture/size_effect.hpp"

namespace comminute::fracture {

struct FractureEnergyModel {
  SizeEffect size_effect;                                       // E50(d)
  double sigma = 0.8;                                           // standard deviation of ln E*
  double emax_ratio = std::numeric_limits<double>::infinity();  // Emax/E50 (inf: untruncated)

  double e50(double d) const { return size_effect.e50(d); }
  FractureEnergyDistribution distribution(double d) const;
  // P(E) for particles of size d (m): the fraction with fracture energy at most `energy` (J/kg).
  double cdf(double energy, double d) const { return distribution(d).cdf(energy); }
};

// Reads the keys above from `t` (partition stays 1: the caller applies it when E_inf is an
// applied energy). Out-of-range values are InputErrors naming file, line and key.
FractureEnergyModel read_fracture_energy_model(const CaseTable& t);

}  // namespace comminute::fracture
