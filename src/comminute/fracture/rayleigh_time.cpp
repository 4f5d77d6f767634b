#include "comminute/fracture/rayleigh_time.hpp"

#include <cmath>

#include "comminute/core/units.hpp"

namespace comminute::fracture {

// docs/models.md eq. R1.
double rayleigh_time(double d, double density, double shear_modulus, double poisson_ratio) {
  return units::pi * 0.5 * d * std::sqrt(density / shear_modulus) /
         (0.1631 * poisson_ratio + 0.8766);
}

}  // namespace comminute::fracture
