#include "comminute/fracture/breaking_median.hpp"

namespace comminute::fracture {

// Tavares & de Carvalho, Minerals Eng. 22 (2009) 650: median of P truncated at E (docs/models.md
// eq. P1b), P(E50b) = P(E)/2.
double breaking_median(const FractureEnergyDistribution& dist, double energy) {
  if (!(energy > 0)) return dist.e50();
  const double half = 0.5 * dist.cdf(energy);
  if (half < 1e-15) return energy;
  return dist.quantile(half);
}

double t10_median_energy(const FractureEnergyDistribution& dist, double energy, E50bRule rule) {
  return rule == E50bRule::breaking ? breaking_median(dist, energy) : dist.e50();
}

E50bRule read_e50b_rule(const CaseTable& t) {
  return t.choice("e50b", {"breaking", "class"}, "breaking") == "breaking" ? E50bRule::breaking
                                                                           : E50bRule::class_median;
}

}  // namespace comminute::fracture
