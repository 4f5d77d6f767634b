#include "comminute/fracture/energy_share.hpp"

namespace comminute::fracture {

// docs/models.md eq. F4.
double plane_strain_modulus(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);
}

// docs/models.md eq. F5.
double energy_share(double k_p, double k_o) {
  return 1.0 / (1.0 + k_p / k_o);
}

}  // namespace comminute::fracture
