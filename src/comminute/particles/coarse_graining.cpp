#include "comminute/particles/coarse_graining.hpp"

#include <cmath>

namespace comminute {

PairInput CoarseGraining::scaled(const PairInput& primary) const {
  PairInput p = primary;
  // Γ → k Γ: Feng & Owen, Comp. Part. Mech. 1 (2014) 159, exact scaling (energy k³ / area k²)
  p.surface_energy *= scale;
  return p;
}

double CoarseGraining::frequency_factor() const {
  return std::pow(scale, frequency_exponent);
}

}  // namespace comminute
